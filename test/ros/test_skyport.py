#!/usr/bin/python3
"""The SKYPORT bridge end to end: what skyport_sim (the DJI adapter) sends arrives as ROS topics
with the right values and units, and its camera and gimbal commands act on k40t_sim (the pod)
through the driver; replies are checked on the adapter's side (return code + data) and the pod's
state through k40t_sim's control socket."""
import glob
import math
import os
import struct
import sys
import time
import unittest
import xmlrpc.client

import rosgraph
import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticStatus
from geometry_msgs.msg import QuaternionStamped, TwistStamped
from sensor_msgs.msg import BatteryState, Imu, NavSatFix, TimeReference
from std_msgs.msg import Bool, UInt8MultiArray

from k40t_driver.msg import BarometricAltitude, CameraStatus, LinkBandwidth, UavState
from k40t_driver.srv import GetPosition
from k40t_test_support import Diagnostics, Recorder, SimControl, name, service, wait_until

PKG = "k40t_driver"

# skyport_sim's flight (psdk/sim/flight_model.h): a 50 m circle around DJI's HQ, 30 m up.
HOME_LAT, HOME_LON, HOME_MSL = 22.5790, 113.9434, 40.0
HOME_UNDULATION = -3.47  # EGM96 geoid height at home: NavSatFix heights are HOME_MSL + this
CIRCLE_DEG = 60.0 / 111000.0  # a little more than the radius, in degrees of latitude
START_UTC = 1719792000  # 2024-07-01 00:00:00, the simulated clock's start


def ack(reply):
    """(code, data bytes) of an 'ok code=0xNN data=..' reply of skyport_sim."""
    if not reply.startswith("ok code="):
        raise AssertionError("no ACK: %s" % reply)
    code = int(reply.split()[1][len("code="):], 16)
    data = reply.split("data=", 1)[1].split()
    return code, bytes(int(b, 16) for b in data)


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


def manager_rss_kb():
    """Resident memory of the nodelet manager that runs the bridge (its pid from its XML-RPC API)."""
    uri = rosgraph.Master("/test_skyport").lookupNode(name("manager"))
    _, _, pid = xmlrpc.client.ServerProxy(uri).getPid("/test_skyport")
    with open("/proc/%d/status" % pid) as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise AssertionError("no VmRSS for pid %d" % pid)


def wrap_deg(deg):
    """An angle in degrees brought into [-180, 180)."""
    return (deg + 180.0) % 360.0 - 180.0


def pod_status_number(status, key):
    """A number after `key` in k40t_sim's status line ('... yaw 12.3 pitch -4 zoom 2x ...')."""
    words = status.replace("|", " ").split()
    for i, w in enumerate(words[:-1]):
        if w == key:
            return float(words[i + 1].rstrip("x"))
    return None


class Skyport(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_skyport")
        cls.pod = SimControl(rospy.get_param("~pod_control"))
        cls.skyport = SimControl(rospy.get_param("~skyport_control"))
        cls.raw_gps = Recorder(name("skyport/raw_gps"), NavSatFix)
        cls.gps = Recorder(name("skyport/gps"), NavSatFix)
        cls.rtk = Recorder(name("skyport/rtk"), NavSatFix)
        cls.velocity = Recorder(name("skyport/raw_gps/velocity"), TwistStamped)
        cls.imu = Recorder(name("skyport/imu"), Imu)
        cls.attitude = Recorder(name("skyport/attitude"), QuaternionStamped)
        cls.battery = Recorder(name("skyport/battery"), BatteryState)
        cls.power_off = Recorder(name("skyport/power_off_warning"), Bool)
        cls.uav = Recorder(name("skyport/uav_state"), UavState)
        cls.link = Recorder(name("skyport/link_bandwidth"), LinkBandwidth)
        cls.baro = Recorder(name("skyport/barometric_altitude"), BarometricAltitude)
        cls.utc = Recorder(name("skyport/utc_time"), TimeReference)
        cls.fix = Recorder(name("fix"), NavSatFix)
        cls.from_mobile = Recorder(name("skyport/transparent/from_mobile"), UInt8MultiArray)
        cls.camera = Recorder(name("camera/status"), CameraStatus)
        cls.diagnostics = Diagnostics()
        # The bridge is up when it answers identity verification (until then: no ACK).
        cls.identity = wait_until(
            lambda: (lambda r: r if "no ACK" not in r else None)(cls.skyport("identity", 10.0)), 60.0)
        # The bridge answers camera queries from the pod's camera/status (1 Hz); until the first one
        # has reached it, it honestly answers 0x01. Tests start once it knows the pod's state:
        # GetCameraWorkMode (0x04/0x02) answered 0x00.
        def work_mode_answered():
            reply = cls.skyport("send 4 2", 15.0)
            return reply.startswith("ok code=") and ack(reply)[0] == 0x00
        cls.pod_known = wait_until(work_mode_answered, 30.0, step=0.2)

    def command(self, line):
        """Sends a command through skyport_sim; (code, data) of the bridge's ACK."""
        return ack(self.skyport(line, 15.0))

    def command_ok(self, line):
        """Like command(), retried while the pod refuses because it is still busy with an earlier
        test: storing a photo ("taking photo", 0x0203) or calibrating the gimbal (`check gimbal`
        ends with a calibration, "busy", 0x0008), both come back as 0x01; asserts 0x00 in the
        end."""
        replies = []

        def done():
            replies.append(self.command(line))
            return replies[-1][0] == 0x00
        self.assertTrue(wait_until(done, 15.0, step=0.3), "%s: %s" % (line, replies[-1:]))
        return replies[-1]

    def pod_status(self):
        return self.pod.ok("status")

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

    def check(self, what):
        """skyport_sim's scripted `check WHAT` (what DJI Pilot sends, every ACK checked); asserts
        that every step passed and returns the steps."""
        reply = self.skyport("check " + what, 90.0)
        self.assertTrue(reply.startswith("ok "), reply)
        steps = [s.strip() for s in reply.split("|")[1:]]
        report = "\n".join(steps)
        self.assertTrue(steps, "check %s: no steps: %s" % (what, reply))
        failed = [s for s in steps if not s.startswith("PASS ")]
        self.assertEqual(failed, [], "check %s:\n%s" % (what, report))
        self.assertTrue(reply.startswith("ok passed"), "check %s:\n%s" % (what, report))
        return steps

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

    # --- camera ----------------------------------------------------------------------------------

    def test_shoot_photo_is_geotagged_with_the_pushed_position(self):
        self.assertTrue(self.fix.wait_for(1, 15.0), "no fix for the pod yet")
        self.command_ok("work_mode photo")
        before = self.pod.ok("photos")
        count = int(before.split()[1])
        self.command_ok("photo")
        new_photo = lambda: [p for p in self.pod.ok("photos").split("; ")[1:]][count:]
        self.assertTrue(wait_until(new_photo, 10.0), "the pod took no photo: %s" % self.pod.ok("photos"))
        # The geotag is attached when the driver answered the pod's GPS request: wait for it.
        tagged = wait_until(lambda: [p for p in new_photo() if "lat 22.5" in p], 10.0)
        self.assertTrue(tagged, "the photo is not geotagged with the pushed position: %s" % new_photo())
        self.assertIn("lon 113.9", tagged[0])

    def video_mode(self):
        # The pod records in video mode only (DJI Pilot switches the work mode first, too).
        self.command_ok("work_mode video")
        # Read back from the pod's camera status (1 Hz): wait for it to show the change.
        self.assertTrue(wait_until(lambda: self.command("send 4 2") == (0x00, b"\x01"), 10.0),
                        "work mode: %s" % self.skyport("send 4 2"))

    def test_utc_push_over_500_ms_late_is_dropped_without_pps(self):
        # 3.3.10's rule in the default configuration (no pps_topic): skyport_sim sends one UTC push
        # 800 ms after its turn; the bridge drops it (later than the punctual pushes by more than
        # 500 ms), counts it, and uses the following ones again.
        late_key = "UTC pushes dropped (over 500 ms after their edge)"
        self.assertTrue(self.utc.wait_for(3, 15.0), "no skyport/utc_time")
        self.assertTrue(wait_until(lambda: self.diagnostics.value("SKYPORT link", late_key) is not None, 10.0))
        dropped_before = int(self.diagnostics.value("SKYPORT link", late_key))
        since = time.time()
        self.skyport.ok("utc_late 800")
        self.assertTrue(wait_until(lambda: int(self.diagnostics.value("SKYPORT link", late_key)) > dropped_before,
                                   10.0), self.diagnostics.status("SKYPORT link"))
        # Pushes go on: the next punctual ones are published, each UTC second once, none of them
        # the dropped one (its second is missing from the topic).
        self.assertTrue(len(self.utc.wait_for(4, 10.0, since=since)) >= 4)
        # From the push before the command on (1 Hz): the dropped second is the gap.
        seconds = [m.time_ref.secs for m in self.utc.messages(since - 1.5)]
        self.assertEqual(len(seconds), len(set(seconds)), seconds)
        self.assertTrue(any(b - a == 2 for a, b in zip(seconds, seconds[1:])), seconds)

    def test_pod_clock_is_set_from_the_skyport_utc(self):
        # The simulated flight's UTC is 2024-07-01: once the driver set the pod's clock from it, the
        # pod names its photos with that date.
        self.assertTrue(self.utc.wait_for(1, 15.0), "no skyport/utc_time")
        self.command_ok("work_mode photo")

        def photo_of_2024():
            self.command("photo")  # may be refused while the previous one is stored: retried
            photos = self.pod.ok("photos").split("; ")[1:]
            return photos and "_20240701_" in photos[-1]
        self.assertTrue(wait_until(photo_of_2024, 30.0, step=1.0),
                        "the pod's clock was not set from the SKYPORT: %s" % self.pod.ok("photos"))

    def test_record_start_and_stop(self):
        self.video_mode()
        self.command_ok("record start")
        self.assertTrue(wait_until(lambda: "recording yes" in self.pod_status(), 10.0), self.pod_status())
        code, data = self.command("record_state")
        self.assertEqual(code, 0x00)
        self.assertEqual(data[0], 1)
        # A pod event becomes a floating-window message in DJI Pilot.
        self.assertTrue(wait_until(lambda: "recording started" in self.skyport.ok("floating"), 10.0),
                        self.skyport.ok("floating"))
        # record/status goes silent (the pod sends nothing for 5 s): after 2.5 s the recording state
        # is unknown, answered 0x01 rather than "recording" for good; known again once it speaks.
        self.pod.ok("silence 5")
        self.assertTrue(wait_until(lambda: self.command("record_state")[0] == 0x01, 5.0))
        def known_recording():
            code, data = self.command("record_state")
            return code == 0x00 and data[:1] == b"\x01"
        self.assertTrue(wait_until(known_recording, 15.0), self.skyport("record_state"))
        code, _ = self.command("record stop")
        self.assertEqual(code, 0x00)
        self.assertTrue(wait_until(lambda: "recording no" in self.pod_status(), 10.0), self.pod_status())
        code, data = self.command("record_state")
        self.assertEqual(data[0], 0)

    def test_zoom(self):
        code, _ = self.command("focal 4.7")  # optical 1x
        self.assertEqual(code, 0x00)
        code, _ = self.command("zoom 2")  # digital 2x
        self.assertEqual(code, 0x00)
        self.assertTrue(wait_until(lambda: abs(pod_status_number(self.pod_status(), "zoom") - 2.0) < 0.05, 15.0),
                        self.pod_status())
        code, _ = self.command("focal 9.4")  # optical 2x, times digital 2x
        self.assertEqual(code, 0x00)
        self.assertTrue(wait_until(lambda: abs(pod_status_number(self.pod_status(), "zoom") - 4.0) < 0.05, 15.0),
                        self.pod_status())
        code, _ = self.command("zoom 100")  # beyond the pod's 160x hybrid with 2x optical
        self.assertEqual(code, 0x01)

    # --- gimbal ----------------------------------------------------------------------------------

    def pod_heading(self):
        """The aircraft heading k40t_sim uses (degrees from north, clockwise), once it has held for
        0.3 s: the bridge's view of the pod's attitude lags the pod by a fraction of that."""
        heading = pod_status_number(self.pod.ok("truth"), "heading")
        for _ in range(10):
            time.sleep(0.3)
            again = pod_status_number(self.pod.ok("truth"), "heading")
            if again == heading:
                return heading
            heading = again
        return heading

    def test_gimbal_angle(self):
        # NED (gimbal_angle_layout dji_headers, the default; docs/psdk.md P28): pitch -30 = 30
        # degrees down, yaw +20 = 20 degrees right of north. The bridge aims the pod's joints at
        # 20 minus the heading the pod knows (fed once a second from the circling flight), so the
        # joint yaw k40t_sim reports ends at 20 minus a heading between those read before and after.
        before = self.pod_heading()
        self.command_ok("gimbal -30 0 20")
        after = pod_status_number(self.pod.ok("truth"), "heading")
        turned = wrap_deg(after - before)  # the flight turns clockwise: >= 0

        def joints_there():
            status = self.pod_status()
            offset = wrap_deg(20 - pod_status_number(status, "yaw") - before)
            return (abs(pod_status_number(status, "pitch") + 30) < 1.0 and
                    -1.0 < offset < turned + 1.0)
        self.assertTrue(wait_until(joints_there, 20.0),
                        "%s (heading %.1f..%.1f)" % (self.pod_status(), before, after))

        # The state reads the NED attitude: the joint yaw plus the heading the pod knows now.
        def state_reached():
            code, data = self.command("gimbal_state")
            if code != 0:
                return False
            pitch, roll, yaw = struct.unpack("<hhh", data[2:8])
            status = self.pod_status()
            ned_yaw = pod_status_number(status, "yaw") + pod_status_number(self.pod.ok("truth"), "heading")
            return abs(pitch / 10.0 + 30) < 1.5 and abs(wrap_deg(yaw / 10.0 - ned_yaw)) < 1.5
        self.assertTrue(wait_until(state_reached, 10.0), "gimbal state: %s" % self.skyport("gimbal_state"))
        code, _ = self.command("gimbal 0 10 0")  # the pod takes no roll command
        self.assertEqual(code, 0x01)

    # --- DJI Pilot widgets -------------------------------------------------------------------------

    def test_widgets(self):
        self.assertEqual(self.command("send 2 4"), (0x00, b"\x04"))  # palette, image mode, laser, record
        code, data = self.command("send 2 5 01")
        self.assertEqual(code, 0x00)
        self.assertEqual(data[0], 4)  # choose list
        self.assertIn(b"Image mode", data)
        # Image mode "Split" (item 2) -> the pod's image mode 7, seen in camera/status.
        self.assertEqual(self.command("send 2 8 04 01 02 00 00 00"), (0x00, b""))
        self.assertTrue(self.camera.wait_for_match(lambda m: m.image_mode == 7, 10.0),
                        "the pod's image mode did not change")
        # Laser ranging button -> one ranging, its result in DJI Pilot's floating window.
        self.assertEqual(self.command("send 2 8 01 02 01 00 00 00"), (0x00, b""))
        self.assertTrue(wait_until(lambda: "laser range" in self.skyport.ok("floating"), 10.0),
                        self.skyport.ok("floating"))
        # Palette "Iron red" (item 4), read back in the group's values.
        self.assertEqual(self.command("send 2 8 04 00 04 00 00 00"), (0x00, b""))
        code, data = self.command("send 2 7 00")
        self.assertEqual(code, 0x00)
        self.assertEqual(data[0], 4)  # four values
        self.assertEqual(struct.unpack("<BBi", data[1:7]), (4, 0, 4))
        self.assertEqual(struct.unpack("<BBi", data[7:13]), (4, 1, 2))

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

    def test_y_diagnostics_error_while_the_adapter_is_silent(self):
        self.assertTrue(self.diagnostics.wait_level("SKYPORT link", DiagnosticStatus.OK, 20.0))
        since = time.time()
        self.skyport.ok("silence 3")

        def silent_error():
            with self.diagnostics.lock:
                return [m for t, n, lv, m in self.diagnostics.history
                        if t >= since and n.endswith(": SKYPORT link") and lv == DiagnosticStatus.ERROR]
        errors = wait_until(silent_error, 10.0)
        self.assertTrue(errors, "no ERROR while the adapter was silent: %s" % self.diagnostics.status("SKYPORT link"))
        self.assertIn("silent", errors[0])
        self.assertTrue(self.diagnostics.wait_level("SKYPORT link", DiagnosticStatus.OK, 15.0),
                        "not OK again after the silence")

    def test_yy_unplugged_pod_while_dji_pilot_polls(self):
        # The pod's link is cut (k40t_sim closes it; the driver's status topics stop and its
        # services fail) while the adapter keeps polling: the bridge answers every getter from the
        # last known state at once, diagnostics mark that state stale, and nothing piles up.
        self.assertTrue(self.diagnostics.wait_level("SKYPORT link", DiagnosticStatus.OK, 20.0))
        before, _ = self.command("gimbal_state")
        self.assertEqual(before, 0x00)
        self.pod.ok("disconnect 15")
        self.assertTrue(wait_until(lambda: self.diagnostics.value("SKYPORT link", "pod state stale") == "True",
                                   10.0), self.diagnostics.status("SKYPORT link"))
        codes = []

        def poll(rounds):
            for _ in range(rounds):
                for getter in ("gimbal_state", "record_state"):
                    codes.append(self.command(getter)[0])
                self.command("gimbal_return")  # a pod call: refused or busy, never waited for
        poll(5)
        rss_before = manager_rss_kb()
        poll(15)  # three times as many: memory must not grow with them (a bounded queue)
        rss_after = manager_rss_kb()
        print("manager resident memory while the pod is unplugged: %d kB after 5 polling rounds, %d kB after 15 more"
              % (rss_before, rss_after))
        self.assertEqual(codes, [0x00] * len(codes))
        self.assertLess(rss_after - rss_before, 2048,
                        "the manager grew from %d to %d kB while the pod was unplugged" % (rss_before, rss_after))
        status = self.diagnostics.status("SKYPORT link")
        self.assertIn("stale", status.message)
        self.assertLessEqual(int(self.diagnostics.value("SKYPORT link", "pod jobs queued")), 8)
        # Plugged in again: the state is fresh, diagnostics OK.
        self.assertTrue(wait_until(lambda: self.diagnostics.value("SKYPORT link", "pod state stale") == "False",
                                   30.0), self.diagnostics.status("SKYPORT link"))

    # --- power-off: last (the announcement stays) -------------------------------------------------

    def test_zz_power_off_stops_recording_then_acks_ready(self):
        self.video_mode()
        self.command_ok("record start")
        self.assertTrue(wait_until(lambda: "recording yes" in self.pod_status(), 10.0), self.pod_status())
        self.skyport.ok("power_off")
        self.assertTrue(self.power_off.wait_for_match(lambda m: m.data, 10.0), "no power-off warning topic")
        self.assertTrue(wait_until(lambda: "power_off_ready=1" in self.skyport.ok("status"), 15.0),
                        self.skyport.ok("status"))
        # "Ready" comes only after the driver's record service had the pod acknowledge the stop (the
        # simulated pod closes the file on its next tick).
        self.assertTrue(wait_until(lambda: "recording no" in self.pod_status(), 5.0), self.pod_status())


if __name__ == "__main__":
    rostest.rosrun(PKG, "skyport", Skyport, sys.argv)
