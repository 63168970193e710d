// k40t_driver/SkyportNodelet: the SKYPORT bridge in the driver's nodelet manager.
#include "k40t_driver/ros/component_host.h"
#include "k40t_driver/ros/skyport/skyport_ros.h"

// Multi-threaded handles: the pod's services are called while pushes keep arriving.
K40T_COMPONENT_NODELET(k40t::driver::skyport, SkyportNodelet, SkyportRos, "SKYPORT bridge",
                       kConcurrent)
