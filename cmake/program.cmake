# k40t_add_program(name SOURCES ... LINK ...): a program of the ROS-free build (k40t_sim, k40t,
# skyport_sim, k40t_video_sim), linked privately to LINK; a ROS build also installs it into the
# package's bin directory, where rosrun and roslaunch look for it.
function(k40t_add_program name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LINK" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_LINK})
  if(K40T_WITH_ROS)
    install(TARGETS ${name} RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
  endif()
endfunction()
