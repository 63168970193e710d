# The ROS layer: one shared library per nodelet, so that each loads only what it uses, over a small
# common one:
#   k40t_ros_common       src/ros/param_reader.cpp, stop_signals.cpp, start_failure.cpp,
#                         callback_threads.cpp: the glue all three share (checked parameters,
#                         SIGTERM as SIGINT, a start that failed on its configuration as a
#                         diagnostic, the standalone nodes' callback threads); roscpp and
#                         diagnostic_updater only;
#   k40t_pod              the rest of src/ros/*.cpp: RosPod (parameters, topics, services,
#                         actions, reconfigure, diagnostics over driver/'s PodDriver), which
#                         k40t_node links without the nodelet library (nodelet's roslib brings
#                         rospack and libpython: ~3 MB resident); no GStreamer or OpenSSL, and of
#                         OpenCV only calib3d (k40t_camera: locate_pixel's lens distortion);
#   k40t_pod_nodelet      src/ros/pod_nodelet.cpp: PodNodelet over k40t_pod;
#   k40t_video_nodelet    src/ros/video/: VideoNodelet, k40t_video_node (OpenCV, GStreamer,
#                         image_transport, camera_info_manager; no OpenSSL; cmake/video_ros.cmake);
#   k40t_skyport_nodelet  src/ros/skyport/: SkyportNodelet, k40t_skyport_node, the ROS glue of the
#                         ROS-free bridge k40t_skyport_bridge (src/skyport/; the PSDK layer, OpenSSL);
#                         no OpenCV or GStreamer: it talks to the pod only through PodNodelet's
#                         ROS interface;
#   k40t_rviz_panel       src/rviz/: the rviz panel PodPanel (Qt; cmake/rviz_panel.cmake).
# test/launch/check_nodelet_libraries.py checks what each one loads. The standalone nodes and the
# rostest programs under test/ros/ link them.
set(K40T_ROS_COMMON_SOURCES ${PROJECT_SOURCE_DIR}/src/ros/callback_threads.cpp
                            ${PROJECT_SOURCE_DIR}/src/ros/param_reader.cpp
                            ${PROJECT_SOURCE_DIR}/src/ros/stop_signals.cpp
                            ${PROJECT_SOURCE_DIR}/src/ros/start_failure.cpp)
file(GLOB K40T_POD_NODELET_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/ros/*.cpp)
list(REMOVE_ITEM K40T_POD_NODELET_SOURCES ${K40T_ROS_COMMON_SOURCES}
     ${PROJECT_SOURCE_DIR}/src/ros/pod_nodelet.cpp)
file(GLOB K40T_SKYPORT_NODELET_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/ros/skyport/*.cpp)

add_library(k40t_ros_common SHARED ${K40T_ROS_COMMON_SOURCES})
target_include_directories(k40t_ros_common PUBLIC ${PROJECT_SOURCE_DIR}/include)
# The ROS headers, for every target that links this one (the nodelets, nodes and tests here; other
# packages get them from catkin_package()'s CATKIN_DEPENDS).
#catkin_lint: ignore_once external_interface_path
target_include_directories(k40t_ros_common SYSTEM PUBLIC ${catkin_INCLUDE_DIRS})
target_link_libraries(k40t_ros_common PUBLIC ${catkin_LIBRARIES})
# Generated message/service headers and the dynamic_reconfigure K40tConfig.h, for all that link it.
add_dependencies(k40t_ros_common ${PROJECT_NAME}_generate_messages_cpp ${PROJECT_NAME}_gencfg)

add_library(k40t_pod SHARED ${K40T_POD_NODELET_SOURCES})
target_link_libraries(k40t_pod PUBLIC k40t_ros_common k40t_driver_core k40t_core k40t_geo k40t_camera)
add_library(k40t_pod_nodelet SHARED ${PROJECT_SOURCE_DIR}/src/ros/pod_nodelet.cpp)
target_link_libraries(k40t_pod_nodelet PUBLIC k40t_pod)

add_library(k40t_skyport_nodelet SHARED ${K40T_SKYPORT_NODELET_SOURCES})
target_link_libraries(k40t_skyport_nodelet PUBLIC k40t_ros_common k40t_skyport_bridge)
# k40t_video_nodelet, k40t_ros_bag and k40t_rviz_panel are defined by the files CMakeLists.txt
# includes before this one (cmake/video_ros.cmake, bag.cmake with k40t_topic_monitor, rviz_panel.cmake).

# Every node catches SIGINT/SIGTERM from the start of its process (src/ros/early/: a static
# library, as only an executable's .preinit_array runs before the shared libraries' initialisers).
add_library(k40t_early_stop_signals STATIC ${PROJECT_SOURCE_DIR}/src/ros/early/early_stop_signals.cpp)
target_include_directories(k40t_early_stop_signals PUBLIC ${PROJECT_SOURCE_DIR}/include)

# One executable per src/ros/nodes/*.cpp, each a thin main() over the library it names.
set(K40T_NODE_LIBRARY_k40t_node k40t_pod)
set(K40T_NODE_LIBRARY_k40t_video_node k40t_video_nodelet)
set(K40T_NODE_LIBRARY_k40t_skyport_node k40t_skyport_nodelet)
set(K40T_NODE_LIBRARY_k40t_manager k40t_ros_common)
file(GLOB K40T_ROS_NODES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/ros/nodes/*.cpp)
foreach(source ${K40T_ROS_NODES})
  get_filename_component(name ${source} NAME_WE)
  if(NOT K40T_NODE_LIBRARY_${name})
    message(FATAL_ERROR "src/ros/nodes/${name}.cpp: say which library it links in ros_targets.cmake")
  endif()
  add_executable(${name} ${source})
  target_link_libraries(${name} PRIVATE ${K40T_NODE_LIBRARY_${name}} k40t_early_stop_signals)
  install(TARGETS ${name} RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
endforeach()

install(TARGETS k40t_ros_common k40t_pod k40t_pod_nodelet k40t_video_nodelet k40t_skyport_nodelet
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(DIRECTORY include/k40t_driver/ DESTINATION ${CATKIN_PACKAGE_INCLUDE_DESTINATION})
install(FILES nodelet_plugins.xml DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})
install(FILES bench/bench_nodelet_plugins.xml DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/bench)
install(DIRECTORY launch config urdf rviz DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})
# The launch files' URDF generator ($(find k40t_driver)/scripts/k40t_urdf.py: prefixed frames): in
# share/, where $(find k40t_driver) points in an install space too, rather than in bin.
#catkin_lint: ignore_once wrong_bin_install_destination
install(PROGRAMS scripts/k40t_urdf.py DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/scripts)
# replay.launch's player (pkg="k40t_driver" type="k40t_replay_play.py"): rosbag play, then the launch ends.
catkin_install_python(PROGRAMS scripts/k40t_replay_play.py DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
# The live telemetry line (`rosrun k40t_driver k40t_status.py`).
catkin_install_python(PROGRAMS scripts/k40t_status.py DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

# rostest programs, run by scripts/run_tests.sh through test/ros/*.test:
#   test/ros/unit/*.cpp  gtest of what needs ROS types (conversions, the settings table...), one
#                        binary k40t_ros_unit_tests;
#   test/ros/*.cpp       gtest nodes, one executable each;
#   test/ros/*.py        Python test nodes (/usr/bin/python3, rospy + unittest).
if(CATKIN_ENABLE_TESTING)
  # Also found by cmake/unit_tests.cmake, which only the ROS-free build includes.
  #catkin_lint: ignore_once duplicate_find
  find_package(GTest REQUIRED)
  file(GLOB K40T_ROS_UNIT_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/test/ros/unit/*.cpp)
  if(K40T_ROS_UNIT_SOURCES)
    add_executable(k40t_ros_unit_tests ${K40T_ROS_UNIT_SOURCES})
    target_link_libraries(k40t_ros_unit_tests PRIVATE k40t_pod_nodelet k40t_video_nodelet k40t_skyport_nodelet k40t_ros_bag GTest::gtest
                                                      GTest::gtest_main)
    # The settings table's test checks docs/ros_interface.md and cfg/ against the table.
    target_compile_definitions(k40t_ros_unit_tests PRIVATE
                               K40T_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}/test/data"
                               K40T_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  endif()
  file(GLOB K40T_ROSTEST_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/test/ros/*.cpp)
  foreach(source ${K40T_ROSTEST_SOURCES})
    get_filename_component(name ${source} NAME_WE)
    add_executable(${name} ${source})
    target_link_libraries(${name} PRIVATE k40t_pod_nodelet k40t_video_nodelet k40t_skyport_nodelet
                                  GTest::gtest)
  endforeach()
  # The passthrough test reads the simulator's frame stamps (render time) in the pixels.
  target_link_libraries(test_video_passthrough PRIVATE k40t_sim_model)
endif()

# End-to-end benchmarks of the ROS layer (bench/ros/, run by bench/ros/run_ros_bench.sh): the
# latency probe as a node and as a nodelet (library k40t_bench_nodelets, listed in
# bench/bench_nodelet_plugins.xml), and the service round-trip client.
add_library(k40t_bench_nodelets SHARED ${PROJECT_SOURCE_DIR}/bench/ros/latency_probe.cpp
                                       ${PROJECT_SOURCE_DIR}/bench/ros/latency_probe_nodelet.cpp)
target_link_libraries(k40t_bench_nodelets PUBLIC k40t_pod_nodelet)
add_executable(k40t_latency_probe ${PROJECT_SOURCE_DIR}/bench/ros/latency_probe_node.cpp)
target_link_libraries(k40t_latency_probe PRIVATE k40t_bench_nodelets)
add_executable(k40t_service_rtt ${PROJECT_SOURCE_DIR}/bench/ros/service_rtt.cpp)
target_link_libraries(k40t_service_rtt PRIVATE k40t_pod_nodelet)
# The SKYPORT bridge's getter ACK latency while a pod call is blocked (no ROS master needed).
add_executable(k40t_skyport_getter_latency ${PROJECT_SOURCE_DIR}/bench/ros/skyport_getter_latency.cpp)
target_link_libraries(k40t_skyport_getter_latency PRIVATE k40t_skyport_bridge)
install(TARGETS k40t_bench_nodelets k40t_video_bench k40t_latency_probe k40t_service_rtt
                k40t_skyport_getter_latency
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
