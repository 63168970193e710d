# Offline decoding of recorded flights (`k40t bag`, docs/bag_decoding.md): the library k40t_ros_bag
# (src/ros/bag/: the bag sink of the decoded topics, the decoder, the video export) and the program
# k40t_bag that
# `k40t bag` runs. The exports and the k40t tool's argument parsing and frame JSON it reuses are
# the ROS-free k40t_frame_export (cmake/tools.cmake). It reads the driver's YAML parameter file
# with yaml-cpp (no parameter server).
find_package(rosbag_storage REQUIRED)
find_package(yaml-cpp REQUIRED)
file(GLOB K40T_ROS_BAG_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/ros/bag/*.cpp)
add_library(k40t_ros_bag SHARED ${K40T_ROS_BAG_SOURCES})
#catkin_lint: ignore_once external_interface_path (for k40t_bag and the tests that link it)
target_include_directories(k40t_ros_bag SYSTEM PUBLIC ${rosbag_storage_INCLUDE_DIRS}
                                                      ${YAML_CPP_INCLUDE_DIR})
target_link_libraries(k40t_ros_bag PUBLIC k40t_pod_nodelet k40t_frame_export k40t_video opencv_imgcodecs
                                         ${rosbag_storage_LIBRARIES} ${YAML_CPP_LIBRARIES})

add_executable(k40t_bag ${PROJECT_SOURCE_DIR}/tools/k40t_bag/main.cpp
                        ${PROJECT_SOURCE_DIR}/tools/k40t_bag/progress_bar.cpp)
target_link_libraries(k40t_bag PRIVATE k40t_ros_bag)

# The decode benchmark (bench/ros/bag_decode_bench.cpp): a synthetic hour of pod traffic.
add_executable(k40t_bag_decode_bench ${PROJECT_SOURCE_DIR}/bench/ros/bag_decode_bench.cpp)
target_link_libraries(k40t_bag_decode_bench PRIVATE k40t_ros_bag k40t_sim_model)

install(TARGETS k40t_ros_bag k40t_bag k40t_bag_decode_bench
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

# `k40t monitor ros:///NAMESPACE` runs k40t_topic_monitor (tools/k40t_topic_monitor/): a running
# driver's link from its raw/rx and raw/tx topics, printed as the k40t tool prints a link.
add_executable(k40t_topic_monitor ${PROJECT_SOURCE_DIR}/tools/k40t_topic_monitor/main.cpp)
target_link_libraries(k40t_topic_monitor PRIVATE k40t_ros_common k40t_frame_export)
install(TARGETS k40t_topic_monitor RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
