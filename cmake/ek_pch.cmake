# Precompiled headers in Release builds with GCC and in the Clang build of the
# fuzz targets (EK_FUZZ), to shorten the builds that `make test` starts with
# (docs/performance.md, "Build and test time"). The module libraries reuse
# one precompiled header of Eigen, nlohmann-json and the standard headers
# most of their sources include (ek_lib_pch, compiled as a library's sources
# are), the programs on top of them (knots, the experiments) another one
# compiled as a program's sources are (ek_exe_pch, -fPIE). The test programs
# have their own (tests/CMakeLists.txt). A precompiled header replaces the
# parsing of these headers only: what is compiled, and at which optimisation
# level, does not change.
set(EK_PCH_HEADERS <Eigen/Core> <Eigen/Dense> <Eigen/Sparse> <nlohmann/json.hpp> <algorithm> <cmath> <functional>
                   <map> <memory> <string> <vector>)
if((CMAKE_BUILD_TYPE STREQUAL "Release" AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND NOT EK_PARSERS_ONLY) OR EK_FUZZ)
  add_library(ek_lib_pch STATIC ${PROJECT_SOURCE_DIR}/cmake/pch_owner.cpp)
  target_link_libraries(ek_lib_pch PRIVATE Eigen3::Eigen nlohmann_json::nlohmann_json ek_warnings)
  target_precompile_headers(ek_lib_pch PRIVATE ${EK_PCH_HEADERS})
  # no compile definitions here: GCC refuses a header precompiled with a macro the user lacks
  add_executable(ek_exe_pch ${PROJECT_SOURCE_DIR}/cmake/pch_owner_main.cpp)
  target_link_libraries(ek_exe_pch PRIVATE Eigen3::Eigen nlohmann_json::nlohmann_json ek_warnings)
  target_precompile_headers(ek_exe_pch PRIVATE ${EK_PCH_HEADERS})
endif()

# The precompiled header of ek_lib_pch (a library) or ek_exe_pch (a program)
# for TARGET, when this build has them.
function(ek_use_pch TARGET)
  get_target_property(type ${TARGET} TYPE)
  if(type STREQUAL "STATIC_LIBRARY" AND TARGET ek_lib_pch)
    target_precompile_headers(${TARGET} REUSE_FROM ek_lib_pch)
  elseif(type STREQUAL "EXECUTABLE" AND TARGET ek_exe_pch)
    target_precompile_headers(${TARGET} REUSE_FROM ek_exe_pch)
  endif()
endfunction()
