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
