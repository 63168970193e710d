// k40t_manager: a nodelet manager (drop-in for `nodelet manager`) that unloads its nodelets
// before it shuts ROS down (after waiting up to a second for their loaders to do it).
//
// Why: nodelet 1.10 (Debian 12) destroys a manager's nodelets before the bonds to their loaders.
// On Ctrl-C every loader breaks its bond while the manager is exiting; the bond's "broken"
// callback then unloads the nodelet again from the map that was just destroyed, and the manager
// aborts with boost::lock_error (a mutex of the destroyed callback-queue manager). Unloading each
// nodelet through the manager's own unload service first removes its bond with the callback
// disabled, so nothing is left for the bonds to do when the Loader is destroyed.
#include <atomic>
#include <chrono>
#include <csignal>
#include <string>
#include <thread>
#include <vector>

#include <nodelet/NodeletUnload.h>
#include <nodelet/loader.h>
#include <ros/ros.h>

#include "k40t_driver/ros/stop_signals.h"
#include "k40t_driver/transport/thread_name.h"

namespace {

std::atomic<bool> g_stop_requested{false};

void request_stop(int) {
  g_stop_requested = true;
  k40t::driver::note_stop_signal();  // the nodelets' links: what follows is no loss
}

void install_stop_handlers() {
  struct sigaction action {};
  action.sa_handler = request_stop;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace

int main(int argc, char** argv) {
  using k40t::transport::name_this_thread;
  // Threads named for `top -H`: roscpp's inherit "k40t_roscpp", the loader's workers (the
  // nodelets' multi-threaded queue) "k40t_nodelet", the spinner's (services, default queue)
  // "k40t_spin".
  const k40t::transport::SavedThreadName program_name;  // the process name: ps, pkill
  name_this_thread("k40t_roscpp");
  ros::init(argc, argv, "manager", ros::init_options::NoSigintHandler);
  install_stop_handlers();
  if (k40t::driver::stop_requested_before_ros_start()) g_stop_requested = true;  // while loading
  ros::NodeHandle private_nh("~");
  name_this_thread("k40t_nodelet");
  nodelet::Loader loader(private_nh);  // load_nodelet, unload_nodelet, list, bonds
  // The manager's services and the nodelets' default queue, as `nodelet manager`'s ros::spin().
  ros::AsyncSpinner spinner(1);
  name_this_thread("k40t_spin");
  spinner.start();
  program_name.restore();

  while (!g_stop_requested && ros::ok()) std::this_thread::sleep_for(std::chrono::milliseconds(50));

  // roslaunch's Ctrl-C reaches the loaders too, and each asks to unload its own nodelet: give
  // them a moment, so that they do not find the nodelet gone and log an error.
  const auto grace_end = std::chrono::steady_clock::now() + std::chrono::seconds(1);
  while (!loader.listLoadedNodelets().empty() && std::chrono::steady_clock::now() < grace_end)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));

  ros::ServiceClient unload = private_nh.serviceClient<nodelet::NodeletUnload>("unload_nodelet");
  for (const std::string& name : loader.listLoadedNodelets()) {
    nodelet::NodeletUnload call;
    call.request.name = name;
    // A loader that got the same Ctrl-C may have unloaded it first: then this one just fails.
    if (!unload.call(call)) loader.unload(name);
  }
  spinner.stop();
  ros::shutdown();
  return 0;
}
