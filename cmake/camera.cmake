# k40t_camera (src/camera/): pixels to rays through a camera_info's intrinsics and lens
# distortion (OpenCV's calib3d, nothing else of OpenCV), and which split-screen panel a pixel is
# in. ROS-free; the driver's locate_pixel uses it.
# (OpenCV is found by cmake/third_party.cmake.)
file(GLOB K40T_CAMERA_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/camera/*.cpp)
add_library(k40t_camera STATIC ${K40T_CAMERA_SOURCES})
target_include_directories(k40t_camera PUBLIC ${PROJECT_SOURCE_DIR}/include)
target_include_directories(k40t_camera SYSTEM PRIVATE ${OpenCV_INCLUDE_DIRS})
target_link_libraries(k40t_camera PUBLIC opencv_core opencv_calib3d)
set_target_properties(k40t_camera PROPERTIES POSITION_INDEPENDENT_CODE ON)
