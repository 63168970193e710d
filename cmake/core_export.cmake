# The ROS-free build describes its libraries and programs in k40t_targets.cmake, so that the ROS
# build (cmake/core_import.cmake) links and runs them instead of compiling the same sources again.
set(K40T_EXPORTED_TARGETS)
foreach(target k40t_codec k40t_transport k40t_core k40t_geo k40t_camera k40t_opencv_lens k40t_driver_core k40t_psdk k40t_skyport_bridge k40t_frame_export k40t_video k40t_sim_model k40t k40t_sim skyport_sim k40t_video_sim)
  if(TARGET ${target})
    list(APPEND K40T_EXPORTED_TARGETS ${target})
  endif()
endforeach()
export(TARGETS ${K40T_EXPORTED_TARGETS} FILE ${CMAKE_BINARY_DIR}/k40t_targets.cmake)
