// k40t_driver/PodNodelet: the driver inside a nodelet manager (zero-copy to other nodelets).
#include "k40t_driver/ros/component_host.h"
#include "k40t_driver/ros/ros_pod.h"

// Multi-threaded handles: a service waiting for an ACK must not hold up the others.
K40T_COMPONENT_NODELET(k40t::driver, PodNodelet, RosPod, "K40T driver", kConcurrent)
