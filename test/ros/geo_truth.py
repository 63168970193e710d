"""What the geo rostests (test_geo.py, test_geo_split.py, test_geo_odom.py) share: the simulator's
ground truth ('truth' on its control socket), metres between geodetic points, the hot object's
pixel computed from the truth, and a thread that feeds the truth to the driver as its vehicle
inputs (docs/geo.md)."""
import math
import threading
import time

import rospy
from geometry_msgs.msg import TwistStamped
from nav_msgs.msg import Odometry
from sensor_msgs.msg import CameraInfo, Imu, NavSatFix

from k40t_test_support import name, wait_until

A, F = 6378137.0, 1 / 298.257223563
GROUND_HEIGHT = 30.0  # the simulator's default: the ground is 30 m below the pod
HOT_RADIUS = 2.0
# The synthetic 1920x1080 telephoto view the tests without video publish as camera_info.
TELE_K = [1500.0, 0, 960.0, 0, 1500.0, 540.0, 0, 0, 1]


def radii(lat_deg):
    e2 = F * (2 - F)
    s = math.sin(math.radians(lat_deg))
    w = math.sqrt(1 - e2 * s * s)
    return A * (1 - e2) / w ** 3, A / w


def offset_m(a, b):
    """(north, east, up) metres from a to b, each (lat, lon, h): small offsets (< 1 km)."""
    meridian, prime = radii(a[0])
    north = math.radians(b[0] - a[0]) * (meridian + a[2])
    east = math.radians(b[1] - a[1]) * (prime + a[2]) * math.cos(math.radians(a[0]))
    return north, east, b[2] - a[2]


def distance_m(a, b):
    return math.sqrt(sum(c * c for c in offset_m(a, b)))


def fix_point(fix):
    return fix.latitude, fix.longitude, fix.altitude


def parse_truth(reply):
    words = reply.split()
    out = {"unix": float(words[words.index("unix") + 1])}
    for key in ("pod", "hot", "laser"):
        i = words.index(key)
        out[key] = None if words[i + 1] == "none" else tuple(float(w) for w in words[i + 1:i + 5])
    i = words.index("pod_ne")
    out["pod_ne"] = (float(words[i + 1]), float(words[i + 2]))
    i = words.index("velocity_ne")
    out["velocity"] = (float(words[i + 1]), float(words[i + 2]))
    out["heading"] = float(words[words.index("heading") + 1])
    i = words.index("boresight")
    out["boresight"] = (float(words[i + 1]), float(words[i + 2]))  # yaw cw from north, pitch up
    out["range"] = float(words[words.index("range") + 1])
    out["zoom"] = float(words[words.index("zoom") + 1])  # the tele's hybrid zoom
    out["hfov"] = float(words[words.index("hfov") + 1])  # its horizontal field of view, deg
    return out


def pixel_of(truth, point, k):
    """Where `point` (lat, lon, h) appears in a camera looking along the truth's boresight (every
    camera of the simulated pod does; the image's x axis is horizontal) with intrinsics k (the
    camera_info's K, no distortion): the simulator's own pinhole (src/sim/video/pinhole_view.cpp),
    from the truth alone."""
    d = offset_m(truth["pod"][0:3], point[0:3])  # north, east, up
    yaw, pitch = (math.radians(a) for a in truth["boresight"])
    forward = (math.cos(pitch) * math.cos(yaw), math.cos(pitch) * math.sin(yaw), math.sin(pitch))
    right = (-math.sin(yaw), math.cos(yaw), 0.0)
    up = (forward[1] * right[2] - forward[2] * right[1], forward[2] * right[0] -
          forward[0] * right[2], forward[0] * right[1] - forward[1] * right[0])
    dot = lambda a, b: sum(x * y for x, y in zip(a, b))
    depth = dot(d, forward)
    assert depth > 0, "the point is behind the camera"
    return k[2] + k[0] * dot(d, right) / depth, k[5] - k[4] * dot(d, up) / depth


def quaternion_enu(heading_deg, pitch_deg=0.0, roll_deg=0.0):
    """(x, y, z, w) of a body (x forward, y left, z up) in ENU: heading clockwise from north,
    nose-up pitch, right-wing-down roll (yaw = 90 deg - heading, pitch about y negated)."""
    y, p, r = math.radians(90.0 - heading_deg) / 2, math.radians(-pitch_deg) / 2, \
        math.radians(roll_deg) / 2
    cy, sy, cp, sp, cr, sr = math.cos(y), math.sin(y), math.cos(p), math.sin(p), math.cos(r), \
        math.sin(r)
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy, cr * cp * cy + sr * sp * sy)


def rotate_inverse(q, v):
    """v (in the parent frame) in the frame of the quaternion q = (x, y, z, w): R(q)^T v."""
    x, y, z, w = q
    x, y, z = -x, -y, -z  # the conjugate
    # v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z)
    c1 = (y * v[2] - z * v[1], z * v[0] - x * v[2], x * v[1] - y * v[0])
    c2 = (y * c1[2] - z * c1[1], z * c1[0] - x * c1[2], x * c1[1] - y * c1[0])
    return tuple(v[i] + 2 * w * c1[i] + 2 * c2[i] for i in range(3))


class Aiming:
    """Gimbal aiming for a unittest.TestCase with self.feeder (TruthFeeder), self.control
    (SimControl), self.set_angle (gimbal/set_angle) and self.joints (a joint_states Recorder)."""

    def aim_at_hot_object(self, lead=0.3):
        """Points the boresight at the hot object's centre from where the pod will be in `lead`
        seconds; returns the commanded (pitch, yaw), REP 103 radians."""
        truth = self.feeder.latest
        pod = list(truth["pod"][0:3])
        vn, ve = truth["velocity"]
        meridian, prime = radii(pod[0])
        pod[0] += math.degrees(vn * lead / meridian)
        pod[1] += math.degrees(ve * lead / (prime * math.cos(math.radians(pod[0]))))
        n, e, u = offset_m(pod, truth["hot"][0:3])
        bearing = math.degrees(math.atan2(e, n)) - truth["heading"]  # joint yaw, right positive
        down = math.atan2(-u, math.hypot(n, e))
        yaw = -math.radians((bearing + 180.0) % 360.0 - 180.0)
        res = self.set_angle(pitch=down, yaw=yaw)
        self.assertTrue(res.success, res.message)
        return down, yaw

    def on_target(self, pitch, yaw, tolerance=math.radians(0.1)):
        js = self.joints.latest()
        if js is None:
            return False
        joint = dict(zip(js.name, js.position))
        return (abs(joint["k40t_pitch_joint"] - pitch) < tolerance and
                abs(joint["k40t_yaw_joint"] - yaw) < tolerance)

    def place_and_aim(self, slant):
        """Puts the hot object at about `slant` ahead and aims the boresight at it."""
        # The object straight ahead of the vehicle's track (so its bearing holds while flying),
        # at about `slant` when the laser measures: the gimbal first turns to the track, then
        # the object is placed ahead by what the vehicle flies while the gimbal settles (~1.5 s).
        truth = self.feeder.latest
        vn, ve = truth["velocity"]
        speed = math.hypot(vn, ve)
        dn, de = (vn / speed, ve / speed) if speed > 0 else (1.0, 0.0)
        down = math.atan2(GROUND_HEIGHT, slant)
        track = -math.atan2(de, dn)  # REP 103 yaw of the track (heading 0: the vehicle faces north)
        self.set_angle(pitch=down, yaw=track)
        wait_until(lambda: self.on_target(down, track, math.radians(0.5)), 10.0)
        truth = self.feeder.latest
        pod_n, pod_e = truth["pod_ne"]
        horizontal = math.sqrt(slant * slant - (GROUND_HEIGHT - HOT_RADIUS) ** 2)
        ahead = horizontal + speed * 1.5
        self.control.ok("hot-object %.3f %.3f" % (pod_n + dn * ahead, pod_e + de * ahead))
        time.sleep(0.3)
        # The gimbal turns at 20 deg/s: aim again (ahead of the flight) until it is there.
        deadline = time.time() + 15.0
        while time.time() < deadline:
            pitch, yaw = self.aim_at_hot_object()
            time.sleep(0.3)
            if self.on_target(pitch, yaw):
                break

    def aim_off(self, yaw_left_deg, pitch_up_deg):
        """Turns the gimbal from where it is by these angles and waits until it is there."""
        js = self.joints.latest()
        joint = dict(zip(js.name, js.position))
        pitch = joint["k40t_pitch_joint"] - math.radians(pitch_up_deg)
        yaw = joint["k40t_yaw_joint"] + math.radians(yaw_left_deg)
        res = self.set_angle(pitch=pitch, yaw=yaw)
        self.assertTrue(res.success, res.message)
        self.assertTrue(wait_until(lambda: self.on_target(pitch, yaw, math.radians(0.05)), 10.0),
                        "the gimbal did not settle off the object")
        time.sleep(0.3)


class TruthFeeder(threading.Thread):
    """Publishes the simulator's true state as the driver's fix, attitude and velocity, 20 Hz,
    stamped at the truth's time. camera_info: also a synthetic telephoto camera_info (TELE_K)
    stamped the same (hold_camera_info pauses it, so a test can publish its own). odometry: a
    function truth -> nav_msgs/Odometry published on velocity_odom instead of velocity."""

    def __init__(self, control, camera_info=True, odometry=None):
        super().__init__(daemon=True)
        self.control = control
        self.fix = rospy.Publisher(name("fix"), NavSatFix, queue_size=10)
        self.attitude = rospy.Publisher(name("attitude"), Imu, queue_size=10)
        self.odometry = odometry
        if odometry:
            self.velocity = rospy.Publisher(name("velocity_odom"), Odometry, queue_size=10)
        else:
            self.velocity = rospy.Publisher(name("velocity"), TwistStamped, queue_size=10)
        self.camera_info = (rospy.Publisher(name("camera_info"), CameraInfo, queue_size=1)
                            if camera_info else None)
        self.hold_camera_info = False
        self.latest = None
        self.running = True

    def publish_camera_info(self, stamp, k=TELE_K):
        info = CameraInfo()
        info.header.stamp = stamp
        info.header.frame_id = "k40t_tele_optical_frame"
        info.width, info.height = 1920, 1080
        info.K = k
        self.camera_info.publish(info)

    def run(self):
        while self.running and not rospy.is_shutdown():
            truth = parse_truth(self.control.ok("truth"))
            self.latest = truth
            stamp = rospy.Time.from_sec(truth["unix"])
            fix = NavSatFix()
            fix.header.stamp = stamp
            fix.header.frame_id = "base_link"
            fix.status.status = fix.status.STATUS_GBAS_FIX
            fix.latitude, fix.longitude, fix.altitude = truth["pod"][0:3]
            fix.position_covariance = [0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.04]
            fix.position_covariance_type = NavSatFix.COVARIANCE_TYPE_DIAGONAL_KNOWN
            self.fix.publish(fix)
            imu = Imu()
            imu.header = fix.header
            yaw = math.radians(90.0 - truth["heading"])  # ENU, level vehicle
            imu.orientation.z, imu.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
            self.attitude.publish(imu)
            if self.odometry:
                odom = self.odometry(truth)
                odom.header.stamp = stamp
                self.velocity.publish(odom)
            else:
                twist = TwistStamped()
                twist.header = fix.header
                twist.twist.linear.y, twist.twist.linear.x = truth["velocity"]  # north, east
                self.velocity.publish(twist)
            if self.camera_info and not self.hold_camera_info:
                self.publish_camera_info(stamp)
            time.sleep(0.05)
