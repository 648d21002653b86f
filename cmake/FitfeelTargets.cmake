# Helpers shared by every folder: one call builds a plugin, a test or a benchmark the same way.

# fitfeel_add_plugin(<name> SOURCES ... [LIBS ...] [OUTPUT_DIR dir] [EXPORT_ALL]) builds a
# loadable module into the build tree's plugin folder. Only the registration hook is exported.
# The same function an out-of-tree plugin calls through the installed package.
include(${CMAKE_CURRENT_LIST_DIR}/fitfeelPlugin.cmake)

function(fitfeel_add_plugin name)
  cmake_parse_arguments(ARG "EXPORT_ALL" "OUTPUT_DIR" "SOURCES;LIBS" ${ARGN})
  if(NOT ARG_OUTPUT_DIR)
    set(ARG_OUTPUT_DIR ${FITFEEL_BUILD_PLUGIN_DIR})
  endif()
  if(ARG_EXPORT_ALL)
    # Test plugins that deliberately export something else than the registration hook.
    add_library(${name} MODULE ${ARG_SOURCES})
    target_link_libraries(${name} PRIVATE fitfeel::fitfeel ${ARG_LIBS})
    set_target_properties(${name} PROPERTIES PREFIX "lib")
  else()
    fitfeel_add_plugin_module(${name} SOURCES ${ARG_SOURCES} LIBS ${ARG_LIBS})
  endif()
  set_target_properties(${name} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${ARG_OUTPUT_DIR})
  if(ARG_OUTPUT_DIR STREQUAL FITFEEL_BUILD_PLUGIN_DIR)
    # Installed in lib/fitfeel/plugins, two folders below the framework library.
    set_target_properties(${name} PROPERTIES INSTALL_RPATH "$ORIGIN/../..")
    install(TARGETS ${name} LIBRARY DESTINATION lib/fitfeel/plugins)
    add_dependencies(fitfeel_plugins ${name})
  endif()
endfunction()

# fitfeel_add_plugin_folder(<surface|device> <name> SOURCES ... [LIBS ...] [OUTPUT_DIR dir]) is the
# whole CMakeLists.txt of a plugin folder, which has one shape for every plugin:
#   <name>_<role>.h/.cc  the model, a static library fitfeel_<kind>_<name>_model, namespace
#                        fitfeel::<name>, so tests use its classes directly;
#   register.cc          the plugin fitfeel_<kind>_<name>: the model and its one exported hook,
#                        FITFEEL_REGISTER_SURFACE or FITFEEL_REGISTER_DEVICE;
#   test/                its tests (fitfeel_<kind>_<name>_test; the conformance suite, which counts
#                        allocations, joins fitfeel_allocation_test);
#   bench/               its benchmarks (built only with FITFEEL_BUILD_BENCHMARKS);
#   README.md            what it models, its choices and its tests.
function(fitfeel_add_plugin_folder kind name)
  cmake_parse_arguments(ARG "" "OUTPUT_DIR" "SOURCES;LIBS" ${ARGN})
  set(plugin fitfeel_${kind}_${name})
  add_library(${plugin}_model STATIC ${ARG_SOURCES})
  target_link_libraries(${plugin}_model PUBLIC fitfeel::framework ${ARG_LIBS})
  set(output_dir)
  if(ARG_OUTPUT_DIR)
    set(output_dir OUTPUT_DIR ${ARG_OUTPUT_DIR})
  endif()
  fitfeel_add_plugin(${plugin} SOURCES register.cc LIBS ${plugin}_model ${output_dir})
  if(FITFEEL_BUILD_TESTS AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/test/CMakeLists.txt)
    add_subdirectory(test)
  endif()
  if(FITFEEL_BUILD_BENCHMARKS AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/bench/CMakeLists.txt)
    add_subdirectory(bench)
  endif()
endfunction()

# fitfeel_add_test(<name> SOURCES ... [LIBS ...] [NEEDS target...] [LABELS ...]) builds a
# GoogleTest binary and registers its tests with ctest. Tests run with the build tree's plugins and
# the repository as the working tree. Calls with the same name from several folders add their
# sources to one binary: tests are grouped by module (a binary per plugin, one for the framework's
# core), so the build links and lists a few executables instead of one per folder. Tests that count
# operator new go to fitfeel_add_allocation_test instead. NEEDS names what the tests load or run
# (plugins, the CLI); it may be defined later in the tree.
# fitfeel_off_tick(<target>...): compiles the targets' own sources at FITFEEL_OFF_TICK_OPTIMIZATION
# in Release (see the top-level CMakeLists.txt); what they link keeps its own level.
function(fitfeel_off_tick)
  if(FITFEEL_OFF_TICK_OPTIMIZATION)
    foreach(target IN LISTS ARGN)
      target_compile_options(${target} PRIVATE
                             $<$<CONFIG:Release>:${FITFEEL_OFF_TICK_OPTIMIZATION}>)
    endforeach()
  endif()
endfunction()

# The settings every test target compiles with (the test trees' paths, the tests' level).
function(fitfeel_test_settings name)
  target_link_libraries(${name} PRIVATE fitfeel::framework GTest::gtest GTest::gmock)
  # gtest_discover_tests keeps only the first entry of a list-valued ENVIRONMENT, so the trees
  # come from a generated library; the macros call it (framework/testing/test_paths.h).
  target_compile_definitions(${name} PRIVATE FITFEEL_TEST_SOURCE_DIR=fitfeel_test_source_dir\(\)
                                             FITFEEL_TEST_BUILD_DIR=fitfeel_test_build_dir\(\))
  # Forced into every test file; with the precompiled header it comes from there (a header
  # forced before the precompiled one would keep the compiler from using it).
  if(NOT FITFEEL_TEST_PCH)
    target_compile_options(${name} PRIVATE
                           -include ${PROJECT_SOURCE_DIR}/framework/testing/test_paths.h)
  endif()
  if(FITFEEL_TEST_OPTIMIZATION)
    target_compile_options(${name} PRIVATE $<$<CONFIG:Release>:${FITFEEL_TEST_OPTIMIZATION}>)
  endif()
endfunction()

# One precompiled header for every test target: GoogleTest, GoogleMock, Eigen and the standard
# headers most test files include are parsed once per build instead of once per translation unit
# (each test file otherwise spends seconds on them). Made with the test targets' own settings,
# which REUSE_FROM requires.
function(fitfeel_test_pch)
  if(TARGET fitfeel_test_pch)
    return()
  endif()
  # An executable like the tests (position-independent the same way, which the header must match).
  file(WRITE ${CMAKE_BINARY_DIR}/test_pch.cc
       "// The test targets' precompiled header.\nint main() { return 0; }\n")
  add_executable(fitfeel_test_pch ${CMAKE_BINARY_DIR}/test_pch.cc)
  fitfeel_test_settings(fitfeel_test_pch)
  set_target_properties(fitfeel_test_pch PROPERTIES UNITY_BUILD OFF)
  target_precompile_headers(fitfeel_test_pch PRIVATE
    ${PROJECT_SOURCE_DIR}/framework/testing/test_paths.h
    <algorithm> <cmath> <cstdint> <filesystem> <fstream> <functional> <map> <memory> <optional>
    <sstream> <string> <vector> <Eigen/Core> <Eigen/Geometry> <gmock/gmock.h> <gtest/gtest.h>)
endfunction()

function(fitfeel_add_test name)
  if(NOT FITFEEL_BUILD_TESTS)
    return()
  endif()
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS;NEEDS;LABELS" ${ARGN})
  if(TARGET ${name})
    target_sources(${name} PRIVATE ${ARG_SOURCES})
  else()
    add_executable(${name} ${ARG_SOURCES})
    target_link_libraries(${name} PRIVATE fitfeel_test_main)
    fitfeel_test_settings(${name})
    if(FITFEEL_TEST_PCH)
      fitfeel_test_pch()
      target_precompile_headers(${name} REUSE_FROM fitfeel_test_pch)
    endif()
    set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
    gtest_discover_tests(${name}
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
      PROPERTIES LABELS "${ARG_LABELS}"
      DISCOVERY_TIMEOUT 60)
  endif()
  if(ARG_LIBS)
    target_link_libraries(${name} PRIVATE ${ARG_LIBS})
  endif()
  if(ARG_NEEDS)
    add_dependencies(${name} ${ARG_NEEDS})
  endif()
endfunction()

# fitfeel_add_allocation_test(SOURCES ... [LIBS ...] [NEEDS target...]) adds tests that count heap
# allocations (framework/testing/allocation_counter.h), and every surface plugin's conformance
# suite, to the one binary whose global operator new counts: fitfeel_allocation_test, with
# framework/testing/count_allocations.cc. ctest runs each of its tests in a process of its own, so
# no test counts another's allocations. Names private to a file must be unique in the binary (the
# unity build compiles its files together).
function(fitfeel_add_allocation_test)
  if(NOT FITFEEL_BUILD_TESTS)
    return()
  endif()
  if(NOT TARGET fitfeel_allocation_test)
    fitfeel_add_test(fitfeel_allocation_test
                     SOURCES ${PROJECT_SOURCE_DIR}/framework/testing/count_allocations.cc)
  endif()
  fitfeel_add_test(fitfeel_allocation_test ${ARGN})
endfunction()

# fitfeel_add_benchmark(<name> SOURCES ... [LIBS ...]) builds a Google Benchmark binary into
# build/bench. Benchmarks are never run by ctest: they measure, tests assert.
function(fitfeel_add_benchmark name)
  if(NOT FITFEEL_BUILD_BENCHMARKS)
    return()
  endif()
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE fitfeel::framework benchmark::benchmark
                                        benchmark::benchmark_main ${ARG_LIBS})
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bench)
endfunction()

# Adds every immediate subfolder of the current folder that has a CMakeLists.txt, so that a new
# plugin is one new folder and no edit elsewhere.
function(fitfeel_add_plugin_folders)
  file(GLOB children LIST_DIRECTORIES true RELATIVE ${CMAKE_CURRENT_SOURCE_DIR}
       ${CMAKE_CURRENT_SOURCE_DIR}/*)
  list(SORT children)
  foreach(child IN LISTS children)
    if(IS_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/${child}
       AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${child}/CMakeLists.txt)
      add_subdirectory(${child})
    endif()
  endforeach()
endfunction()

# fitfeel_add_fuzzer(<name> SOURCES ... [LIBS ...] [NEEDS target...] [REPLAY_ALSO path...]) builds
# a libFuzzer target (preset `fuzz`: clang, FITFEEL_BUILD_FUZZERS=ON) into build-fuzz/fuzz/. The
# sources define LLVMFuzzerTestOneInput; the seed corpus is the folder `corpus/<name>` beside them,
# which `make fuzz` copies before a run so that the repository's corpus only grows by hand: every
# input that once failed is added there. In an ordinary test build the same sources join one plain
# replay driver, fitfeel_fuzz_replay (framework/testing/fuzz_replay_main.cc), and ctest replays
# the corpus (and REPLAY_ALSO, repository-relative) through this target as fuzz_replay.<name>.
function(fitfeel_add_fuzzer name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS;NEEDS;REPLAY_ALSO" ${ARGN})
  if(FITFEEL_BUILD_FUZZERS)
    add_executable(${name} ${ARG_SOURCES})
    target_link_options(${name} PRIVATE -fsanitize=fuzzer)
    set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/fuzz)
    target_link_libraries(${name} PRIVATE fitfeel::framework ${ARG_LIBS})
    add_dependencies(fitfeel_fuzzers ${name})
    if(ARG_NEEDS)
      add_dependencies(${name} ${ARG_NEEDS})
    endif()
  elseif(FITFEEL_BUILD_TESTS)
    set(driver fitfeel_fuzz_replay)
    if(NOT TARGET ${driver})
      add_executable(${driver} ${PROJECT_SOURCE_DIR}/framework/testing/fuzz_replay_main.cc)
      set_target_properties(${driver} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
      fitfeel_off_tick(${driver})
    endif()
    # The target's objects with its entry point renamed, so that every target links into the one
    # driver, and registered there under its name (framework/testing/fuzz_targets.h).
    set(objects ${name}_replay)
    add_library(${objects} OBJECT ${ARG_SOURCES}
                ${PROJECT_SOURCE_DIR}/framework/testing/fuzz_target_registration.cc)
    target_compile_definitions(${objects} PRIVATE LLVMFuzzerTestOneInput=fitfeel_fuzz_${name}
                                                  FITFEEL_FUZZ_TARGET="${name}")
    target_link_libraries(${objects} PUBLIC fitfeel::framework ${ARG_LIBS})
    fitfeel_off_tick(${objects})
    target_link_libraries(${driver} PRIVATE ${objects})
    if(ARG_NEEDS)
      add_dependencies(${driver} ${ARG_NEEDS})
    endif()
    list(TRANSFORM ARG_REPLAY_ALSO PREPEND ${PROJECT_SOURCE_DIR}/)
    add_test(NAME fuzz_replay.${name}
             COMMAND ${driver} ${name} ${CMAKE_CURRENT_SOURCE_DIR}/corpus/${name} ${ARG_REPLAY_ALSO}
             WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  endif()
endfunction()
