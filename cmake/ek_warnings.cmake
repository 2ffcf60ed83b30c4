# Warnings as an interface target, linked PRIVATE by every project target.
add_library(ek_warnings INTERFACE)
target_compile_options(ek_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast
  -Wcast-align -Wunused -Woverloaded-virtual
  $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>)
# In a unity build each source is an included file of its batch, so GCC's
# -Wsubobject-linkage (meant for headers) reports a class with a member of
# the source's own anonymous namespace; built one source at a time, the
# same code compiles without it.
if(EK_UNITY_BUILD)
  target_compile_options(ek_warnings INTERFACE $<$<CXX_COMPILER_ID:GNU>:-Wno-subobject-linkage>)
endif()
option(EK_WERROR "Treat warnings as errors" OFF)
if(EK_WERROR)
  target_compile_options(ek_warnings INTERFACE -Werror)
endif()
