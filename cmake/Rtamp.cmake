# Helpers shared by every layer's CMakeLists.txt.
# GCC 12 reports a false -Wrestrict in std::string concatenation at -O2 (GCC bug 105329): disabled for GCC.
#   rtamp_add_layer(NAME SOURCES ... [DEPS ...] [SYSTEM_DEPS ...])
#     -> static library rtamp_<NAME> (-fPIC), alias rtamp::<NAME>, headers included as
#        "rtamp/<NAME>/x.hpp"; installed and exported as rtamp::<NAME> (cmake/RtampInstall.cmake):
#        the layers in RTAMP_MUJOCO_LAYERS go to the "mujoco" component, the others to the core.
#        Wrap build-only header libraries in $<BUILD_INTERFACE:...> in SYSTEM_DEPS so that
#        users of the installed package need not have them (e.g. nlohmann_json).
#   rtamp_options: the project's warning (and sanitizer) flags, linked PRIVATE by every
#     project target and never passed on to users of the libraries.
#   rtamp_add_test(NAME SOURCES ... DEPS ... [LABELS ...] [TIMEOUT s] [USES_CLI])
#     -> GoogleTest executable registered with ctest (one ctest entry per TEST); none
#        in a sanitizer build (RTAMP_SANITIZE) when LABELS has slow; compiled with
#        RTAMP_SANITIZER_BUILD 1 in a sanitizer build, else 0; USES_CLI: built after the
#        rtamp binary, which it runs (RTAMP_BIN in "rtamp_source_dir.hpp").
#        Test code is compiled at -O1 (the libraries it tests keep the build type's
#        optimisation) with GoogleTest and the common standard headers precompiled once
#        (RTAMP_PCH): half the compile time of a clean build was test code.
#   rtamp_source_dir: tests and benchmarks that read files of the source tree include
#     "rtamp_source_dir.hpp" (RTAMP_SOURCE_DIR, the checkout's path; RTAMP_BIN, the CLI's). A generated header
#     rather than a -D on every target, so that objects that do not use the path compile
#     the same in every checkout (a shared compiler cache serves them all).

# A compiler cache when Debian's ccache is installed (RTAMP_CCACHE, on by default; a launcher
# given on the command line wins): paths are taken relative to the checkout (base_dir) and the
# build directory is not hashed, so a fresh clone in another folder hits what an earlier one
# compiled; the sloppiness lets objects that use precompiled headers be cached, and clang's
# precompiled headers carry no timestamps for the same reason.
option(RTAMP_CCACHE "Compile through ccache when it is installed" ON)
if(RTAMP_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  find_program(RTAMP_CCACHE_PROGRAM ccache)
  if(RTAMP_CCACHE_PROGRAM)
    set(CMAKE_CXX_COMPILER_LAUNCHER ${CMAKE_COMMAND} -E env CCACHE_BASEDIR=${PROJECT_SOURCE_DIR} CCACHE_NOHASHDIR=true
        CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime ${RTAMP_CCACHE_PROGRAM})
  endif()
endif()
if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  add_compile_options("SHELL:-Xclang -fno-pch-timestamp")
endif()

set(RTAMP_WARNINGS -Wall -Wextra -Wpedantic $<$<CXX_COMPILER_ID:GNU>:-Wshadow=local> $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict> -Wnon-virtual-dtor -Wno-missing-field-initializers)
if(RTAMP_WERROR)
  list(APPEND RTAMP_WARNINGS -Werror)
endif()

add_library(rtamp_options INTERFACE)
configure_file(${CMAKE_CURRENT_LIST_DIR}/rtamp_source_dir.hpp.in ${PROJECT_BINARY_DIR}/generated/source_dir/rtamp_source_dir.hpp)
add_library(rtamp_source_dir INTERFACE)
target_include_directories(rtamp_source_dir INTERFACE ${PROJECT_BINARY_DIR}/generated/source_dir)
target_compile_options(rtamp_options INTERFACE ${RTAMP_WARNINGS})
target_include_directories(rtamp_options INTERFACE ${PROJECT_SOURCE_DIR}/src)
if(RTAMP_SANITIZE)
  # -O1: the usual optimisation for sanitizer runs; unoptimised Eigen code is ~200x
  # slower than Release, which would put numeric tests past their time limits.
  # -g1: line tables only, all the reports' stacks need (file:line); tests/serve/
  # server_test.cpp compiled here in 75 s with it, 104 s with full -g (gcc, once each).
  target_compile_options(rtamp_options INTERFACE -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g1 -O1)
  target_link_options(rtamp_options INTERFACE -fsanitize=address,undefined)
endif()
if(RTAMP_FUZZ)
  # libFuzzer's coverage instrumentation on every object; only the fuzz targets link the
  # fuzzer runtime (fuzz/CMakeLists.txt). With RTAMP_SANITIZE (make test-asan, make fuzz:
  # one clang tree) the tests and the CLI link the same objects with ASan + UBSan only.
  target_compile_options(rtamp_options INTERFACE -fsanitize=fuzzer-no-link)
  if(NOT RTAMP_SANITIZE)
    target_compile_options(rtamp_options INTERFACE -fsanitize=address,undefined -g)
    target_link_options(rtamp_options INTERFACE -fsanitize=address,undefined)
  endif()
endif()

include(GNUInstallDirs)
include(rtampDependencies)
# The layers that link MuJoCo (directly or through sim): the "mujoco" component.
set(RTAMP_MUJOCO_LAYERS sim episode batch serve)

function(rtamp_add_layer name)
  cmake_parse_arguments(L "" "" "SOURCES;DEPS;SYSTEM_DEPS" ${ARGN})
  add_library(rtamp_${name} STATIC ${L_SOURCES})
  add_library(rtamp::${name} ALIAS rtamp_${name})
  # Warnings are private; for a static library CMake still passes the link options
  # (the sanitizers) on to in-tree users as $<LINK_ONLY:...>, which is what they need.
  target_link_libraries(rtamp_${name} PUBLIC ${L_DEPS} ${L_SYSTEM_DEPS} PRIVATE $<BUILD_INTERFACE:rtamp_options>)
  target_include_directories(rtamp_${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>
                                                  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(rtamp_${name} PUBLIC cxx_std_20)
  set_target_properties(rtamp_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON EXPORT_NAME ${name})
  if(name IN_LIST RTAMP_MUJOCO_LAYERS)
    set(export rtampMujocoTargets)
    set_property(GLOBAL APPEND PROPERTY RTAMP_MUJOCO_TARGETS rtamp_${name})
  else()
    set(export rtampTargets)
    set_property(GLOBAL APPEND PROPERTY RTAMP_CORE_TARGETS rtamp_${name})
  endif()
  install(TARGETS rtamp_${name} EXPORT ${export} ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev)
endfunction()

option(RTAMP_PCH "Precompile GoogleTest and the standard headers for the tests" ON)
set(RTAMP_TEST_COMPILE_OPTIONS $<$<NOT:$<CONFIG:Debug>>:-Og>)
if(RTAMP_SANITIZE)
  set(RTAMP_TEST_DEFINITIONS RTAMP_SANITIZER_BUILD=1)
else()
  set(RTAMP_TEST_DEFINITIONS RTAMP_SANITIZER_BUILD=0)
endif()

# The precompiled header every test reuses (made once, after find_package(GTest)). Its flags
# are the tests' own: the compilers accept a precompiled header only under the same ones.
function(rtamp_test_pch)
  add_library(rtamp_test_pch OBJECT ${PROJECT_SOURCE_DIR}/cmake/rtamp_test_pch.cpp)
  target_link_libraries(rtamp_test_pch PRIVATE rtamp_options rtamp_source_dir GTest::gtest GTest::gmock)
  target_compile_definitions(rtamp_test_pch PRIVATE ${RTAMP_TEST_DEFINITIONS})
  target_compile_options(rtamp_test_pch PRIVATE ${RTAMP_TEST_COMPILE_OPTIONS})
  target_precompile_headers(rtamp_test_pch PRIVATE
    <gtest/gtest.h> <gmock/gmock.h>
    <algorithm> <array> <chrono> <cmath> <cstdint> <cstdio> <cstdlib> <filesystem> <fstream>
    <functional> <limits> <map> <memory> <optional> <random> <set> <sstream> <string>
    <unordered_map> <vector>)
endfunction()

function(rtamp_add_test name)
  cmake_parse_arguments(T "USES_CLI" "TIMEOUT" "SOURCES;DEPS;LABELS;ENVIRONMENT" ${ARGN})
  # The sanitizer run leaves out the tests labelled slow (make test-asan: ctest -LE slow),
  # so a sanitizer build does not compile them either (callers check if(TARGET name)).
  if(RTAMP_SANITIZE AND "slow" IN_LIST T_LABELS)
    return()
  endif()
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE rtamp_options rtamp_source_dir ${T_DEPS} GTest::gtest GTest::gtest_main GTest::gmock)
  # RTAMP_SANITIZER_BUILD (0 or 1): property tests draw fewer samples under the
  # sanitizers (~10x slower). A definition, not __SANITIZE_ADDRESS__: clang lacks that macro.
  target_compile_definitions(${name} PRIVATE ${RTAMP_TEST_DEFINITIONS})
  target_compile_options(${name} PRIVATE ${RTAMP_TEST_COMPILE_OPTIONS})
  if(RTAMP_PCH)
    target_precompile_headers(${name} REUSE_FROM rtamp_test_pch)
  endif()
  if(T_USES_CLI)
    add_dependencies(${name} rtamp)
  endif()
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 600)
  endif()
  set(props TIMEOUT ${T_TIMEOUT})
  if(T_LABELS)
    list(APPEND props LABELS "${T_LABELS}")
  endif()
  if(T_ENVIRONMENT)
    list(APPEND props ENVIRONMENT "${T_ENVIRONMENT}")
  endif()
  gtest_discover_tests(${name} DISCOVERY_MODE PRE_TEST PROPERTIES ${props})
endfunction()
