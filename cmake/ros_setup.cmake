# catkin: messages, services, dynamic_reconfigure and catkin_package(). Included before any
# target so that catkin's output directories apply to every executable (rosrun k40t_driver k40t).
set(K40T_CATKIN_COMPONENTS
  roscpp nodelet pluginlib std_msgs std_srvs sensor_msgs geometry_msgs nav_msgs diagnostic_msgs
  diagnostic_updater dynamic_reconfigure tf2 tf2_ros tf2_msgs actionlib actionlib_msgs visualization_msgs
  message_generation)
find_package(catkin REQUIRED COMPONENTS ${K40T_CATKIN_COMPONENTS})

# Message and service definitions are globbed: adding a .msg/.srv file is enough.
file(GLOB K40T_MSG_FILES RELATIVE ${PROJECT_SOURCE_DIR}/msg CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/msg/*.msg)
file(GLOB K40T_SRV_FILES RELATIVE ${PROJECT_SOURCE_DIR}/srv CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/srv/*.srv)
add_message_files(FILES ${K40T_MSG_FILES})
file(GLOB K40T_ACTION_FILES RELATIVE ${PROJECT_SOURCE_DIR}/action CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/action/*.action)
add_service_files(FILES ${K40T_SRV_FILES})
add_action_files(FILES ${K40T_ACTION_FILES})  # the long operations (docs/ros_interface.md, "Actions")
generate_messages(DEPENDENCIES std_msgs sensor_msgs geometry_msgs actionlib_msgs)

generate_dynamic_reconfigure_options(cfg/K40t.cfg)
# K40t.cfg reads the enum names from cfg/setting_enums.txt: regenerate when it changes.
add_custom_command(OUTPUT ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_INCLUDE_DESTINATION}/K40tConfig.h APPEND
                   DEPENDS ${PROJECT_SOURCE_DIR}/cfg/setting_enums.txt)

catkin_package(
  INCLUDE_DIRS include
  LIBRARIES k40t_ros_common k40t_pod_nodelet k40t_video_nodelet k40t_skyport_nodelet
  CATKIN_DEPENDS roscpp nodelet pluginlib std_msgs std_srvs sensor_msgs geometry_msgs nav_msgs
                 diagnostic_msgs diagnostic_updater dynamic_reconfigure tf2 tf2_ros tf2_msgs actionlib
                 actionlib_msgs visualization_msgs message_runtime)
