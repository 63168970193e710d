#!/usr/bin/python3
"""The SKYPORT bridge end to end: what skyport_sim (the DJI adapter) sends arrives as ROS topics
with the right values and units, the payload-state exchanges and scripted checks pass, and
transparent data and get-position work; replies are checked on the adapter's side (return code +
data). Camera and gimbal: test_skyport_camera_gimbal.py; faults and power-off:
test_skyport_faults.py."""
import glob
import math
import os
import sys
import time

import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticStatus
from std_msgs.msg import UInt8MultiArray

from k40t_driver.srv import GetPosition
from k40t_test_support import name, service, wait_until
from skyport_test_support import CIRCLE_DEG, HOME_LAT, HOME_LON, HOME_MSL, HOME_UNDULATION, START_UTC, SkyportCase


PKG = "k40t_driver"


GOLDEN_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "psdk_golden")


def golden_keys():
    """(set, id, packet type) of every hand-written frame in test/data/psdk_golden: bytes 6, 7 and
    bit 5 of byte 3 of each frame's first hex line (its README)."""
    keys = set()
    for path in glob.glob(os.path.join(GOLDEN_DIR, "*.txt")):
        in_frame = False
        with open(path) as text:
            for line in text:
                line = line.strip()
                if not line or line.startswith("#"):
                    continue
                if line.startswith("="):
                    in_frame = False
                    continue
                if not in_frame:
                    in_frame = True
                    b = [int(x, 16) for x in line.split()[:8]]
                    keys.add((b[6], b[7], b[3] >> 5 & 1))
    return keys


class Skyport(SkyportCase):
    # --- payload state ---------------------------------------------------------------------------

    def test_bridge_learns_the_pods_state(self):
        self.assertTrue(self.pod_known, "the bridge never answered GetCameraWorkMode with 0x00")

    def test_every_handled_command_has_a_golden_frame(self):
        # The nodelet's whole dispatch table (bridge, pushes, transparent data), as it registered it;
        # ACKed commands need their ACK's frame too, pushes without ACK only theirs.
        handled = rospy.get_param(name("skyport/handled_commands"))
        self.assertGreater(len(handled), 50, handled)
        golden = golden_keys()
        no_ack = {(0x02, 0x01), (0x06, 0x01)} | {(0x03, i) for i in range(0x01, 0x0D) if i != 0x03}
        missing = []
        for text in handled:
            cmd_set, cmd_id = (int(x, 16) for x in text.split("/"))
            if (cmd_set, cmd_id, 0) not in golden:
                missing.append(text)
            if (cmd_set, cmd_id) not in no_ack and (cmd_set, cmd_id, 1) not in golden:
                missing.append(text + " ACK")
        self.assertEqual(missing, [], "handled without a golden frame in test/data/psdk_golden")

    def test_identity_verification_passes(self):
        self.assertTrue(self.identity, "the bridge never answered identity verification")
        self.assertTrue(self.identity.startswith("ok passed"), self.identity)
        self.assertNotIn("identity_passed=0", self.skyport.ok("status"))

    def test_payload_state_exchanges(self):
        steps = self.check("payload")
        # DJI's code sends the app name as the product name (docs/psdk.md P32).
        self.assertTrue(any("'k40t_test'" in s for s in steps), steps)

    def test_check_camera_every_step_passes(self):
        # Photo, photo state until stored, video, record start/stop, focal length until the lens
        # arrives, continuous zoom, focus, metering.
        steps = self.check("camera")
        self.assertTrue(any(s.startswith("PASS photo_stored") for s in steps), steps)
        self.assertTrue(any("focal length reads back" in s for s in steps), steps)

    def test_check_gimbal_every_step_passes(self):
        steps = self.check("gimbal")
        self.assertTrue(any(s.startswith("PASS gimbal_reaches_angle") for s in steps), steps)

    def test_check_unsupported_every_step_passes(self):
        self.check("unsupported")

    def test_unknown_command_is_unsupported(self):
        code, data = self.command("unknown")
        self.assertEqual(code, 0x02)
        self.assertEqual(data, b"")

    # --- pushes ----------------------------------------------------------------------------------

    def test_gps_pushes_in_degrees_and_metres(self):
        fix = self.raw_gps.wait_for(1, 15.0)
        self.assertTrue(fix, "no skyport/raw_gps")
        fix = fix[-1]
        self.assertAlmostEqual(fix.latitude, HOME_LAT, delta=CIRCLE_DEG)
        self.assertAlmostEqual(fix.longitude, HOME_LON, delta=CIRCLE_DEG * 1.1)
        # Above the ellipsoid (docs/geo.md): home 40 m above sea level + the undulation + climb.
        self.assertGreater(fix.altitude, HOME_MSL + HOME_UNDULATION - 1)
        self.assertLess(fix.altitude, HOME_MSL + HOME_UNDULATION + 31)
        self.assertEqual(fix.status.status, fix.status.STATUS_FIX)
        fused = self.gps.wait_for(1, 15.0)
        self.assertTrue(fused, "no skyport/gps")
        self.assertAlmostEqual(fused[-1].latitude, HOME_LAT, delta=CIRCLE_DEG)  # radians -> degrees
        self.assertTrue(math.isnan(fused[-1].altitude))
        rtk = self.rtk.wait_for(1, 15.0)
        self.assertTrue(rtk, "no skyport/rtk")
        self.assertAlmostEqual(rtk[-1].longitude, HOME_LON, delta=CIRCLE_DEG * 1.1)

    def test_velocity_in_metres_per_second(self):
        # The circle is flown at 5 m/s, the climb is slower: cm/s would be a hundred times more.
        twists = self.velocity.wait_for(5, 15.0)
        self.assertTrue(twists, "no skyport/raw_gps/velocity")
        for t in twists:
            speed = math.sqrt(t.twist.linear.x ** 2 + t.twist.linear.y ** 2 + t.twist.linear.z ** 2)
            self.assertLess(speed, 6.0)

    def test_attitude_is_a_unit_quaternion_in_enu(self):
        imu = self.imu.wait_for(10, 15.0)
        self.assertTrue(imu, "no skyport/imu")
        q = imu[-1].orientation
        self.assertAlmostEqual(q.x ** 2 + q.y ** 2 + q.z ** 2 + q.w ** 2, 1.0, places=3)
        self.assertEqual(imu[-1].angular_velocity_covariance[0], -1)
        self.assertTrue(self.attitude.wait_for(1, 5.0), "no skyport/attitude")

    def test_slow_pushes(self):
        battery = self.battery.wait_for(1, 15.0)
        self.assertTrue(battery, "no skyport/battery")
        self.assertGreater(battery[-1].percentage, 0.5)  # a fraction, not percent
        self.assertLessEqual(battery[-1].percentage, 1.0)
        uav = self.uav.wait_for(1, 15.0)
        self.assertTrue(uav, "no skyport/uav_state")
        self.assertEqual(uav[-1].drone_type, 8)  # M210 RTK V2
        self.assertTrue(self.link.wait_for(1, 15.0), "no skyport/link_bandwidth")
        baro = self.baro.wait_for(1, 15.0)
        self.assertTrue(baro, "no skyport/barometric_altitude")
        self.assertLess(abs(baro[-1].altitude_m), 100.0)
        utc = self.utc.wait_for(1, 15.0)
        self.assertTrue(utc, "no skyport/utc_time")
        self.assertGreaterEqual(utc[-1].time_ref.secs, START_UTC)
        self.assertLess(utc[-1].time_ref.secs, START_UTC + 3600)

    def test_pod_is_fed_the_aircraft_position(self):
        fix = self.fix.wait_for(1, 15.0)
        self.assertTrue(fix, "the bridge does not publish the driver's fix")
        self.assertAlmostEqual(fix[-1].latitude, HOME_LAT, delta=CIRCLE_DEG)

    def test_diagnostics_ok_when_verified(self):
        self.assertTrue(self.diagnostics.wait_level("SKYPORT link", DiagnosticStatus.OK, 20.0),
                        "SKYPORT link diagnostics never OK: %s" % self.diagnostics.status("SKYPORT link"))

    # --- transparent data and positioning ---------------------------------------------------------

    def test_transparent_data_from_the_app(self):
        self.skyport.ok("transparent hello pod")
        got = self.from_mobile.wait_for_match(lambda m: bytes(m.data) == b"hello pod", 10.0)
        self.assertTrue(got, "nothing on skyport/transparent/from_mobile")

    def test_transparent_data_to_the_app(self):
        pub = rospy.Publisher(name("skyport/transparent/to_mobile"), UInt8MultiArray, queue_size=1, latch=True)
        self.assertTrue(wait_until(lambda: pub.get_num_connections() > 0, 10.0))
        pub.publish(UInt8MultiArray(data=list(b"x" * 200)))  # two frames: 128 + 72
        count = lambda: int(self.skyport.ok("status").split("transparent_to_mobile_bytes=")[1].split()[0])
        self.assertTrue(wait_until(lambda: count() >= 200, 10.0), self.skyport.ok("status"))

    def test_get_position_service(self):
        proxy = service("skyport/get_position", GetPosition)
        self.assertTrue(self.utc.wait_for(1, 15.0), "no skyport/utc_time")
        # 3.7.1: the instants must lie in the 2 s before the newest UTC push; a fractional base
        # time is honoured (the stamps come back at exactly the instants asked for).
        newest = self.utc.latest().time_ref
        base = newest - rospy.Duration(1.25)
        response = proxy(base_time=base, time_offsets_us=[0, 500000])
        self.assertTrue(response.success, response.message)
        self.assertEqual(len(response.positions), 2)
        self.assertAlmostEqual(response.positions[0].latitude, HOME_LAT, delta=CIRCLE_DEG)
        self.assertEqual(response.positions[0].header.stamp, base)
        self.assertEqual(response.positions[1].header.stamp, base + rospy.Duration(0.5))
        # Outside the window: refused with the reason, nothing asked of the adapter.
        time.sleep(0.3)  # past the rate limit
        late = proxy(base_time=newest - rospy.Duration(5), time_offsets_us=[0])
        self.assertFalse(late.success)
        self.assertIn("2 s", late.message)


if __name__ == "__main__":
    rostest.rosrun(PKG, "skyport", Skyport, sys.argv)
