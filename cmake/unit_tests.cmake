# gtest unit tests of the ROS-free layers: one binary, one file per subject under test/unit/.
find_package(GTest REQUIRED)
enable_testing()
file(GLOB_RECURSE K40T_UNIT_TEST_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/test/unit/*.cpp)
add_executable(k40t_unit_tests ${K40T_UNIT_TEST_SOURCES})
target_link_libraries(k40t_unit_tests PRIVATE k40t_core k40t_geo k40t_camera k40t_driver_core GTest::gtest GTest::gtest_main GTest::gmock)
# The optional ROS-free libraries, where this build has them.
foreach(library k40t_sim_model k40t_psdk k40t_frame_export k40t_skyport_bridge)
  if(TARGET ${library})
    target_link_libraries(k40t_unit_tests PRIVATE ${library})
  endif()
endforeach()
target_compile_definitions(k40t_unit_tests PRIVATE
  K40T_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}/test/data"
  K40T_BINARY_DIR="${CMAKE_RUNTIME_OUTPUT_DIRECTORY}")
add_test(NAME k40t_unit_tests COMMAND k40t_unit_tests)
# The tool tests run the built k40t program (K40T_BINARY_DIR).
if(TARGET k40t)
  add_dependencies(k40t_unit_tests k40t)
endif()
