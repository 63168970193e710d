# k40t_camera (src/camera/): pixels to rays through a camera_info's intrinsics and lens
# distortion, and which split-screen panel a pixel is in. ROS-free; the driver's locate_pixel uses
# it. The distortion itself is OpenCV's calib3d, in the module k40t_opencv_lens
# (src/camera/opencv_lens/) that k40t_camera opens with dlopen on first use instead of linking
# it: calib3d and what it brings cost ~4.8 MB of resident memory from a process's start
# (include/k40t_driver/camera/opencv_lens.h). The module is built beside the programs (bin/ of
# the ROS-free build) or in the devel space's lib/ beside the driver's library, where
# k40t_camera looks first, and installed there.
# (OpenCV is found by cmake/third_party.cmake.)
file(GLOB K40T_CAMERA_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/camera/*.cpp)
add_library(k40t_camera STATIC ${K40T_CAMERA_SOURCES})
target_include_directories(k40t_camera PUBLIC ${PROJECT_SOURCE_DIR}/include)
target_link_libraries(k40t_camera PUBLIC ${CMAKE_DL_LIBS})
set_target_properties(k40t_camera PROPERTIES POSITION_INDEPENDENT_CODE ON)

add_library(k40t_opencv_lens MODULE ${PROJECT_SOURCE_DIR}/src/camera/opencv_lens/opencv_lens.cpp)
target_include_directories(k40t_opencv_lens PRIVATE ${PROJECT_SOURCE_DIR}/include)
target_include_directories(k40t_opencv_lens SYSTEM PRIVATE ${OpenCV_INCLUDE_DIRS})
target_link_libraries(k40t_opencv_lens PRIVATE opencv_core opencv_calib3d)
set_target_properties(k40t_opencv_lens PROPERTIES PREFIX "lib" CXX_VISIBILITY_PRESET hidden)
if(K40T_WITH_ROS)
  set_target_properties(k40t_opencv_lens PROPERTIES
                        LIBRARY_OUTPUT_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_LIB_DESTINATION})
  install(TARGETS k40t_opencv_lens LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
else()
  set_target_properties(k40t_opencv_lens PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin)
endif()
# Whatever links k40t_camera gets the module built with it.
add_dependencies(k40t_camera k40t_opencv_lens)
