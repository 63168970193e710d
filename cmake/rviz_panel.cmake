# k40t_rviz_panel: the rviz panel k40t_driver/PodPanel (src/rviz/, listed in rviz_plugins.xml).
# It talks to the driver only through its ROS interface (topics, services, dynamic_reconfigure),
# so it links no pod library: Qt stays out of the nodelet libraries and everything below it. moc runs on the
# Qt classes of src/rviz/ (AUTOMOC on this target only). rviz is found as a package of its own, not
# as a catkin component, so that only this library links it.
file(GLOB K40T_RVIZ_PANEL_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/rviz/*.cpp
                                                    ${PROJECT_SOURCE_DIR}/src/rviz/*.h)
find_package(rviz REQUIRED)
find_package(Qt5 REQUIRED COMPONENTS Core Widgets Test)
add_library(k40t_rviz_panel SHARED ${K40T_RVIZ_PANEL_SOURCES})
set_target_properties(k40t_rviz_panel PROPERTIES AUTOMOC ON)
# Qt's signals/slots keywords clash with Boost (rviz's own advice for plugins).
target_compile_definitions(k40t_rviz_panel PRIVATE QT_NO_KEYWORDS)
target_include_directories(k40t_rviz_panel PRIVATE ${PROJECT_SOURCE_DIR}/src/rviz)
# The devel space's include/: the generated message and dynamic_reconfigure headers.
#catkin_lint: ignore_once external_directory
target_include_directories(k40t_rviz_panel SYSTEM PRIVATE ${rviz_INCLUDE_DIRS} ${catkin_INCLUDE_DIRS}
                                                         ${CATKIN_DEVEL_PREFIX}/include)
target_link_libraries(k40t_rviz_panel PRIVATE ${rviz_LIBRARIES} ${catkin_LIBRARIES} Qt5::Widgets
                                              Qt5::Test)
add_dependencies(k40t_rviz_panel ${PROJECT_NAME}_generate_messages_cpp ${PROJECT_NAME}_gencfg)
install(TARGETS k40t_rviz_panel LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(FILES rviz_plugins.xml DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})
