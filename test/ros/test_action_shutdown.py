#!/usr/bin/python3
"""The driver stops promptly and cleanly while an action goal runs: k40t_node on SIGINT, and
PodNodelet unloaded from a nodelet manager that keeps running with no thread left behind. Each
test runs its own simulator and driver (the launch file starts only the test)."""
import os
import signal
import subprocess
import sys
import time
import unittest

import actionlib
import roslib.packages
import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from nodelet.srv import NodeletUnload

from k40t_driver.msg import GimbalMoveToAction, GimbalMoveToGoal, TfUpgradeAction, TfUpgradeGoal
from k40t_test_support import Run, wait_until

PKG = "k40t_driver"


class ActionShutdown(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_action_shutdown")

    def spawn(self, package, executable, *args):
        """Starts a program the way roslaunch finds it (catkin's devel space first)."""
        found = roslib.packages.find_node(package, executable)
        self.assertTrue(found, "no executable %s in %s" % (executable, package))
        process = subprocess.Popen([found[0]] + list(args), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

        def stop():
            if process.poll() is None:
                process.send_signal(signal.SIGINT)
                try:
                    process.wait(5.0)
                except subprocess.TimeoutExpired:
                    process.kill()
                    process.wait()
        self.addCleanup(stop)
        return process

    def start_own_pod(self, tag):
        """A simulator of its own; returns the driver parameters for it."""
        link = "/tmp/k40t_actions_%s_%d" % (tag, os.getpid())
        self.spawn("k40t_driver", "k40t_sim", "--link", "pty:" + link)
        self.assertTrue(wait_until(lambda: os.path.exists(link), 15.0), "no simulator at " + link)
        return ["_device:=serial://" + link, "_time_sync_period:=0", "_laser_target_period:=0"]

    def start_long_goal(self, ns, action="tf_upgrade", spec=TfUpgradeAction, goal=None):
        """A goal that runs for seconds (by default a TF-card upgrade, 10 s in the simulator),
        running once its first feedback arrives."""
        client = actionlib.SimpleActionClient(ns + "/" + action, spec)
        self.assertTrue(client.wait_for_server(rospy.Duration(20.0)), "no action server in " + ns)
        time.sleep(1.0)  # the pod comes online, the driver reads its settings
        run = Run(client, goal if goal is not None else TfUpgradeGoal())
        self.assertTrue(wait_until(lambda: run.feedback, 5.0), "the goal never ran")
        return run

    def test_sigint_during_a_goal_stops_the_node_promptly(self):
        params = self.start_own_pod("sigint")
        node = self.spawn("k40t_driver", "k40t_node", "__ns:=/k40t_sigint", "__name:=driver", *params)
        self.start_long_goal("/k40t_sigint")
        start = time.time()
        node.send_signal(signal.SIGINT)
        code = node.wait(10.0)
        elapsed = time.time() - start
        self.assertEqual(code, 0, "k40t_node exited with %d after SIGINT during a goal" % code)
        self.assertLess(elapsed, 2.0, "k40t_node took %.2f s to stop during a goal" % elapsed)

    def load_goal_unload(self, manager, params, *goal):
        """Loads the driver into the manager, starts a goal, unloads the driver during it."""
        loader = self.spawn("nodelet", "nodelet", "load", "k40t_driver/PodNodelet", "/k40t_unload/manager",
                            "__ns:=/k40t_unload", "__name:=driver", *params)
        run = self.start_long_goal("/k40t_unload", *goal)
        unload = rospy.ServiceProxy("/k40t_unload/manager/unload_nodelet", NodeletUnload)
        start = time.time()
        self.assertTrue(unload(name="/k40t_unload/driver").success)
        elapsed = time.time() - start
        self.assertLess(elapsed, 2.0, "unloading took %.2f s during a goal" % elapsed)
        self.assertIsNone(manager.poll(), "the nodelet manager died on unload")
        # The loader follows its nodelet (bond), so the next load can take its name.
        self.assertTrue(wait_until(lambda: loader.poll() is not None, 5.0), "the loader outlived its nodelet")
        # The running goal was ended, not left hanging (when the result got out before the server went).
        if run.client.wait_for_result(rospy.Duration(1.0)):
            self.assertEqual(run.client.get_state(), GoalStatus.ABORTED)
            self.assertIn("shutting down", run.client.get_result().message)

    def test_unload_during_a_goal_leaves_the_manager_running(self):
        params = self.start_own_pod("unload")
        manager = self.spawn("nodelet", "nodelet", "manager", "__ns:=/k40t_unload", "__name:=manager")
        rospy.wait_for_service("/k40t_unload/manager/unload_nodelet", timeout=15.0)

        def threads():
            return len(os.listdir("/proc/%d/task" % manager.pid))

        # The first cycle also starts roscpp's process-wide timer threads, which stay; a second
        # cycle must end with no more threads than the first: every thread the driver and its
        # action servers start is joined on unload.
        self.load_goal_unload(manager, params)
        time.sleep(1.0)
        after_first = threads()
        # The simulator's upgrade is still running: this time a long gimbal move.
        self.load_goal_unload(manager, params, "gimbal/move_to", GimbalMoveToAction, GimbalMoveToGoal(yaw=-3.0))
        self.assertTrue(wait_until(lambda: threads() <= after_first, 3.0),
                        "threads after the first unload %d, after the second %d" % (after_first, threads()))


if __name__ == "__main__":
    rostest.rosrun(PKG, "action_shutdown", ActionShutdown, sys.argv)
