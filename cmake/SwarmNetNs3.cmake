# Finds Debian's libns3-dev (ns-3.37) for the targets that use ns-3: the validation replay
# (tests/validation/) and the ns-3 network engine module (core/src/ns3_engine/). Its pkg-config
# files carry a stray "-I/usr\;" in their cflags, so headers and libraries are found directly.
#
# swarmnet_find_ns3(<component>...)
# Sets, in the caller's scope: NS3_INCLUDE_DIR, SWARMNET_NS3_LIBRARIES (one library per
# component, in the order given), SWARMNET_NS3_MISSING (the components not found) and
# SWARMNET_NS3_FOUND (headers and every component found).
include_guard(GLOBAL)

function(swarmnet_find_ns3)
  find_path(NS3_INCLUDE_DIR ns3/core-module.h PATHS /usr/include /usr/local/include)
  set(libraries)
  set(missing)
  foreach(component IN LISTS ARGN)
    find_library(NS3_${component}_LIBRARY NAMES ns3-${component} ns3.37-${component}-default)
    if(NS3_${component}_LIBRARY)
      list(APPEND libraries ${NS3_${component}_LIBRARY})
    else()
      list(APPEND missing ns3-${component})
    endif()
  endforeach()
  if(NS3_INCLUDE_DIR AND NOT missing)
    set(found ON)
  else()
    set(found OFF)
  endif()
  set(NS3_INCLUDE_DIR ${NS3_INCLUDE_DIR} PARENT_SCOPE)
  set(SWARMNET_NS3_LIBRARIES ${libraries} PARENT_SCOPE)
  set(SWARMNET_NS3_MISSING ${missing} PARENT_SCOPE)
  set(SWARMNET_NS3_FOUND ${found} PARENT_SCOPE)
endfunction()
