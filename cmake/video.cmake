# Video, ROS-free:
#   k40t_video      the RTSP client (src/video/): OpenCV videoio capture with the GStreamer or
#                   FFmpeg back-end, the newest-frame grabber, the native GStreamer access-unit
#                   source (passthrough), H.264 encoder/decoder, stamps, zoom intrinsics;
#   src/sim/video/  the simulated pod's RTSP server and renderers, part of k40t_sim_model (sim.cmake
#                   globs src/sim/ recursively): here it gets GStreamer's RTSP server and OpenCV,
#                   and k40t_video for the split-screen layout both sides share; the unit tests and
#                   benchmarks reach k40t_video through k40t_sim_model;
#   k40t_video_sim  the standalone simulated stream (tools/k40t_video_sim/).
# GStreamer and OpenCV are found by cmake/third_party.cmake.

file(GLOB K40T_VIDEO_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/video/*.cpp)
add_library(k40t_video STATIC ${K40T_VIDEO_SOURCES})
target_include_directories(k40t_video PUBLIC ${PROJECT_SOURCE_DIR}/include)
#catkin_lint: ignore_once external_interface_path (cv::Mat is in k40t_video's headers)
target_include_directories(k40t_video SYSTEM PUBLIC ${OpenCV_INCLUDE_DIRS})
target_link_libraries(k40t_video PUBLIC k40t_core PkgConfig::K40T_GST opencv_core opencv_imgproc
                                        opencv_videoio)
set_target_properties(k40t_video PROPERTIES POSITION_INDEPENDENT_CODE ON)

if(TARGET k40t_sim_model)
  target_link_libraries(k40t_sim_model PUBLIC k40t_video PkgConfig::K40T_GST_RTSP_SERVER)
endif()

file(GLOB K40T_VIDEO_SIM_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tools/k40t_video_sim/*.cpp)
k40t_add_program(k40t_video_sim SOURCES ${K40T_VIDEO_SIM_SOURCES} LINK k40t_sim_model)
