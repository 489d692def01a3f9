# swarmnet_add_plugin(NAME SOURCES...)
#
# Builds one plugin as a MODULE named swarmnet_<NAME>.so into the plugin directory, linked only
# against the SDK (never the kernel), with hidden visibility so that the entry symbol is its only
# export. Used in SwarmNet's tree and, installed with the CMake package, by third-party plugins
# (find_package(SwarmNet)), where the modules go to <build>/plugins unless
# SWARMNET_BUILD_PLUGIN_DIR says otherwise.
include(GNUInstallDirs)
function(swarmnet_add_plugin name)
  set(target swarmnet_plugin_${name})
  if(NOT SWARMNET_BUILD_PLUGIN_DIR)
    set(SWARMNET_BUILD_PLUGIN_DIR ${CMAKE_BINARY_DIR}/plugins)
  endif()
  add_library(${target} MODULE ${ARGN})
  target_link_libraries(${target} PRIVATE SwarmNet::sdk)
  set_target_properties(${target} PROPERTIES
    PREFIX ""
    OUTPUT_NAME swarmnet_${name}
    LIBRARY_OUTPUT_DIRECTORY ${SWARMNET_BUILD_PLUGIN_DIR}
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  target_link_options(${target} PRIVATE -Wl,--no-undefined)
  if(TARGET swarmnet_plugins)
    add_dependencies(swarmnet_plugins ${target})
  endif()
  install(TARGETS ${target} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/swarmnet/plugins)
endfunction()
