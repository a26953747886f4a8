# Small helpers so each folder's CMakeLists.txt stays short.

# vbim_test(<name> SOURCES <files...> LIBS <targets...>)
# One GoogleTest executable; its tests are discovered when ctest runs (not at build time), so a
# sanitizer build does not run them twice.
function(vbim_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} GTest::gtest GTest::gtest_main Threads::Threads)
  gtest_discover_tests(${name} DISCOVERY_MODE PRE_TEST WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}
                       PROPERTIES ENVIRONMENT "VBIM_SOURCE_DIR=${PROJECT_SOURCE_DIR}")
endfunction()

# vbim_bench(<name> SOURCES <files...> LIBS <targets...>)
function(vbim_bench name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} benchmark::benchmark Threads::Threads)
endfunction()
