# k40t_video_nodelet: the video nodelet (src/ros/video/), with the catkin packages it needs besides
# the driver's and the RTSP client it is built on. They are found as packages of their own, not as
# catkin components, so that only this library links them (the other nodelets link
# ${catkin_LIBRARIES}).
file(GLOB K40T_ROS_VIDEO_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/ros/video/*.cpp)
find_package(image_transport REQUIRED)
find_package(camera_info_manager REQUIRED)
add_library(k40t_video_nodelet SHARED ${K40T_ROS_VIDEO_SOURCES})
#catkin_lint: ignore_once external_interface_path (ROS headers, for the targets that link this one)
target_include_directories(k40t_video_nodelet SYSTEM PUBLIC ${image_transport_INCLUDE_DIRS}
                                                            ${camera_info_manager_INCLUDE_DIRS})
target_link_libraries(k40t_video_nodelet PUBLIC k40t_ros_common k40t_video
                                                ${image_transport_LIBRARIES}
                                                ${camera_info_manager_LIBRARIES})

# The video benchmark's probe nodelet (bench/video/, run by bench/video/run_video_bench.sh; listed
# in bench/bench_nodelet_plugins.xml): it reads the simulator's frame stamps.
add_library(k40t_video_bench SHARED ${PROJECT_SOURCE_DIR}/bench/video/video_latency_probe.cpp)
target_link_libraries(k40t_video_bench PUBLIC k40t_video_nodelet k40t_sim_model)

# The k40t_video image_transport plugin pair (src/ros/video_transport/, k40t_video_plugins.xml):
# H.264 through GStreamer both ways, for any image_transport publisher and subscriber.
file(GLOB K40T_VIDEO_TRANSPORT_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/ros/video_transport/*.cpp)
add_library(k40t_video_transport SHARED ${K40T_VIDEO_TRANSPORT_SOURCES})
target_link_libraries(k40t_video_transport PUBLIC k40t_ros_common k40t_video
                                                  ${image_transport_LIBRARIES})
install(TARGETS k40t_video_transport LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(FILES k40t_video_plugins.xml DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})

# The passthrough benchmark's subscriber (bench/video/run_passthrough_bench.sh).
add_executable(k40t_passthrough_probe ${PROJECT_SOURCE_DIR}/bench/video/passthrough_probe.cpp)
target_link_libraries(k40t_passthrough_probe PRIVATE k40t_video_nodelet k40t_sim_model)
