# k40t_rviz_panel: the rviz panel k40t_driver/PodPanel (src/rviz/, listed in rviz_plugins.xml).
# It talks to the driver only through its ROS interface (topics, services, dynamic_reconfigure),
# so it links no pod library: Qt stays out of the nodelet libraries and everything below it. moc runs on the
# Qt classes of src/rviz/ (AUTOMOC on this target only). catkin's result variables are restored
# afterwards for whatever ros_targets.cmake does next.
file(GLOB K40T_RVIZ_PANEL_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/rviz/*.cpp
                                                    ${PROJECT_SOURCE_DIR}/src/rviz/*.h)
set(K40T_SAVED_CATKIN_INCLUDE_DIRS ${catkin_INCLUDE_DIRS})
set(K40T_SAVED_CATKIN_LIBRARIES ${catkin_LIBRARIES})
find_package(catkin REQUIRED COMPONENTS rviz)
find_package(Qt5 REQUIRED COMPONENTS Core Widgets Test)
add_library(k40t_rviz_panel SHARED ${K40T_RVIZ_PANEL_SOURCES})
set_target_properties(k40t_rviz_panel PROPERTIES AUTOMOC ON)
# Qt's signals/slots keywords clash with Boost (rviz's own advice for plugins).
target_compile_definitions(k40t_rviz_panel PRIVATE QT_NO_KEYWORDS)
target_include_directories(k40t_rviz_panel PRIVATE ${PROJECT_SOURCE_DIR}/src/rviz)
target_include_directories(k40t_rviz_panel SYSTEM PRIVATE ${catkin_INCLUDE_DIRS} ${K40T_SAVED_CATKIN_INCLUDE_DIRS}
                                                         ${CATKIN_DEVEL_PREFIX}/include)
target_link_libraries(k40t_rviz_panel PRIVATE ${catkin_LIBRARIES} ${K40T_SAVED_CATKIN_LIBRARIES} Qt5::Widgets
                                              Qt5::Test)
add_dependencies(k40t_rviz_panel ${PROJECT_NAME}_generate_messages_cpp ${PROJECT_NAME}_gencfg)
install(TARGETS k40t_rviz_panel LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(FILES rviz_plugins.xml DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})
set(catkin_INCLUDE_DIRS ${K40T_SAVED_CATKIN_INCLUDE_DIRS})
set(catkin_LIBRARIES ${K40T_SAVED_CATKIN_LIBRARIES})
