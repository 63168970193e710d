# The ROS build on top of a finished ROS-free build (K40T_CORE_BUILD_DIR, written by
# cmake/core_export.cmake): the same targets (k40t_core, k40t_psdk, k40t_skyport_bridge,
# k40t_video, k40t_sim_model and the programs), imported rather than compiled again. What those
# targets link publicly was found by cmake/third_party.cmake, as the ROS-free build found it.
set(K40T_TARGETS_FILE ${K40T_CORE_BUILD_DIR}/k40t_targets.cmake)
if(NOT EXISTS ${K40T_TARGETS_FILE})
  message(FATAL_ERROR "K40T_CORE_BUILD_DIR=${K40T_CORE_BUILD_DIR} has no k40t_targets.cmake: "
                      "build the ROS-free part there first (scripts/build.sh core)")
endif()
include(${K40T_TARGETS_FILE})

# rosrun/roslaunch look for the programs in the devel space's lib/k40t_driver: link them there.
foreach(program k40t k40t_sim skyport_sim k40t_video_sim)
  # The location under the build type the ROS-free build was configured with (Release, ...).
  get_target_property(configs ${program} IMPORTED_CONFIGURATIONS)
  list(GET configs 0 config)
  get_target_property(location ${program} IMPORTED_LOCATION_${config})
  if(NOT location)
    message(FATAL_ERROR "${K40T_TARGETS_FILE} gives no location for ${program}")
  endif()
  file(MAKE_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION})
  file(CREATE_LINK ${location} ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}/${program}
       SYMBOLIC)
  install(PROGRAMS ${location} DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
endforeach()

# The lens-distortion module k40t_camera opens on first use (cmake/camera.cmake): beside the
# driver's library in the devel space's lib/, and installed there.
get_target_property(configs k40t_opencv_lens IMPORTED_CONFIGURATIONS)
list(GET configs 0 config)
get_target_property(location k40t_opencv_lens IMPORTED_LOCATION_${config})
file(MAKE_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_LIB_DESTINATION})
file(CREATE_LINK ${location} ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_LIB_DESTINATION}/libk40t_opencv_lens.so
     SYMBOLIC)
install(FILES ${location} DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
