# The k40t command-line tool (decode, monitor, send), ROS-free.
file(GLOB K40T_TOOL_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tools/k40t/*.cpp)
if(K40T_TOOL_SOURCES)
  add_executable(k40t ${K40T_TOOL_SOURCES})
  target_link_libraries(k40t PRIVATE k40t_core)
  if(K40T_WITH_ROS)
    install(TARGETS k40t RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
  endif()
endif()

# skyport_sim: the simulated DJI SKYPORT adapter (PSDK v1), ROS-free; the control socket is
# k40t_sim's (k40t_sim_model).
file(GLOB SKYPORT_SIM_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tools/skyport_sim/*.cpp)
if(SKYPORT_SIM_SOURCES AND TARGET k40t_psdk AND TARGET k40t_sim_model)
  add_executable(skyport_sim ${SKYPORT_SIM_SOURCES})
  target_link_libraries(skyport_sim PRIVATE k40t_psdk k40t_sim_model)
  if(K40T_WITH_ROS)
    install(TARGETS skyport_sim RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
  endif()
endif()
