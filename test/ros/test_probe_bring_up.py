#!/usr/bin/python3
"""Issue 21's "Done when", end to end: a simulated pod that plays the other reading of every open
point of the document (docs/protocol/decisions.md#conventions), `k40t probe --allow-motion
--calibration --out f.yaml` against it, then the driver started with `k40t.launch
conventions:=f.yaml`: joint_states, TF, gimbal/attitude, the SD capacities and the shutter equal
the simulator's truth, and gimbal/calibrate ends within 2 s of the pod's end. docs/bring_up.md
walks through the same steps with a real pod."""
import math
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import actionlib
import rospy
import rostest
import tf2_ros
from dynamic_reconfigure.client import Client as ReconfigureClient
from geometry_msgs.msg import QuaternionStamped
from sensor_msgs.msg import JointState

from k40t_driver.msg import (CameraStatus, Frame, GimbalCalibrateAction, GimbalCalibrateGoal,
                             VisibleStatus)
from k40t_driver.srv import SetAngle
from k40t_test_support import Recorder, SimControl, name, reply_number, service, wait_until

PKG = "k40t_driver"
SD_CAPACITY_MB = 4000  # fits 0.1 MB counts (a uint16 of them holds 6553.5 MB)

# The other reading of every item; the probe cannot learn the last six from traffic, and none of
# them changes what is compared here (the roll is 0, the vehicle level, no photo is taken).
SIM_READINGS = [
    "--crc-coverage", "whole_frame", "--ack-byte-order", "little", "--angle-scale", "10",
    "--gimbal-system-id", "5", "--laser-status-byte-order", "big",
    "--convention", "yaw_sign=left", "--convention", "pitch_sign=down",
    "--convention", "yaw_range=heading", "--convention", "sd_capacity_unit=0.1mb",
    "--convention", "shutter_field=100us", "--convention", "enhancement_switch=bit0",
    "--convention", "thermal_zoom_code=zero_based", "--convention", "calibration_end=ack",
    "--convention", "roll_sign=left_down", "--convention", "attitude_order=zxy",
    "--convention", "photo_mode_2=self_timer", "--convention", "gps_request_time=local",
    "--convention", "gps_answer_byte_order=big", "--convention", "focus_plus=far",
]


def yaw_pitch(q):
    """Yaw and pitch (rad) of a rotation with no roll: R = Rz(yaw) Ry(pitch)."""
    yaw = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
    pitch = math.asin(max(-1.0, min(1.0, 2 * (q.w * q.y - q.z * q.x))))
    return yaw, pitch


class ProbeBringUp(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_probe_bring_up")
        cls.tmp = tempfile.mkdtemp(prefix="k40t_probe_")
        cls.pty = os.path.join(cls.tmp, "pod")
        cls.control = os.path.join(cls.tmp, "control")
        cls.params = os.path.join(cls.tmp, "f.yaml")
        cls.processes = []
        cls.sim = SimControl(cls.control)
        cls.start(["rosrun", PKG, "k40t_sim", "--link", "pty:" + cls.pty, "--control",
                   "unix:" + cls.control, "--sd-capacity-mb", str(SD_CAPACITY_MB)] + SIM_READINGS)
        assert wait_until(lambda: os.path.exists(cls.pty), 10.0), "the simulator made no pty"
        url = "serial://%s?baud=115200" % cls.pty
        # The card's label: the capacity unit is the one reading traffic alone cannot tell.
        cls.probe = subprocess.run(
            ["rosrun", PKG, "k40t", "probe", url, "--listen", "1", "--allow-motion",
             "--calibration", "--sd-card-gb", "4", "--out", cls.params],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True, timeout=60)
        print(cls.probe.stdout, cls.probe.stderr)
        assert cls.probe.returncode == 0, "k40t probe failed: " + cls.probe.stderr
        cls.start(["roslaunch", PKG, "k40t.launch", "device:=" + url, "conventions:=" + cls.params,
                   "respawn:=false"])
        cls.joints = Recorder(name("joint_states"), JointState)
        cls.attitude = Recorder(name("gimbal/attitude"), QuaternionStamped)
        cls.camera = Recorder(name("camera/status"), CameraStatus)
        cls.visible = Recorder(name("visible/status"), VisibleStatus)
        cls.raw = Recorder(name("raw/rx"), Frame)
        cls.tf_buffer = tf2_ros.Buffer()
        cls.tf_listener = tf2_ros.TransformListener(cls.tf_buffer)
        assert cls.joints.wait_for(5, timeout=20.0), "no joint_states from the driver"

    @classmethod
    def start(cls, command):
        cls.processes.append(subprocess.Popen(command, start_new_session=True))

    @classmethod
    def tearDownClass(cls):
        for process in reversed(cls.processes):  # the driver first, then the simulator
            if process.poll() is None:
                os.killpg(process.pid, signal.SIGINT)
                try:
                    process.wait(timeout=10)
                except subprocess.TimeoutExpired:
                    os.killpg(process.pid, signal.SIGKILL)
                    process.wait()
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def truth(self):
        """The simulated gimbal's joints (deg; right and up positive: physical, not a reading)."""
        reply = self.sim.ok("status")
        return reply_number(reply, "yaw"), reply_number(reply, "pitch")

    def test_1_the_probe_learned_the_readings_traffic_shows(self):
        text = open(self.params).read()
        for line in ["yaw_sign: left", "pitch_sign: down", "angle_command_scale: 10",
                     "yaw_range: heading", "sd_capacity_unit: 0.1mb", "shutter_field: 100us",
                     "calibration_end: ack", "crc_coverage: whole_frame", "ack_byte_order: little",
                     "gimbal_system_id: 5"]:
            self.assertIn("\n" + line + "  #", text)
        self.assertIn("# roll_sign: right_down  # not learnable from traffic: default kept", text)

    def test_2_joints_tf_and_attitude_equal_the_truth(self):
        set_angle = service("gimbal/set_angle", SetAngle)
        heading = reply_number(self.sim.ok("truth"), "heading")
        # Left of centre and up: the yaw is a heading above 180 on the wire, both signs flipped.
        for pitch_down, yaw_left in [(-0.2, 0.5), (0.6, -0.8)]:
            res = set_angle(pitch=pitch_down, yaw=yaw_left)
            self.assertTrue(res.success, res.message)
            self.assertTrue(wait_until(lambda: abs(self.truth()[0] + math.degrees(yaw_left)) < 0.1
                                       and abs(self.truth()[1] + math.degrees(pitch_down)) < 0.1, 10.0),
                            "the simulated gimbal did not go where the driver sent it: %s" % (self.truth(),))
            true_yaw, true_pitch = self.truth()
            since = time.time() + 0.3
            js = self.joints.wait_for(1, timeout=3.0, since=since)[-1]
            # REP 103: yaw positive left, pitch positive down.
            self.assertAlmostEqual(js.position[0], -math.radians(true_yaw), delta=0.005)
            self.assertAlmostEqual(js.position[2], -math.radians(true_pitch), delta=0.005)
            rospy.sleep(0.3)  # TF follows joint_states
            t = self.tf_buffer.lookup_transform("k40t_base_link", "k40t_pitch_link", rospy.Time(0))
            tf_yaw, tf_pitch = yaw_pitch(t.transform.rotation)
            self.assertAlmostEqual(tf_yaw, -math.radians(true_yaw), delta=0.01)
            self.assertAlmostEqual(tf_pitch, -math.radians(true_pitch), delta=0.01)
            q = self.attitude.wait_for(1, timeout=3.0, since=since)[-1].quaternion
            att_yaw, att_pitch = yaw_pitch(q)
            expected_yaw = -math.radians(true_yaw + heading)
            self.assertAlmostEqual(math.remainder(att_yaw - expected_yaw, 2 * math.pi), 0, delta=0.01)
            self.assertAlmostEqual(att_pitch, -math.radians(true_pitch), delta=0.01)

    def test_3_sd_capacity_and_shutter_equal_the_truth(self):
        status = self.camera.wait_for(1, timeout=3.0)[-1]
        self.assertAlmostEqual(status.sd_total_mb, SD_CAPACITY_MB, delta=0.2)
        self.assertAlmostEqual(status.sd_free_mb + status.sd_used_mb, SD_CAPACITY_MB, delta=0.5)
        client = ReconfigureClient(name("driver"), timeout=10.0)
        client.update_configuration({"shutter": 1})  # 1/4 s: 250000 us, 2500 counts of 100 us
        since = time.time()
        shown = self.visible.wait_for_match(lambda m: abs(m.shutter_s - 0.25) < 1e-6, timeout=5.0,
                                            since=since)
        self.assertIsNotNone(shown, "visible/status never showed the 1/4 s shutter: %s" %
                             (self.visible.latest(),))

    def test_4_calibration_ends_within_2_s_of_the_pods_end(self):
        # This pod answers a calibration when it is done (calibration_end: ack): its end is that
        # ACK, 0x010013 with code OK (a pod with calibration_end: status would end it with
        # 0x000008 "succeeded", state 0, section 3.2.1.4; test_conventions_calibration.cpp has both).
        client = actionlib.SimpleActionClient(name("gimbal/calibrate"), GimbalCalibrateAction)
        self.assertTrue(client.wait_for_server(rospy.Duration(10)))
        since = time.time()
        client.send_goal(GimbalCalibrateGoal(kind=GimbalCalibrateGoal.DRIFT, timeout=30.0))
        self.assertTrue(client.wait_for_result(rospy.Duration(20)))
        goal_end = time.time()
        result = client.get_result()
        self.assertTrue(result.success, result.message)
        def pod_ends():
            with self.raw.lock:
                heard = [(t, m) for t, m in self.raw.items if t >= since]
            return [t for t, m in heard if frame_id(m.data) in (0x010013, 0x000008) and bytearray(m.data)[10] == 0]
        # The frame may reach raw/rx after the action's result reached this test.
        self.assertTrue(wait_until(lambda: pod_ends(), 3.0), "no OK ACK 0x010013 nor 0x000008 "
                        "'succeeded' on raw/rx (%s)" % result.message)
        ends = pod_ends()
        print("gimbal/calibrate ended %.2f s after the pod's end (%.1f s after the goal)" %
              (goal_end - ends[0], ends[0] - since))
        self.assertLess(abs(goal_end - ends[0]), 2.0, "the goal ended %.1f s after the start, the "
                        "pod's calibration %.1f s" % (goal_end - since, ends[0] - since))

def frame_id(data):
    """Message id of a raw frame (bytes 7..9, low byte first: section 2.1)."""
    data = bytearray(data)
    return data[7] | data[8] << 8 | data[9] << 16

if __name__ == "__main__":
    rostest.rosrun(PKG, "probe_bring_up", ProbeBringUp, sys.argv)
