#!/usr/bin/python3
"""Telemetry against the simulated pod: every published topic at its rate, the values equal to
what the simulator sent (checked against the raw frames, decoded here independently of the
driver's C++ decoder), honest stamps, the TF tree, laser range and target, diagnostics."""
import math
import struct
import sys
import time
import unittest

import rospy
import rostest
import tf2_ros
from diagnostic_msgs.msg import DiagnosticArray
from dynamic_reconfigure.client import Client as ReconfigureClient
from geometry_msgs.msg import QuaternionStamped
from sensor_msgs.msg import Imu, JointState, NavSatFix, NavSatStatus, Range
from std_srvs.srv import Trigger

from k40t_driver.msg import CameraStatus, Frame, GimbalStatus, ThermalStats, VisibleStatus
from k40t_driver.srv import SetAngle
from k40t_test_support import ERROR, OK, Diagnostics, Recorder, SimControl, name, service, wait_until

PKG = "k40t_driver"


def frame_id(data):
    """Message id of a raw frame (bytes 7..9, low byte first: section 2.1)."""
    return data[7] | data[8] << 8 | data[9] << 16


def payload(data):
    return bytes(data[10:10 + data[1]])


class Telemetry(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_telemetry")
        cls.sim = SimControl(rospy.get_param("~control"))
        cls.sd_capacity_mb = rospy.get_param("~sd_capacity_mb")
        cls.topics = {
            "joint_states": Recorder(name("joint_states"), JointState),
            "gimbal/attitude": Recorder(name("gimbal/attitude"), QuaternionStamped),
            "gimbal/status": Recorder(name("gimbal/status"), GimbalStatus),
            "camera/status": Recorder(name("camera/status"), CameraStatus),
            "visible/status": Recorder(name("visible/status"), VisibleStatus),
            "thermal/stats": Recorder(name("thermal/stats"), ThermalStats),
        }
        cls.raw_rx = Recorder(name("raw/rx"), Frame)
        cls.diagnostics = Diagnostics()
        cls.tf_buffer = tf2_ros.Buffer()
        cls.tf_listener = tf2_ros.TransformListener(cls.tf_buffer)
        # The driver is up once attitude reports flow.
        assert cls.topics["joint_states"].wait_for(5, timeout=20.0), "no joint_states from the driver"

    def test_every_report_topic_at_the_documents_rate(self):
        expected = {  # docs/protocol/decisions.md#periodic-reports
            "joint_states": 10.0, "gimbal/attitude": 10.0, "gimbal/status": 2.0,
            "camera/status": 1.0, "visible/status": 5.0, "thermal/stats": 5.0,
        }
        window = 4.0
        start = time.time()
        time.sleep(window)
        for topic, rate in expected.items():
            got = len(self.topics[topic].messages(start)) / window
            self.assertGreaterEqual(got, rate * 0.7, "%s at %.2f Hz, expected %.1f" % (topic, got, rate))
            self.assertLessEqual(got, rate * 1.3 + 0.25, "%s at %.2f Hz, expected %.1f" % (topic, got, rate))

    def matching_frame(self, msg_id, stamp):
        for frame in self.raw_rx.messages():
            if frame.stamp == stamp and frame_id(frame.data) == msg_id:
                return frame
        return None

    def with_frames(self, topic, msg_id, n, timeout):
        """(message, payload of the raw frame with the same stamp) for the next n messages of
        `topic` (those whose frame raw/rx holds: its recorder may have missed the oldest)."""
        msgs = self.topics[topic].wait_for(n, timeout=timeout, since=time.time())
        pairs = []
        for msg in msgs:
            frame = self.matching_frame(msg_id, msg.header.stamp)
            if frame is not None:
                pairs.append((msg, payload(frame.data)))
        return pairs

    def test_joint_states_equal_the_attitude_frames(self):
        # Section 3.1.1.2: int16 deg x100, joint yaw, roll, pitch first; REP 103 flips yaw and pitch.
        self.sim.ok("clear")
        pairs = self.with_frames("joint_states", 0x000002, 20, 5.0)
        for js, data in pairs:
            yaw, roll, pitch = struct.unpack_from("<hhh", data)
            self.assertEqual(js.name, ["k40t_yaw_joint", "k40t_roll_joint", "k40t_pitch_joint"])
            self.assertAlmostEqual(js.position[0], -math.radians(yaw / 100.0), places=9)
            self.assertAlmostEqual(js.position[1], math.radians(roll / 100.0), places=9)
            self.assertAlmostEqual(js.position[2], -math.radians(pitch / 100.0), places=9)
        self.assertGreaterEqual(len(pairs), 10, "joint_states without a raw attitude frame of the same stamp")

    def test_thermal_stats_equal_the_thermal_frames(self):
        # Section 3.2.1.2: int16 x0.1 degC max, min, centre, point, average; uint16 coordinates.
        pairs = self.with_frames("thermal/stats", 0x000004, 10, 5.0)
        for stats, data in pairs:
            tmax, tmin, centre, point, average, max_x, max_y = struct.unpack_from("<hhhhhHH", data)
            self.assertAlmostEqual(stats.max_degC, tmax / 10.0, places=4)
            self.assertAlmostEqual(stats.min_degC, tmin / 10.0, places=4)
            self.assertAlmostEqual(stats.centre_degC, centre / 10.0, places=4)
            self.assertAlmostEqual(stats.point_degC, point / 10.0, places=4)
            self.assertAlmostEqual(stats.average_degC, average / 10.0, places=4)
            self.assertEqual((stats.max_x, stats.max_y), (max_x, max_y))
            self.assertEqual(stats.header.frame_id, "k40t_thermal_optical_frame")
        self.assertGreaterEqual(len(pairs), 5)

    def test_camera_status_carries_the_simulators_sd_card(self):
        status = self.topics["camera/status"].wait_for(1, timeout=3.0)[-1]
        self.assertAlmostEqual(status.sd_total_mb, self.sd_capacity_mb, delta=10.0)  # 10 MB per count
        self.assertEqual(status.sd_state, CameraStatus.SD_OK)
        self.assertAlmostEqual(status.sd_free_mb + status.sd_used_mb, status.sd_total_mb, delta=20.0)

    def test_self_test_failure_reaches_topic_and_diagnostics(self):
        self.sim.ok("self-test 0x0D")  # everything but the telephoto sensor passes
        try:
            status = self.topics["gimbal/status"].wait_for_match(lambda m: not m.tele_ok, timeout=3.0,
                                                                 since=time.time())
            self.assertIsNotNone(status, "gimbal/status never showed the failed telephoto self-test")
            self.assertTrue(status.thermal_ok and status.wide_ok and status.laser_ok)
            self.assertTrue(self.diagnostics.wait_level("self-test", ERROR, 3.0))
            self.assertIn("tele", self.diagnostics.status("self-test").message)
        finally:
            self.sim.ok("self-test 0x0F")
        self.assertTrue(self.diagnostics.wait_level("self-test", OK, 3.0))

    def test_stamps_are_reception_minus_wire_time(self):
        since = time.time()
        msgs = self.topics["joint_states"].wait_for(10, timeout=3.0, since=since)
        for js in msgs:
            frame = self.matching_frame(0x000002, js.header.stamp)
            if frame is None:
                continue
            # 115200 baud, 10 bits per byte: the stamp is the frame's first byte.
            wire = len(frame.data) * 10.0 / 115200.0
            self.assertGreater(wire, 0.002)
        arrivals = [(t, m.header.stamp.to_sec()) for t, m in self.topics["joint_states"].items[-10:]]
        for arrival, stamp in arrivals:
            self.assertLess(stamp, arrival, "a stamp later than the message's arrival")
            self.assertLess(arrival - stamp, 0.1, "a stamp more than 100 ms before arrival")
        stamps = [s for _, s in arrivals]
        self.assertEqual(stamps, sorted(stamps), "stamps go backwards")

    def test_tf_tree_is_complete(self):
        frames = ["k40t_yaw_link", "k40t_roll_link", "k40t_pitch_link", "k40t_tele_optical_frame",
                  "k40t_wide_optical_frame", "k40t_thermal_optical_frame", "k40t_laser_frame"]
        for child in frames:
            ok = wait_until(lambda: self.tf_buffer.can_transform("k40t_base_link", child, rospy.Time(0)), 5.0)
            self.assertTrue(ok, "no TF from k40t_base_link to %s" % child)
        # The chain follows the pod: the pitch link's x axis matches joint_states' pitch.
        js = self.topics["joint_states"].latest()
        t = self.tf_buffer.lookup_transform("k40t_roll_link", "k40t_pitch_link", rospy.Time(0))
        q = t.transform.rotation
        pitch = 2.0 * math.atan2(q.y, q.w)
        self.assertAlmostEqual(pitch, js.position[2], delta=0.05)

    def test_periodic_laser_range(self):
        ranges = Recorder(name("laser/range"), Range)
        client = ReconfigureClient(name("driver"), timeout=10.0)
        client.update_configuration({"periodic_ranging": True})
        try:
            got = ranges.wait_for(3, timeout=6.0)
            self.assertGreaterEqual(len(got), 3, "no periodic laser/range after periodic_ranging:=true")
            for r in got:
                self.assertEqual(r.header.frame_id, "k40t_laser_frame")
                self.assertEqual(r.radiation_type, Range.INFRARED)
                self.assertTrue(math.isinf(r.range) or r.range > 0)
        finally:
            client.update_configuration({"periodic_ranging": False})
            ranges.close()

    def test_laser_target_from_fix_and_attitude(self):
        targets = Recorder(name("laser/target"), NavSatFix)
        fix_pub = rospy.Publisher(name("fix"), NavSatFix, queue_size=1, latch=True)
        imu_pub = rospy.Publisher(name("attitude"), Imu, queue_size=1, latch=True)
        fix = NavSatFix()
        fix.header.stamp = rospy.Time.now()
        fix.status.status = NavSatStatus.STATUS_FIX
        fix.latitude, fix.longitude, fix.altitude = 47.3977, 8.5456, 500.0
        imu = Imu()
        imu.orientation.w = 1.0
        fix_pub.publish(fix)
        imu_pub.publish(imu)
        # Looking at the horizon the laser has no return: the pod answers with no position.
        self.assertTrue(service("gimbal/center", Trigger)().success)
        none = targets.wait_for_match(lambda m: m.status.status == NavSatStatus.STATUS_NO_FIX, 8.0)
        self.assertIsNotNone(none, "no laser/target answer while looking at the horizon")
        # Looking down at the ground 30 m below, the target is a few tens of metres away.
        self.assertTrue(service("gimbal/set_angle", SetAngle)(pitch=0.8, yaw=0.0).success)
        joints = self.topics["joint_states"]
        self.assertTrue(wait_until(lambda: abs(joints.latest().position[2] - 0.8) < 0.01, 10.0), "gimbal not down")
        arrived = time.time() + 0.1  # a request sent once the gimbal is there
        target = targets.wait_for_match(lambda m: m.status.status == NavSatStatus.STATUS_FIX, 15.0, since=arrived + 1.0)
        self.assertIsNotNone(target, "no laser/target with a position after looking down")
        self.assertEqual(target.header.frame_id, "k40t_laser_frame")
        # 30 m below at 0.8 rad down: about 29 m away horizontally (0.0004 deg at this latitude).
        self.assertAlmostEqual(target.latitude, fix.latitude, delta=0.0006)
        self.assertAlmostEqual(target.longitude, fix.longitude, delta=0.0006)
        self.assertLess(target.altitude, fix.altitude)  # the ground is below the pod
        self.assertTrue(service("gimbal/center", Trigger)().success)
        targets.close()

    def test_diagnostics_show_a_healthy_link_and_every_report(self):
        self.assertTrue(self.diagnostics.wait_level("link", OK, 5.0), "link not OK")
        for report in ["gimbal status report (0x000001)", "gimbal attitude report (0x000002)",
                       "camera status report (0x000003)", "thermal report (0x000004)",
                       "visible report (0x000005)"]:
            self.assertTrue(self.diagnostics.wait_level(report, OK, 5.0), "%s not OK" % report)
        hardware_id = self.diagnostics.status("link").hardware_id
        self.assertTrue(wait_until(lambda: "gimbal hw" in self.diagnostics.status("link").hardware_id, 5.0),
                        "hardware id without versions: %s" % hardware_id)
        self.assertEqual(self.diagnostics.value("link", "checksum errors"), "0")

    def test_diagnostic_aggregator_groups_the_driver(self):
        # config/diagnostics.yaml, loaded into diagnostic_aggregator by telemetry.test.
        aggregated = Recorder("/diagnostics_agg", DiagnosticArray)

        def groups():
            latest = aggregated.latest()
            return {s.name: s for s in latest.status} if latest else {}

        expected = ["/K40T pod/Link", "/K40T pod/Periodic reports", "/K40T pod/Sensors"]
        self.assertTrue(wait_until(lambda: all(g in groups() and groups()[g].level == OK for g in expected), 10.0),
                        "aggregated groups: %s" % {n: s.level for n, s in groups().items()})
        aggregated.close()


if __name__ == "__main__":
    rostest.rosrun(PKG, "telemetry", Telemetry, sys.argv)
