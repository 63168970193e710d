"""What the rostest nodes of the SKYPORT bridge share (test_skyport*.py): skyport_sim's simulated
flight, its ACK replies, and a test case that waits until the bridge is up and knows the pod's
state, with recorders of every topic the bridge publishes. Imported by the test scripts (which
run from this directory); not a test itself."""
import unittest

import rospy
from geometry_msgs.msg import QuaternionStamped, TwistStamped
from sensor_msgs.msg import BatteryState, Imu, NavSatFix, TimeReference
from std_msgs.msg import Bool, UInt8MultiArray

from k40t_driver.msg import BarometricAltitude, CameraStatus, LinkBandwidth, UavState
from k40t_test_support import Diagnostics, Recorder, SimControl, name, wait_until


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


class SkyportCase(unittest.TestCase):
    """skyport_sim (the DJI adapter, control socket ~skyport_control) and k40t_sim (the pod,
    ~pod_control) around the bridge of launch/skyport.launch."""

    NODE_NAME = "test_skyport"

    @classmethod
    def setUpClass(cls):
        rospy.init_node(cls.NODE_NAME)
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

    def video_mode(self):
        # The pod records in video mode only (DJI Pilot switches the work mode first, too).
        self.command_ok("work_mode video")
        # Read back from the pod's camera status (1 Hz): wait for it to show the change.
        self.assertTrue(wait_until(lambda: self.command("send 4 2") == (0x00, b"\x01"), 10.0),
                        "work mode: %s" % self.skyport("send 4 2"))
