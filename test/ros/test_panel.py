#!/usr/bin/python3
"""The rviz panel k40t_driver/PodPanel against the simulated pod, end to end: rviz loads
rviz/k40t.rviz on a virtual X display, the test presses the panel's buttons, drags its joystick,
types into it and picks from its combo boxes (real Qt input events through the panel's test hook),
and checks through the simulator's control socket that the pod itself changed: palette, image
mode, zoom (slider and held buttons), gimbal (joystick, held keys, move to angles, centre, look at
the point clicked with rviz's Publish Point tool), photo,
recording, laser. A refused call must show the driver's message in the panel, and a namespace with
no driver behind it must leave rviz running with a message saying so.

Every wait is for a condition with a generous timeout (the machine may be loaded); the only
timed observation is "the pod stopped moving": the same reading twice, a second apart."""
import math
import re
import sys
import time
import unittest

import rospy
import rostest

from geometry_msgs.msg import PointStamped, Twist

from k40t_driver.srv import SetPalette
from k40t_test_support import Recorder, SimControl, wait_until
from panel_driver import RvizPanel

PKG = "k40t_driver"
WAIT = 40.0  # seconds for the pod to get somewhere after a click


class Pod:
    """The simulated pod's true state, from its control socket's status line."""

    def __init__(self, path):
        self.sim = SimControl(path)

    def status(self):
        return self.sim.ok("status")

    def number(self, key):
        return self.sim.number(key)

    def photo_count(self):
        return int(re.match(r"ok (\d+) photos", self.sim.ok("photos")).group(1))

    def settled(self, key, timeout=WAIT):
        """The value of `key` once it read the same twice a second apart (the pod stopped)."""
        last = [self.number(key), time.time()]

        def still():
            now = self.number(key)
            if abs(now - last[0]) > 1e-6:
                last[:] = [now, time.time()]
                return False
            return time.time() - last[1] >= 1.0

        if not wait_until(still, timeout, step=0.1):
            raise AssertionError("%s still changing after %.0f s: %s" % (key, timeout, self.status()))
        return last[0]


class PanelTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_panel")
        cls.pod = Pod(rospy.get_param("~control"))
        cls.ns = rospy.get_param("~ns")  # not the default /k40t: the panel takes it from the .rviz
        cls.rates = Recorder(cls.ns + "/gimbal/cmd_rate", Twist)
        cls.panel = RvizPanel(rospy.get_param("~rviz_config"), cls.ns)

    @classmethod
    def tearDownClass(cls):
        cls.panel.close()

    def near(self, key, value, tolerance):
        return wait_until(lambda: abs(self.pod.number(key) - value) <= tolerance, WAIT, step=0.1)

    def assertRatesThenStop(self, since, axis, expected):
        """cmd_rate from the panel since `since`: about `expected` rad/s on `axis` ("y" pitch, "z" yaw)
        repeated while held (the driver's dead-man would stop it otherwise), then an explicit zero
        on release (not the driver's own dead-man stop)."""

        def seen():
            msgs = self.rates.messages(since)
            # 2 %: the press lands on whole pixels, the knob's centre may be half a pixel off.
            held = [m for m in msgs if abs(getattr(m.angular, axis) - expected) < 0.02 * abs(expected)]
            return len(held) >= 2 and msgs[-1].angular.y == 0 and msgs[-1].angular.z == 0
        ok = wait_until(seen, WAIT)
        self.assertTrue(ok, "cmd_rate: %s" % [(m.angular.y, m.angular.z) for m in self.rates.messages(since)])

    def assertPod(self, key, value, tolerance=0.05):
        self.assertTrue(self.near(key, value, tolerance), "%s not %s: %s" % (key, value, self.pod.status()))

    def test_01_status_shows_the_pod_and_a_healthy_link(self):
        self.assertEqual(self.panel.text("namespace"), self.ns)  # loaded from the .rviz file
        self.assertTrue(wait_until(lambda: self.panel.text("status_link").startswith("OK"), WAIT),
                        self.panel.text("status_link"))
        self.assertTrue(wait_until(lambda: "yaw" in self.panel.text("status_joints"), WAIT))
        for label, text in (("status_zoom", "x, focal length"), ("status_thermal", "max"),
                            ("status_alarms", "none"), ("status_sd", "MB free")):
            self.assertTrue(wait_until(lambda: text in self.panel.text(label), WAIT), self.panel.text(label))

    def test_02_palette_from_the_combo(self):
        self.assertEqual(self.pod.number("palette"), 1)  # white hot, the simulator's default
        self.assertEqual(self.panel.do("choose palette iron red"), "iron red")
        self.assertPod("palette", 5)

    def test_03_image_mode_from_the_combo(self):
        self.panel.do("choose image_mode Split screen")
        self.assertPod("image-mode", 7)

    def test_04_zoom_slider(self):
        start = float(self.panel.text("zoom_value").rstrip("x"))
        self.panel.do("key zoom_slider PgUp")  # one page: +5.0x
        self.assertPod("zoom", start + 5.0)

    def test_05_zoom_in_while_held(self):
        before = self.pod.settled("zoom")
        self.panel.do("press zoom_in")
        zoomed = wait_until(lambda: self.pod.number("zoom") > before * 1.3, WAIT, step=0.05)
        self.panel.do("release zoom_in")
        self.assertTrue(zoomed, "the pod did not zoom in while the button was held: %s" % self.pod.status())
        # Let go: the zoom stops short of its end (160x, ~2 s of zooming further).
        self.assertLess(self.pod.settled("zoom"), 159.0)

    def assertHeldControlTurns(self, key, margin, hold, let_go, axis, rate, limit):
        """Holds a gimbal control (panel commands `hold`, then `let_go`): the pod's `key` must grow
        by more than `margin` degrees meanwhile, cmd_rate must carry `rate` (rad/s) about `axis`
        and then stop, and the pod must stop short of `limit`."""
        before = self.pod.settled(key)
        since = time.time()
        self.panel.do(hold)
        turned = wait_until(lambda: self.pod.number(key) > before + margin, WAIT, step=0.05)
        self.panel.do(let_go)
        self.assertTrue(turned, "the gimbal's %s did not grow while held: %s" % (key, self.pod.status()))
        self.assertRatesThenStop(since, axis, rate)
        self.assertLess(self.pod.settled(key), limit)

    def test_06_joystick_turns_while_held_and_stops_on_release(self):
        # Full right: the pod's yaw grows (right positive); REP 103: right is negative yaw. It stops
        # before the mechanical limit.
        self.assertHeldControlTurns("yaw", 10, "press gimbal_joystick 1 0", "release gimbal_joystick",
                                    "z", -math.radians(20), 179.0)

    def test_07_held_arrow_key_turns_and_release_stops(self):
        self.panel.do("type gimbal_max_rate 5")  # 5 deg/s: seconds of margin before the +30 limit
        # Camera up: the pod's pitch grows (up positive); REP 103: up is negative pitch. It stops
        # before the +30 limit.
        self.assertHeldControlTurns("pitch", 3, "keypress gimbal_joystick Up", "keyrelease gimbal_joystick Up",
                                    "y", -math.radians(5), 29.5)

    def test_08_move_to_angles_then_centre_and_look_down(self):
        self.panel.do("type gimbal_pitch 20")  # REP 103: 20 deg down
        self.panel.do("type gimbal_yaw -30")  # 30 deg right
        self.panel.do("click gimbal_move")
        self.assertPod("pitch", -20, 0.5)
        self.assertPod("yaw", 30, 0.5)
        self.panel.do("click gimbal_center")
        self.assertPod("pitch", 0, 0.5)
        self.assertPod("yaw", 0, 0.5)
        self.panel.do("click gimbal_look_down")
        self.assertPod("pitch", -90, 0.5)

    def test_08a_look_at_clicked_point(self):
        # rviz's Publish Point tool sends /clicked_point in the fixed frame; here the gimbal's
        # base: 100 m ahead, 50 m right, 30 m below = yaw 26.57 deg right, pitch 15.02 deg down.
        clicked = rospy.Publisher("/clicked_point", PointStamped, queue_size=1)
        looks = Recorder(self.ns + "/gimbal/look_at_point", PointStamped)
        self.panel.do("click gimbal_look_at_clicked")  # down
        point = PointStamped()
        point.header.frame_id = "k40t_base_link"
        point.point.x, point.point.y, point.point.z = 100.0, -50.0, -30.0
        self.assertTrue(wait_until(lambda: clicked.publish(point) or looks.count() > 0, WAIT, step=0.2),
                        "the panel does not pass the clicked point on")
        self.assertPod("yaw", 26.57, 0.1)
        self.assertPod("pitch", -15.02, 0.1)
        self.panel.do("click gimbal_look_at_clicked")  # up: the points stop
        up = time.time()
        time.sleep(1.0)
        self.assertEqual(looks.messages(since=up + 0.3), [])
        looks.close()
        clicked.unregister()

    def test_09_record_photo_and_laser(self):
        self.panel.do("click record_start")  # refused in photo mode: the pod's message shows
        self.assertTrue(wait_until(lambda: "record start failed" in self.panel.text("message"), WAIT))
        self.assertIn("recording no", self.pod.status())
        self.panel.do("choose camera_mode Video mode")
        self.assertTrue(wait_until(lambda: "camera_mode: ok" in self.panel.text("message"), WAIT),
                        self.panel.text("message"))
        self.panel.do("click record_start")
        self.assertTrue(wait_until(lambda: "recording yes" in self.pod.status(), WAIT),
                        "panel: %r; pod: %r" % (self.panel.text("message"), self.pod.status()))
        self.assertTrue(wait_until(lambda: re.search(r"0:0[1-9]", self.panel.text("status_record")), WAIT),
                        "no recording time: " + self.panel.text("status_record"))
        self.panel.do("click record_stop")
        self.assertTrue(wait_until(lambda: "recording no" in self.pod.status(), WAIT))
        self.panel.do("choose camera_mode Photo mode")
        self.assertTrue(wait_until(lambda: "camera_mode: ok" in self.panel.text("message"), WAIT),
                        self.panel.text("message"))
        photos = self.pod.photo_count()
        self.panel.do("click take_photo")
        self.assertTrue(wait_until(lambda: self.pod.photo_count() == photos + 1, WAIT))
        self.panel.do("click laser_measure")
        self.assertTrue(wait_until(lambda: re.match(r"([0-9.]+ m|no return) \(at", self.panel.text("status_range")),
                                   WAIT), self.panel.text("status_range"))

    def test_10_refused_call_shows_the_drivers_message(self):
        self.pod.sim.ok("refuse 0x000106")  # the palette request
        try:
            self.panel.do("choose palette rainbow")
            shown = wait_until(lambda: "set_palette failed" in self.panel.text("message"), WAIT)
            self.assertTrue(shown, self.panel.text("message"))
            # The same refusal asked directly: its message is what the panel shows.
            rospy.wait_for_service(self.ns + "/set_palette", timeout=WAIT)
            reply = rospy.ServiceProxy(self.ns + "/set_palette", SetPalette)(palette=3)
            self.assertFalse(reply.success)
            self.assertIn(reply.message, self.panel.text("message"))
            self.assertEqual(self.pod.number("palette"), 5)  # unchanged: still iron red
        finally:
            self.pod.sim.ok("refuse 0")

    def test_10a_a_slow_call_does_not_hold_the_gui(self):
        """With the pod's ACKs late, laser/measure takes the driver's retries (about a second). The
        click and the reading of the message line are carried out in the same pass of the GUI
        thread: had the click waited for the call, the line would already show its outcome."""
        self.pod.sim.ok("delay-acks 5000")
        try:
            _, during = self.panel.do_together(["click laser_measure", "text message"])
            self.assertNotIn("laser/measure", during)
            # The outcome arrives later, the driver's reason with it.
            self.assertTrue(wait_until(lambda: "laser/measure failed" in self.panel.text("message"), WAIT),
                            self.panel.text("message"))
        finally:
            self.pod.sim.ok("delay-acks 0")

    def test_11_no_driver_in_the_namespace(self):
        self.panel.do("type namespace /nowhere")
        self.panel.do("click take_photo")
        expected = "no answer from /nowhere/take_photo"
        self.assertTrue(wait_until(lambda: expected in self.panel.text("message"), WAIT), self.panel.text("message"))
        self.assertTrue(wait_until(lambda: "no diagnostics" in self.panel.text("status_link"), WAIT))
        self.panel.do("type namespace " + self.ns)
        self.assertTrue(wait_until(lambda: self.panel.text("status_link").startswith("OK"), WAIT))
        self.assertTrue(self.panel.alive())

    def test_12_rviz_stops_cleanly(self):
        self.assertEqual(self.panel.close(), 0, "rviz did not exit cleanly on SIGINT; log: " + self.panel.log.name)


if __name__ == "__main__":
    rostest.rosrun(PKG, "panel", PanelTest, sys.argv)
