# The simulated pod's RTSP video (src/sim/video/, ROS-free): its sources are part of
# k40t_sim_model (sim.cmake globs src/sim/ recursively); here they get GStreamer's RTSP server and
# OpenCV, and the standalone stream k40t_video_sim is built.
find_package(PkgConfig REQUIRED)
pkg_check_modules(K40T_GST REQUIRED IMPORTED_TARGET
  gstreamer-1.0 gstreamer-app-1.0 gstreamer-rtsp-server-1.0)
find_package(OpenCV REQUIRED COMPONENTS core imgproc)

if(TARGET k40t_sim_model)
  target_include_directories(k40t_sim_model SYSTEM PUBLIC ${OpenCV_INCLUDE_DIRS})
  target_link_libraries(k40t_sim_model PUBLIC PkgConfig::K40T_GST opencv_core opencv_imgproc)
endif()

file(GLOB K40T_VIDEO_SIM_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tools/k40t_video_sim/*.cpp)
add_executable(k40t_video_sim ${K40T_VIDEO_SIM_SOURCES})
target_link_libraries(k40t_video_sim PRIVATE k40t_sim_model)
if(K40T_WITH_ROS)
  install(TARGETS k40t_video_sim RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
endif()
