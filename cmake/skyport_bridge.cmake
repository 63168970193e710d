# The SKYPORT bridge's ROS-free logic (src/skyport/): SkyportBridge answering the adapter's
# commands through a PodPort, its worker queue, photo progress, gimbal frame, positioning requests
# and the UTC push rule. The ROS build's k40t_skyport_nodelet (src/ros/skyport/) is only its glue.
file(GLOB K40T_SKYPORT_BRIDGE_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/skyport/*.cpp)
if(K40T_SKYPORT_BRIDGE_SOURCES AND TARGET k40t_psdk)
  add_library(k40t_skyport_bridge STATIC ${K40T_SKYPORT_BRIDGE_SOURCES})
  target_link_libraries(k40t_skyport_bridge PUBLIC k40t_psdk k40t_core)
  set_target_properties(k40t_skyport_bridge PROPERTIES POSITION_INDEPENDENT_CODE ON)
endif()
