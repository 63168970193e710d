#!/usr/bin/python3
"""Every service against the simulated pod: the success path changes the simulator's state as
seen in telemetry (or in the pod's own answers); invalid arguments give success=false with a
message naming the field and its range and send nothing (raw/tx unchanged); a NACK and a
timeout come back as success=false with the pod's response text."""
import math
import sys
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist, Vector3Stamped
from sensor_msgs.msg import NavSatFix
from std_srvs.srv import Trigger

from k40t_driver.msg import CameraStatus, Frame, GimbalStatus, RecordStatus, ThermalStats, VisibleStatus
from k40t_driver.srv import (Calibrate, Focus, GetIp, GetSbus, GetVersions, MeasureRange, PointAt, Record, Send,
                             SetAiRecognition, SetAngle, SetArea, SetIp, SetPalette, SetPhotoMode, SetSbus, SetSpot,
                             SetZoom, TakePhoto, Track, Zoom)
from dynamic_reconfigure.client import Client as ReconfigureClient
from k40t_test_support import assert_rejected_without_sending, frame_id, name, service, start_driver_test, wait_until

PKG = "k40t_driver"


class Services(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        start_driver_test(cls, "test_services", raw_tx=("raw/tx", Frame), visible=("visible/status", VisibleStatus),
                          camera=("camera/status", CameraStatus), thermal=("thermal/stats", ThermalStats),
                          gimbal=("gimbal/status", GimbalStatus), record_status=("record/status", RecordStatus))
        # The driver reads versions and settings when the pod comes online; let that finish.
        time.sleep(1.0)

    def setUp(self):
        self.sim.ok("clear")

    # --- helpers ---------------------------------------------------------------------------
    def call_ok(self, srv, srv_type, **args):
        response = service(srv, srv_type)(**args)
        self.assertTrue(response.success, "%s(%s) failed: %s" % (srv, args, response.message))
        return response

    def assert_rejected_without_sending(self, srv, srv_type, field, **args):
        assert_rejected_without_sending(self, self.raw_tx, srv, srv_type, field, **args)

    def sent_ids(self, since):
        return [frame_id(f.data) for f in self.raw_tx.messages(since)]

    def assert_sent(self, msg_id, since):
        """raw/tx shows a frame with msg_id after `since` (it arrives just after the service returns)."""
        self.assertTrue(wait_until(lambda: msg_id in self.sent_ids(since), 2.0),
                        "0x%06X not on raw/tx: %s" % (msg_id, ["0x%06X" % i for i in self.sent_ids(since)]))

    def wait_joint(self, index, value, timeout=15.0, tol=0.03):
        return wait_until(lambda: self.joints.latest() and abs(self.joints.latest().position[index] - value) < tol,
                          timeout)

    # --- camera ----------------------------------------------------------------------------
    def test_set_zoom_changes_the_reported_zoom(self):
        self.call_ok("set_zoom", SetZoom, ratio=20.0)
        self.assertTrue(wait_until(lambda: abs(self.visible.latest().zoom_ratio - 20.0) < 0.05, 15.0),
                        "visible/status zoom stays at %.1f" % self.visible.latest().zoom_ratio)
        self.call_ok("set_zoom", SetZoom, ratio=1.0)
        self.assertTrue(wait_until(lambda: abs(self.visible.latest().zoom_ratio - 1.0) < 0.05, 15.0))

    def test_set_zoom_out_of_range(self):
        self.assert_rejected_without_sending("set_zoom", SetZoom, "zoom", ratio=161.0)
        self.assert_rejected_without_sending("set_zoom", SetZoom, "zoom", ratio=0.5)

    def test_zoom_steps_and_continuous(self):
        self.call_ok("set_zoom", SetZoom, ratio=5.0)
        self.assertTrue(wait_until(lambda: abs(self.visible.latest().zoom_ratio - 5.0) < 0.05, 15.0))
        self.call_ok("zoom", Zoom, action=Zoom._request_class.STEP_IN)
        self.assertTrue(wait_until(lambda: self.visible.latest().zoom_ratio > 5.05, 5.0), "step in did not zoom in")
        self.call_ok("zoom", Zoom, action=Zoom._request_class.ZOOM_OUT)
        self.assertTrue(wait_until(lambda: self.visible.latest().zoom_ratio < 4.9, 5.0), "zoom out did not zoom out")
        self.call_ok("zoom", Zoom, action=Zoom._request_class.STOP)
        time.sleep(0.5)
        stopped = self.visible.latest().zoom_ratio
        time.sleep(0.6)
        self.assertAlmostEqual(self.visible.latest().zoom_ratio, stopped, delta=0.05, msg="zoom kept moving after stop")
        self.assert_rejected_without_sending("zoom", Zoom, "command", action=9)

    def test_focus(self):
        since = time.time()
        self.call_ok("focus", Focus, mode=Focus._request_class.ONE_TOUCH, x1=0, y1=0, x2=0, y2=0)
        self.assert_sent(0x000313, since)
        self.assert_rejected_without_sending("focus", Focus, "command", mode=9, x1=0, y1=0, x2=0, y2=0)

    def test_take_photo_is_geotagged_from_fix(self):
        fix_pub = rospy.Publisher(name("fix"), NavSatFix, queue_size=1, latch=True)
        fix = NavSatFix()
        fix.header.stamp = rospy.Time.now()
        fix.latitude, fix.longitude, fix.altitude = 47.5, 8.25, 420.0
        self.assertTrue(wait_until(lambda: fix_pub.get_num_connections() > 0, 5.0), "the driver does not subscribe fix")
        fix_pub.publish(fix)
        time.sleep(0.5)
        self.call_ok("take_photo", TakePhoto, lens=TakePhoto._request_class.LENS_VISIBLE, stop=False,
                     folder="survey", name="tower")
        # The pod files the photo first and attaches the position when the driver has answered its
        # GPS request (section 3.2.4.3), so the listing shows "no gps" for a moment: wait for the tag.
        tower = lambda: [p for p in self.sim.ok("photos").split("; ") if p.startswith("survey/tower.jpg")]
        self.assertTrue(wait_until(tower, 5.0), "the simulator recorded no photo: %s" % self.sim.ok("photos"))
        tagged = wait_until(lambda: [p for p in tower() if "lat 47.5" in p], 5.0)
        self.assertTrue(tagged, "the photo is not geotagged with the fix: %s" % tower())
        self.assertIn("lon 8.25", tagged[0])

    def test_take_photo_rejects_long_names(self):
        self.assert_rejected_without_sending("take_photo", TakePhoto, "folder", lens=0, stop=False, folder="f" * 21, name="")
        self.assert_rejected_without_sending("take_photo", TakePhoto, "name", lens=0, stop=False, folder="", name="n" * 33)
        self.assert_rejected_without_sending("take_photo", TakePhoto, "lens", lens=7, stop=False, folder="", name="")

    def test_take_photo_nack_is_the_pods_text(self):
        self.sim.ok("sd absent")
        try:
            # A photo of an earlier test may still be in progress (0x0203): wait for it.
            proxy = service("take_photo", TakePhoto)
            response = proxy(lens=0, stop=False, folder="", name="")
            deadline = time.time() + 10.0
            while "0x0203" in response.message and time.time() < deadline:
                time.sleep(0.3)
                response = proxy(lens=0, stop=False, folder="", name="")
            self.assertFalse(response.success)
            self.assertIn("SD", response.message, "not the pod's response text: %s" % response.message)
        finally:
            self.sim.ok("sd insert")

    def test_record_start_and_stop(self):
        # Section 3.2.4.1: in photo mode the pod ignores record commands; video mode first.
        reconfigure = ReconfigureClient(name("driver"), timeout=10.0)
        self.assertEqual(reconfigure.update_configuration({"camera_mode": 1})["camera_mode"], 1)
        try:
            self.call_ok("record", Record, start=True, lens=Record._request_class.LENS_STREAM, folder="", name="clip")
            rec = self.record_status.wait_for_match(lambda m: m.state == RecordStatus.STATE_RECORDING, 5.0)
            self.assertIsNotNone(rec, "record/status never showed recording")
            stopping = time.time()  # the "stopped" status may come with the ACK
            self.call_ok("record", Record, start=False, lens=Record._request_class.LENS_STREAM, folder="", name="")
            stopped = self.record_status.wait_for_match(lambda m: m.state == RecordStatus.STATE_STOPPED, 5.0,
                                                        since=stopping)
            self.assertIsNotNone(stopped, "record/status never showed the recording stopped")
        finally:
            reconfigure.update_configuration({"camera_mode": 0})
        self.assert_rejected_without_sending("record", Record, "lens", start=True, lens=9, folder="", name="")

    def test_capture_in_the_other_mode_is_refused_with_the_reason(self):
        # Section 3.2.4.1: in photo mode (the default) the pod does not answer a record request;
        # the service says so at once instead of "no ACK", and sends nothing.
        self.assertTrue(wait_until(lambda: self.camera.latest() is not None, 5.0), "no camera/status")
        self.assertEqual(self.camera.latest().mode, CameraStatus.MODE_PHOTO)
        self.assert_rejected_without_sending("record", Record, "photo mode", start=True,
                                             lens=Record._request_class.LENS_STREAM, folder="", name="")

    def test_set_photo_mode(self):
        self.call_ok("set_photo_mode", SetPhotoMode, mode=SetPhotoMode._request_class.BURST, timelapse_interval_s=5,
                     burst_count=5)
        self.assertTrue(wait_until(lambda: self.camera.latest().photo_mode == 1 and self.camera.latest().burst_count == 5,
                                   4.0), "camera/status does not show burst x5")
        self.call_ok("set_photo_mode", SetPhotoMode, mode=0, timelapse_interval_s=5, burst_count=3)
        self.assert_rejected_without_sending("set_photo_mode", SetPhotoMode, "burst", mode=1, timelapse_interval_s=5,
                                             burst_count=4)

    def test_ai_recognition_and_tracking(self):
        self.call_ok("ai/recognition", SetAiRecognition, enable=True, model=0, classes=[1, 2])
        self.call_ok("ai/track", Track, enable=True, x=800, y=400, width=200, height=100)
        self.call_ok("ai/track", Track, enable=False, x=0, y=0, width=0, height=0)
        self.call_ok("ai/recognition", SetAiRecognition, enable=False, model=0, classes=[])
        self.assert_rejected_without_sending("ai/recognition", SetAiRecognition, "classes", enable=True, model=0,
                                             classes=list(range(11)))
        self.assert_rejected_without_sending("ai/track", Track, "width", enable=True, x=1900, y=0, width=100, height=10)

    # --- gimbal ----------------------------------------------------------------------------
    def test_set_angle_moves_the_joints(self):
        self.call_ok("gimbal/set_angle", SetAngle, pitch=0.5, yaw=0.3)  # REP 103: down and left
        self.assertTrue(self.wait_joint(2, 0.5), "pitch joint at %.3f" % self.joints.latest().position[2])
        self.assertTrue(self.wait_joint(0, 0.3), "yaw joint at %.3f" % self.joints.latest().position[0])
        self.call_ok("gimbal/center", Trigger)
        self.assertTrue(self.wait_joint(2, 0.0) and self.wait_joint(0, 0.0), "center did not center")

    def test_set_angle_out_of_range(self):
        self.assert_rejected_without_sending("gimbal/set_angle", SetAngle, "pitch", pitch=1.7, yaw=0.0)
        self.assert_rejected_without_sending("gimbal/set_angle", SetAngle, "pitch", pitch=-0.6, yaw=0.0)
        self.assert_rejected_without_sending("gimbal/set_angle", SetAngle, "yaw", pitch=0.0, yaw=3.2)

    def test_look_down_then_laser_measures_the_ground(self):
        self.call_ok("gimbal/look_down", Trigger)
        self.assertTrue(self.wait_joint(2, math.pi / 2, tol=0.02), "look_down did not look down")
        time.sleep(0.3)
        response = self.call_ok("laser/measure", MeasureRange)
        self.assertAlmostEqual(response.range, self.ground_height, delta=1.0)
        self.call_ok("gimbal/center", Trigger)
        self.assertTrue(self.wait_joint(2, 0.0))

    def test_point_at(self):
        self.call_ok("gimbal/center", Trigger)
        self.assertTrue(self.wait_joint(0, 0.0))
        self.call_ok("gimbal/point_at", PointAt, lens=PointAt._request_class.LENS_TELE, zoom=5.0, x=1800, y=540)
        # A point right of the centre: the gimbal turns right, which is negative yaw in REP 103.
        self.assertTrue(wait_until(lambda: self.joints.latest().position[0] < -0.05, 10.0), "point_at did not turn right")
        self.call_ok("gimbal/center", Trigger)
        self.assert_rejected_without_sending("gimbal/point_at", PointAt, "x", lens=0, zoom=5.0, x=0, y=540)
        self.assert_rejected_without_sending("gimbal/point_at", PointAt, "zoom", lens=0, zoom=2.0, x=960, y=540)

    def test_calibrations_restart_and_servo_off(self):
        # Each calibration keeps the gimbal busy for a few seconds; the next one (and any motion)
        # is refused with "busy" until it ends: retry until the pod takes it.
        proxy = service("gimbal/calibrate", Calibrate)
        for kind in (0, 1, 2):
            since = time.time()
            deadline = since + 12.0
            response = proxy(kind=kind)
            while not response.success and "busy" in response.message and time.time() < deadline:
                time.sleep(0.5)
                response = proxy(kind=kind)
            self.assertTrue(response.success, "calibration %d: %s" % (kind, response.message))
            self.assert_sent((0x000013, 0x00002E, 0x000031)[kind], since)
        self.assert_rejected_without_sending("gimbal/calibrate", Calibrate, "kind", kind=3)
        # Let the last calibration end, then the servo off and the restart.
        self.assertTrue(wait_until(lambda: service("gimbal/servo_off", Trigger)().success, 12.0, step=0.5))
        self.call_ok("gimbal/restart", Trigger)
        restarted = self.gimbal.wait_for_match(lambda m: not m.gimbal_link_ok, 4.0, since=time.time() - 0.5)
        self.assertIsNotNone(restarted, "gimbal/status never showed the restart")
        self.assertTrue(wait_until(lambda: self.gimbal.latest().gimbal_link_ok, 15.0))
        self.assertTrue(wait_until(lambda: service("gimbal/center", Trigger)().success, 10.0, step=0.5))

    def test_cmd_angle_out_of_range_is_logged_in_the_topics_units(self):
        # The topic is REP 103 radians: the error names those, not the pod's degrees and signs.
        from rosgraph_msgs.msg import Log
        logs = []
        rosout = rospy.Subscriber("/rosout", Log, lambda m: logs.append(m.msg))
        angle_pub = rospy.Publisher(name("gimbal/cmd_angle"), Vector3Stamped, queue_size=1)
        wait_until(lambda: angle_pub.get_num_connections() > 0, 5.0)
        up_too_far = Vector3Stamped()
        up_too_far.vector.y = -1.0  # 57 deg up; the limit is 30 deg up (-0.52 rad)
        logged = lambda: [m for m in logs if "gimbal/cmd_angle not applied" in m]
        for _ in range(20):
            angle_pub.publish(up_too_far)
            if wait_until(logged, 0.25):
                break
        rosout.unregister()
        self.assertTrue(logged(), "no warning logged for an out-of-range cmd_angle")
        self.assertIn("field 'pitch'", logged()[0])
        self.assertIn("rad (positive = down)", logged()[0])

    def test_cmd_angle_and_cmd_rate_dead_man(self):
        angle_pub = rospy.Publisher(name("gimbal/cmd_angle"), Vector3Stamped, queue_size=1)
        rate_pub = rospy.Publisher(name("gimbal/cmd_rate"), Twist, queue_size=1)
        wait_until(lambda: angle_pub.get_num_connections() > 0 and rate_pub.get_num_connections() > 0, 5.0)
        target = Vector3Stamped()
        target.vector.y, target.vector.z = 0.4, -0.2  # down 0.4 rad, right 0.2 rad
        angle_pub.publish(target)
        self.assertTrue(self.wait_joint(2, 0.4) and self.wait_joint(0, -0.2), "cmd_angle not followed")

        twist = Twist()
        twist.angular.z = 0.2  # turn left at 0.2 rad/s
        start_yaw = self.joints.latest().position[0]
        for _ in range(15):  # 1.5 s of commands at 10 Hz
            rate_pub.publish(twist)
            time.sleep(0.1)
        stopped_at = time.time()
        time.sleep(1.5)
        self.assertGreater(self.joints.latest().position[0], start_yaw + 0.1, "cmd_rate did not turn left")
        # The dead-man: no command for 0.5 s stops the gimbal; allow one report period and the ACK.
        moving = [(t, m.position[0]) for t, m in self.joints.items if t >= stopped_at]
        last_move = max((t for (t, y), (_, y_prev) in zip(moving[1:], moving) if abs(y - y_prev) > 1e-4),
                        default=stopped_at)
        self.assertLess(last_move - stopped_at, 0.5 + 0.35, "the gimbal kept turning %.2f s after the last cmd_rate"
                        % (last_move - stopped_at))
        self.call_ok("gimbal/center", Trigger)

    # --- thermal and laser -----------------------------------------------------------------
    def test_set_palette_is_read_back(self):
        self.call_ok("set_palette", SetPalette, palette=7)
        ack = self.call_ok("send", Send, id=0x000100, payload=[1, 0]).ack
        self.assertEqual(ack[2], 7, "0x000100 reports palette %d" % ack[2])  # byte 3 of the ACK
        self.call_ok("set_palette", SetPalette, palette=1)
        self.assert_rejected_without_sending("set_palette", SetPalette, "palette", palette=21)
        self.assert_rejected_without_sending("set_palette", SetPalette, "palette", palette=0)

    def test_thermal_spot_and_area(self):
        self.call_ok("thermal/set_spot", SetSpot, x=800, y=500)
        self.assertTrue(wait_until(lambda: (self.thermal.latest().point_x, self.thermal.latest().point_y) == (800, 500),
                                   3.0), "thermal/stats point stays at %d,%d" % (self.thermal.latest().point_x,
                                                                                 self.thermal.latest().point_y))
        self.call_ok("thermal/set_area", SetArea, width=200, height=100, center_x=700, center_y=400)
        # The centre is reported at the nearest sensor pixel (640x512 spread over 960x992 units).
        self.assertTrue(wait_until(lambda: abs(self.thermal.latest().centre_x - 700) <= 2 and
                                   abs(self.thermal.latest().centre_y - 400) <= 2, 3.0),
                        "thermal/stats area centre at %d,%d" % (self.thermal.latest().centre_x,
                                                                self.thermal.latest().centre_y))
        self.assert_rejected_without_sending("thermal/set_spot", SetSpot, "x", x=1921, y=500)
        self.assert_rejected_without_sending("thermal/set_area", SetArea, "width", width=2000, height=100, center_x=700,
                                             center_y=400)

    # --- system ----------------------------------------------------------------------------
    def test_versions(self):
        response = self.call_ok("get_versions", GetVersions)
        self.assertEqual((response.gimbal_hardware, response.gimbal_software, response.camera),
                         ("1.2.0", "3.4.1", "2.1.7"))

    def test_ip_round_trip(self):
        self.assertEqual(self.call_ok("get_ip", GetIp).address, "192.168.144.64")
        self.call_ok("set_ip", SetIp, dhcp=False, address="192.168.144.70", netmask="255.255.255.0",
                     gateway="192.168.144.1")
        got = self.call_ok("get_ip", GetIp)
        self.assertEqual((got.address, got.netmask, got.gateway), ("192.168.144.70", "255.255.255.0", "192.168.144.1"))
        self.call_ok("set_ip", SetIp, dhcp=False, address="192.168.144.64", netmask="255.255.255.0",
                     gateway="192.168.144.1")
        self.assert_rejected_without_sending("set_ip", SetIp, "address", dhcp=False, address="300.1.1.1",
                                             netmask="255.255.255.0", gateway="")

    def test_sbus_round_trip(self):
        self.call_ok("sbus/set", SetSbus, max_value=1900, min_value=100, stream_channel=8, zoom_channel=9,
                     photo_channel=10, record_channel=11, pitch_channel=12, yaw_channel=13, centre_channel=14)
        got = self.call_ok("sbus/get", GetSbus)
        self.assertEqual((got.max_value, got.min_value), (1900, 100))
        self.assertEqual([got.stream_channel, got.zoom_channel, got.photo_channel, got.record_channel,
                          got.pitch_channel, got.yaw_channel, got.centre_channel], [8, 9, 10, 11, 12, 13, 14])
        self.assert_rejected_without_sending("sbus/set", SetSbus, "min", max_value=100, min_value=1900,
                                             stream_channel=1, zoom_channel=2, photo_channel=3, record_channel=4,
                                             pitch_channel=5, yaw_channel=6, centre_channel=7)
        self.assert_rejected_without_sending("sbus/set", SetSbus, "channel", max_value=1811, min_value=172,
                                             stream_channel=17, zoom_channel=2, photo_channel=3, record_channel=4,
                                             pitch_channel=5, yaw_channel=6, centre_channel=7)

    def test_format_sd_empties_the_card(self):
        self.sim.ok("sd fill")
        self.assertTrue(wait_until(lambda: self.camera.latest().sd_used_mb > 0, 5.0))
        self.call_ok("format_sd", Trigger)
        self.assertTrue(wait_until(lambda: self.camera.latest().sd_used_mb == 0, 10.0), "format_sd left data")

    def test_send_raw_request(self):
        response = self.call_ok("send", Send, id=0x000317, payload=[1, 0])
        self.assertEqual(response.code, 0)
        self.assertEqual(list(response.ack[2:5]), [2, 1, 7])  # camera version 2.1.7 after the code
        self.assert_rejected_without_sending("send", Send, "id", id=0x1000000, payload=[])
        self.assert_rejected_without_sending("send", Send, "payload", id=0x000317, payload=[0] * 244)

    def test_timeout_is_reported_after_retries(self):
        self.sim.ok("drop-acks 1")
        try:
            since = time.time()
            response = service("set_palette", SetPalette)(palette=2)
            self.assertFalse(response.success)
            self.assertIn("timeout", response.message.lower())
            self.assertTrue(wait_until(lambda: self.sent_ids(since).count(0x000106) == 3, 2.0),
                            "expected the request and 2 retries: %d sent" % self.sent_ids(since).count(0x000106))
        finally:
            self.sim.ok("drop-acks 0")

    # Last (unittest runs tests in name order): the camera reboots after these.
    def test_zz_shutdown_then_factory_reset(self):
        since = time.time()
        self.call_ok("shutdown", Trigger)
        self.assertIsNotNone(self.gimbal.wait_for_match(lambda m: not m.camera_link_ok, 5.0, since=since),
                             "gimbal/status never showed the camera going down")
        self.assertIsNotNone(self.gimbal.wait_for_match(lambda m: m.camera_link_ok, 15.0, since=time.time()),
                             "the camera did not come back after shutdown")
        self.call_ok("set_palette", SetPalette, palette=12)
        since = time.time()
        self.call_ok("factory_reset", Trigger)
        self.assertIsNotNone(self.gimbal.wait_for_match(lambda m: not m.camera_link_ok, 5.0, since=since),
                             "gimbal/status never showed the camera restarting")
        self.assertIsNotNone(self.gimbal.wait_for_match(lambda m: m.camera_link_ok, 15.0, since=time.time()))
        ack = self.call_ok("send", Send, id=0x000100, payload=[1, 0]).ack
        self.assertEqual(ack[2], 1, "palette %d after a factory reset" % ack[2])


if __name__ == "__main__":
    Services.ground_height = 30.0
    rostest.rosrun(PKG, "services", Services, sys.argv)
