# ek_add_module(NAME SOURCES ... DEPS ... [EXTERNAL ...])
#
# Defines the static library ek_<NAME> from src/<NAME>/. Public headers live in
# src/<NAME>/include/ek/<NAME>/ and are visible only to targets that link the
# module (directly or through a dependent module), so the include graph equals
# the link graph. DEPS must name modules defined earlier: the module graph is
# acyclic by construction, in the order of src/CMakeLists.txt.
set_property(GLOBAL PROPERTY EK_MODULES "")

# Installs a library target into the export set of find_package(ElasticKnots)
# (cmake/ElasticKnotsConfig.cmake.in) as ek::EXPORT_NAME.
function(ek_install_library TARGET EXPORT_NAME)
  set_target_properties(${TARGET} PROPERTIES EXPORT_NAME ${EXPORT_NAME})
  install(TARGETS ${TARGET} EXPORT ElasticKnotsTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT library)
endfunction()

function(ek_add_module NAME)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;EXTERNAL" ${ARGN})
  get_property(known GLOBAL PROPERTY EK_MODULES)
  foreach(dep IN LISTS ARG_DEPS)
    if(NOT dep IN_LIST known)
      message(FATAL_ERROR "module '${NAME}' depends on '${dep}', which is not defined before it: "
                          "the dependency direction is fixed by the order in src/CMakeLists.txt")
    endif()
  endforeach()
  set(target ek_${NAME})
  set(include_dirs $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  if(ARG_SOURCES)
    add_library(${target} STATIC ${ARG_SOURCES})
    target_include_directories(${target} PUBLIC ${include_dirs})
    target_link_libraries(${target} PRIVATE $<BUILD_INTERFACE:ek_warnings>)
    ek_use_pch(${target})
    set(scope PUBLIC)
  else()
    add_library(${target} INTERFACE)
    target_include_directories(${target} INTERFACE ${include_dirs})
    set(scope INTERFACE)
  endif()
  ek_install_library(${target} ${NAME})
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT library)
  foreach(dep IN LISTS ARG_DEPS)
    target_link_libraries(${target} ${scope} ek_${dep})
  endforeach()
  if(ARG_EXTERNAL)
    target_link_libraries(${target} ${scope} ${ARG_EXTERNAL})
  endif()
  add_library(ek::${NAME} ALIAS ${target})
  set_property(GLOBAL APPEND PROPERTY EK_MODULES ${NAME})
  set_property(GLOBAL PROPERTY EK_MODULE_DEPS_${NAME} "${ARG_DEPS}")
endfunction()

# ek_add_gtest(NAME SOURCES ... LIBS ... [LABEL label] [TIMEOUT seconds] [NO_DISCOVERY])
# One GoogleTest executable; each TEST becomes a CTest entry with the label:
# unit (default), parsers (also built with sanitizers), stress (short, in
# `make test`), stress-long (`make stress` only). Tests are gathered in one
# program per module and label, compiled in unity batches of up to 16
# sources: fewer programs and batches compile and link faster, and CTest
# still runs each test on its own. NO_DISCOVERY leaves the discovery to
# the caller (the paper checks: one discovery per check, each with its fixture).
# (gtest_discover_tests cannot pass a list of labels, hence one label.)
function(ek_add_gtest NAME)
  cmake_parse_arguments(ARG "NO_DISCOVERY" "TIMEOUT;LABEL" "SOURCES;LIBS" ${ARGN})
  if(EK_PARSERS_ONLY AND NOT ARG_LABEL STREQUAL "parsers")
    return()  # the sanitizer build runs the parsers' tests only
  endif()
  add_executable(${NAME} ${ARG_SOURCES})
  set_target_properties(${NAME} PROPERTIES UNITY_BUILD_BATCH_SIZE 16)
  target_link_libraries(${NAME} PRIVATE ${ARG_LIBS} ek_testing GTest::gtest GTest::gtest_main ek_warnings)
  if(TARGET ek_test_pch)  # tests/CMakeLists.txt: -O1 and the shared precompiled header
    target_compile_options(${NAME} PRIVATE -O1)
    target_precompile_headers(${NAME} REUSE_FROM ek_test_pch)
  endif()
  if(ARG_NO_DISCOVERY)
    return()
  endif()
  if(NOT ARG_LABEL)
    set(ARG_LABEL unit)
  endif()
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 600)
  endif()
  gtest_discover_tests(${NAME} PROPERTIES LABELS ${ARG_LABEL} TIMEOUT ${ARG_TIMEOUT} DISCOVERY_TIMEOUT 60)
endfunction()
