# catkin: messages, services, dynamic_reconfigure and catkin_package(). Included before any
# target so that catkin's output directories apply to every executable (rosrun k40t_driver k40t).
find_package(catkin REQUIRED COMPONENTS roscpp)
catkin_package()
