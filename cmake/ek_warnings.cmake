# Warnings as an interface target, linked PRIVATE by every project target.
add_library(ek_warnings INTERFACE)
target_compile_options(ek_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast
  -Wcast-align -Wunused -Woverloaded-virtual
  $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>)
option(EK_WERROR "Treat warnings as errors" OFF)
if(EK_WERROR)
  target_compile_options(ek_warnings INTERFACE -Werror)
endif()
