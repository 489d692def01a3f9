# cmake -DSOURCE_DIR=... -DWORK_DIR=... -DGENERATOR=... -DCXX=... -P forgotten_macro_test.cmake
# Configures and builds tests/plugin/forgotten_macro (a plugin without SWARMNET_PLUGIN) and
# expects the link to fail naming swarmnet_plugin_entry.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(
  COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/plugin/forgotten_macro -B ${WORK_DIR}
          -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX} -DSWARMNET_SOURCE_DIR=${SOURCE_DIR}
  RESULT_VARIABLE configured OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT configured EQUAL 0)
  message(FATAL_ERROR "configuring the fixture project failed:\n${out}")
endif()
execute_process(
  COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR} --parallel 1
  RESULT_VARIABLE built OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(built EQUAL 0)
  message(FATAL_ERROR "a plugin without SWARMNET_PLUGIN(...) linked:\n${out}")
endif()
if(NOT out MATCHES "swarmnet_plugin_entry")
  message(FATAL_ERROR "the build failed, but not naming swarmnet_plugin_entry:\n${out}")
endif()
message(STATUS "the link failed naming swarmnet_plugin_entry, as expected")
file(REMOVE_RECURSE ${WORK_DIR})
