# Small helpers so each folder's CMakeLists.txt stays short.

# vbim_test(<name> SOURCES <files...> LIBS <targets...>)
# One GoogleTest executable; its tests are discovered when ctest runs (not at build time), so a
# sanitizer build does not run them twice.
function(vbim_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  # Test support headers are included by path from the root ("tests/player/sample_path.hpp").
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} GTest::gtest GTest::gtest_main Threads::Threads)
  # Listing the tests starts the program (and its libraries: OpenImageIO under ASan takes seconds);
  # CMake's default 5 s discovery time-out failed a sanitizer suite on a loaded machine.
  gtest_discover_tests(${name} DISCOVERY_MODE PRE_TEST DISCOVERY_TIMEOUT 120
                       WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR} PROPERTIES ENVIRONMENT "VBIM_SOURCE_DIR=${PROJECT_SOURCE_DIR}"
                       # Test files under this build tree's test-scratch/ (made by the fixture in tests/CMakeLists.txt,
                       # tests/support/scratch.hpp), not /tmp, where another tree's tests or a clean-up could meet them.
                       ENVIRONMENT_MODIFICATION "TMPDIR=set:${PROJECT_BINARY_DIR}/test-scratch"
                       FIXTURES_REQUIRED vbim_test_scratch)
endfunction()

# vbim_bench(<name> SOURCES <files...> LIBS <targets...>)
function(vbim_bench name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} benchmark::benchmark Threads::Threads)
endfunction()

include(GNUInstallDirs)

# vbim_library(<name> [MODEL] SOURCES <files...> [PUBLIC <deps...>] [PRIVATE <deps...>])
# One static library with its own include directory: the project root while building (headers are
# included by path from it), include/vbim once installed. MODEL marks a part of the portable model:
# it may link only other model targets and Threads::Threads, which is checked here at configure time.
function(vbim_library name)
  cmake_parse_arguments(ARG "MODEL" "" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                                            $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/vbim>)
  target_link_libraries(${name} PUBLIC ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE})
  # Users compile our headers (coroutines, concepts): C++20 goes with the target, also when installed.
  target_compile_features(${name} PUBLIC cxx_std_20)
  if(ARG_MODEL)
    get_property(model GLOBAL PROPERTY VBIM_MODEL_TARGETS)
    foreach(dep IN LISTS ARG_PUBLIC ARG_PRIVATE)
      if(NOT dep STREQUAL "Threads::Threads" AND NOT dep IN_LIST model)
        message(FATAL_ERROR "${name} is part of the portable model but links ${dep}: the model links only "
                            "the C++ standard library, threads and other model targets (docs/architecture.md)")
      endif()
    endforeach()
    set_property(GLOBAL APPEND PROPERTY VBIM_MODEL_TARGETS ${name})
  endif()
endfunction()
