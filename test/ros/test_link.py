#!/usr/bin/python3
"""One reader per device and an honest link state (issue 24, items 1 to 3).

Against the driver of link.test (namespace /k40t_link, simulator on a pty): a second
`k40t monitor serial://<its device>` exits non-zero within 1 s naming the driver, and joint_states
stays at 10 Hz; `k40t monitor ros:///k40t_link` shows the link from the topics.
Started here, each in its own namespace: a driver on a device that does not exist ("cannot open",
never "lost"), a driver on a UDP port nobody answers ("waiting", then "nothing has answered", never
"connected"), sim.launch stopped by a Ctrl-C to its whole process group (no "link lost"), and
k40t.launch with a bad device URL (one error naming the parameter and value, no respawn, an ERROR
diagnostic; as a nodelet too)."""
import os
import re
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from sensor_msgs.msg import JointState

from k40t_test_support import Recorder, wait_until

PKG = "k40t_driver"
NS = "/k40t_link"


def free_udp_port():
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Proc:
    """A process in its own session (so a "Ctrl-C" can reach its whole group), output to a file."""

    def __init__(self, args, log_dir, label):
        self.log_path = os.path.join(log_dir, label + ".log")
        self.log = open(self.log_path, "w")
        # rosconsole's INFO lines go to stdout, block-buffered into a file unless told otherwise.
        env = dict(os.environ, ROSCONSOLE_STDOUT_LINE_BUFFERED="1")
        self.proc = subprocess.Popen(args, stdout=self.log, stderr=subprocess.STDOUT,
                                     start_new_session=True, env=env)

    def output(self):
        with open(self.log_path) as f:
            return f.read()

    def wait_output(self, pattern, timeout):
        return wait_until(lambda: re.search(pattern, self.output()), timeout, step=0.05)

    def interrupt_group(self):
        """What Ctrl-C in a terminal does: SIGINT to every process of the group at once."""
        os.killpg(self.proc.pid, signal.SIGINT)

    def stop(self):
        if self.proc.poll() is None:
            self.interrupt_group()
            try:
                self.proc.wait(15)
            except subprocess.TimeoutExpired:
                os.killpg(self.proc.pid, signal.SIGKILL)
                self.proc.wait()
        self.log.close()


class DiagnosticsByName:
    """The latest /diagnostics status by full name ("ns/driver: link")."""

    def __init__(self):
        self.lock = threading.Lock()
        self.latest = {}
        self.sub = rospy.Subscriber("/diagnostics", DiagnosticArray, self._on_msg, queue_size=100)

    def _on_msg(self, array):
        with self.lock:
            for status in array.status:
                self.latest[status.name] = status

    def get(self, name):
        with self.lock:
            return self.latest.get(name)

    def wait(self, name, predicate, timeout):
        return wait_until(lambda: self.get(name) is not None and predicate(self.get(name)), timeout)


class Link(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_link")
        cls.device = rospy.get_param("~link")
        cls.tmp = tempfile.mkdtemp(prefix="k40t_link_test_")
        cls.joints = Recorder(NS + "/joint_states", JointState)
        cls.diagnostics = DiagnosticsByName()
        cls.procs = []
        # The drivers that only log start now, side by side with the main one's start.
        cls.absent = cls.spawn("absent", ["rosrun", PKG, "k40t_node", "__ns:=/k40t_absent",
                                          "__name:=driver", "_device:=serial://%s/none" % cls.tmp])
        cls.udp_url = "udp://127.0.0.1:%d" % free_udp_port()
        cls.nobody = cls.spawn("nobody", ["rosrun", PKG, "k40t_node", "__ns:=/k40t_nobody",
                                          "__name:=driver", "_device:=" + cls.udp_url,
                                          "_link_timeout:=1.0"])
        cls.bad = cls.spawn("bad_url", ["roslaunch", "--wait", PKG, "k40t.launch",
                                        "ns:=k40t_bad_url", "device:=foo://x"])
        cls.spawn("bad_manager", ["rosrun", PKG, "k40t_manager", "__ns:=/k40t_bad_nodelet",
                                  "__name:=manager"])
        cls.bad_nodelet = cls.spawn("bad_nodelet", [
            "roslaunch", "--wait", PKG, "k40t.launch", "ns:=k40t_bad_nodelet",
            "manager:=/k40t_bad_nodelet/manager", "device:=foo://x"])
        assert cls.joints.wait_for(3, timeout=20.0), "no telemetry from the driver"

    @classmethod
    def tearDownClass(cls):
        for p in cls.procs:
            p.stop()

    @classmethod
    def spawn(cls, label, args):
        p = Proc(args, cls.tmp, label)
        cls.procs.append(p)
        return p

    def run_k40t(self, args, timeout):
        start = time.monotonic()
        done = subprocess.run(["k40t"] + args, capture_output=True, text=True, timeout=timeout)
        return done, time.monotonic() - start

    def test_a_second_reader_of_the_drivers_device_is_refused_at_once(self):
        self.assertGreaterEqual(self.joints.rate(2.0), 9.0, "joint_states below 10 Hz before")
        start = time.time()
        for _ in range(3):
            done, seconds = self.run_k40t(["monitor", "serial://" + self.device], 10)
            self.assertNotEqual(done.returncode, 0, done.stderr)
            self.assertLess(seconds, 1.0, "k40t monitor took %.2f s to give up" % seconds)
            self.assertRegex(done.stderr, r"is in use by pid \d+ \(k40t_node\)")
            self.assertIn("ros:///", done.stderr, "no hint at the topic monitor")
            self.assertEqual(done.stdout, "", "the refused monitor printed frames")
        time.sleep(max(0.0, start + 2.0 - time.time()))
        window = time.time() - start
        rate = len(self.joints.messages(start)) / window
        self.assertGreaterEqual(rate, 9.0, "joint_states at %.1f Hz while a monitor tried" % rate)
        link = self.diagnostics.get(NS.lstrip("/") + "/driver: link")
        self.assertIsNotNone(link)
        self.assertEqual(link.level, DiagnosticStatus.OK, link.message)

    def test_b_the_topic_monitor_shows_the_link_without_the_device(self):
        monitor = self.spawn("topic_monitor", ["k40t", "monitor", "ros://" + NS])
        self.assertTrue(monitor.wait_output(r"\d\d:\d\d:\d\d\.\d{3} rx gimbal_attitude", 15.0),
                        monitor.output())
        monitor.stop()
        self.assertIn("k40t monitor: stopped; rx: ", monitor.output())

    def test_c_a_device_that_never_opened_is_cannot_open_not_lost(self):
        url = "serial://%s/none" % self.tmp
        self.assertTrue(self.absent.wait_output(r"K40T cannot open %s\S*: No such file" % re.escape(url),
                                                15.0), self.absent.output())
        self.assertTrue(self.diagnostics.wait(
            "k40t_absent/driver: link",
            lambda s: s.level == DiagnosticStatus.ERROR and s.message.startswith("cannot open"), 10.0))
        self.assertNotIn("lost", self.absent.output())

    def test_d_udp_to_nobody_waits_then_says_nothing_answers(self):
        out = self.nobody
        self.assertTrue(out.wait_output(r"waiting for the pod at %s: nothing has answered for"
                                        % re.escape(self.udp_url), 15.0), out.output())
        # The line before it, as said at start (the text ends there, colour codes follow).
        self.assertRegex(out.output(), r"K40T waiting for the pod at %s(\x1b|\n)" % re.escape(self.udp_url))
        self.assertNotIn("connected", out.output())
        self.assertTrue(self.diagnostics.wait(
            "k40t_nobody/driver: link",
            lambda s: s.level == DiagnosticStatus.ERROR and "nothing has answered" in s.message, 10.0))

    def test_e_a_bad_device_url_is_reported_once_and_not_respawned(self):
        name = "k40t_bad_url/driver: configuration"
        self.assertTrue(self.diagnostics.wait(name, lambda s: s.level == DiagnosticStatus.ERROR, 20.0),
                        self.bad.output())
        message = self.diagnostics.get(name).message
        self.assertIn('parameter /k40t_bad_url/driver/device is wrong: bad device URL "foo://x"', message)
        time.sleep(3.0)  # the old loop restarted every 1.3 s
        out = self.bad.output()
        self.assertEqual(out.count("K40T driver not started"), 1, out)
        self.assertNotIn("respawning", out)
        self.assertIsNone(self.bad.proc.poll(), "roslaunch ended")

    def test_e2_the_nodelet_reports_a_bad_device_url_as_a_diagnostic(self):
        name = "k40t_bad_nodelet/driver: configuration"
        self.assertTrue(self.diagnostics.wait(name, lambda s: s.level == DiagnosticStatus.ERROR, 20.0),
                        self.bad_nodelet.output())
        self.assertIn('parameter /k40t_bad_nodelet/driver/device is wrong: bad device URL "foo://x"',
                      self.diagnostics.get(name).message)
        self.assertIsNone(self.bad_nodelet.proc.poll(), "roslaunch ended")
        self.assertNotIn("respawning", self.bad_nodelet.output())

    def test_f_ctrl_c_is_no_loss(self):
        link = os.path.join(self.tmp, "ctrl_c_pod")
        launch = self.spawn("ctrl_c", ["roslaunch", "--wait", PKG, "sim.launch", "ns:=k40t_ctrl_c",
                                       "sim_link:=" + link, "respawn:=false",
                                       "aggregate:=false"])  # link.test's sim.launch runs it
        self.assertTrue(launch.wait_output(r"K40T connected to the pod at serial://", 20.0),
                        launch.output())
        launch.interrupt_group()
        launch.proc.wait(20)
        out = launch.output()
        self.assertNotIn("lost", out)
        self.assertNotRegex(out, r"K40T .*no answer")
        self.assertNotIn("has died", out)


if __name__ == "__main__":
    rostest.rosrun(PKG, "link", Link, sys.argv)
