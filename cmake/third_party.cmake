# The non-ROS libraries both builds use, found once here: the ROS-free build compiles against them
# and the ROS build's imported targets (cmake/core_import.cmake) link them. Found in one place
# because a second find_package(OpenCV) with other components hides the first one's (catkin_lint's
# "shadows previously selected components"); each target still links only the parts it uses.
find_package(Threads REQUIRED)
# Boost.Preprocessor (header-only): codec/field_list.h declares a message's members and layout from
# one list of fields.
find_package(Boost 1.71 REQUIRED)
find_package(OpenSSL REQUIRED)  # psdk/: AES of encrypted PSDK frames
find_package(PkgConfig REQUIRED)
pkg_check_modules(K40T_GST REQUIRED IMPORTED_TARGET gstreamer-1.0 gstreamer-app-1.0 gstreamer-rtsp-1.0
                  gstreamer-video-1.0)
pkg_check_modules(K40T_GST_RTSP_SERVER REQUIRED IMPORTED_TARGET gstreamer-rtsp-server-1.0)
# calib3d: k40t_camera (lens distortion); imgproc, videoio: k40t_video (the RTSP client);
# imgcodecs: k40t bag --video-frames (PNG).
find_package(OpenCV REQUIRED COMPONENTS core imgproc videoio calib3d imgcodecs)
