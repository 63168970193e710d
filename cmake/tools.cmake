# The k40t command-line tool (decode, monitor, send), ROS-free.
file(GLOB K40T_TOOL_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tools/k40t/*.cpp)
if(K40T_TOOL_SOURCES)
  add_executable(k40t ${K40T_TOOL_SOURCES})
  target_link_libraries(k40t PRIVATE k40t_core)
  if(K40T_WITH_ROS)
    install(TARGETS k40t RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
  endif()
endif()
