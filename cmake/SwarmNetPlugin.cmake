# swarmnet_add_plugin(NAME SOURCES... [TESTS TEST_SOURCES...])
#
# Builds one plugin as a MODULE named swarmnet_<NAME>.so into the plugin directory, linked only
# against the SDK (never the kernel), with hidden visibility so that the entry symbol is its only
# export. Used in SwarmNet's tree and, installed with the CMake package, by third-party plugins
# (find_package(SwarmNet)), where the modules go to <build>/plugins unless
# SWARMNET_BUILD_PLUGIN_DIR says otherwise.
#
# TESTS: the plugin's own unit tests (GoogleTest), written against the SDK and its test kit
# (swarmnet/testing.hpp) only. They become one executable, swarmnet_plugin_<NAME>_tests, with
# the plugin's sources compiled in (the tests construct the plugin class directly), registered
# with CTest. Built when the project builds tests: SWARMNET_BUILD_TESTS in SwarmNet's tree,
# BUILD_TESTING (include(CTest)) in a third-party project.
include(GNUInstallDirs)
function(swarmnet_add_plugin name)
  cmake_parse_arguments(ARG "" "" "TESTS" ${ARGN})
  set(sources ${ARG_UNPARSED_ARGUMENTS})
  set(target swarmnet_plugin_${name})
  if(NOT SWARMNET_BUILD_PLUGIN_DIR)
    set(SWARMNET_BUILD_PLUGIN_DIR ${CMAKE_BINARY_DIR}/plugins)
  endif()
  add_library(${target} MODULE ${sources})
  target_link_libraries(${target} PRIVATE SwarmNet::sdk)
  set_target_properties(${target} PROPERTIES
    PREFIX ""
    OUTPUT_NAME swarmnet_${name}
    LIBRARY_OUTPUT_DIRECTORY ${SWARMNET_BUILD_PLUGIN_DIR}
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  # --no-undefined: a missing symbol fails here, not when a run loads the plugin.
  # --require-defined: a library without SWARMNET_PLUGIN(...) is no plugin; the loader would
  # refuse it at run time, so refuse it at link time: "required symbol `swarmnet_plugin_entry'
  # not defined" means the plugin's source lacks SWARMNET_PLUGIN(TheClass) (docs/plugins.md).
  target_link_options(${target} PRIVATE -Wl,--no-undefined
    -Wl,--require-defined=swarmnet_plugin_entry)
  if(TARGET swarmnet_plugins)
    add_dependencies(swarmnet_plugins ${target})
  endif()
  install(TARGETS ${target} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/swarmnet/plugins)

  if(DEFINED SWARMNET_BUILD_TESTS)
    set(build_tests ${SWARMNET_BUILD_TESTS})
  else()
    set(build_tests ${BUILD_TESTING})
  endif()
  if(ARG_TESTS AND build_tests)
    find_package(GTest REQUIRED)
    include(GoogleTest)
    set(tests ${target}_tests)
    add_executable(${tests} ${ARG_TESTS} ${sources})
    target_link_libraries(${tests} PRIVATE SwarmNet::sdk GTest::gtest_main)
    target_include_directories(${tests} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
    if(PROJECT_NAME STREQUAL "SwarmNet")
      set_target_properties(${tests} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
    endif()
    gtest_discover_tests(${tests} DISCOVERY_TIMEOUT 60)
  endif()
endfunction()
