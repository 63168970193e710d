#!/usr/bin/env python3
"""velocity_odom end to end (docs/geo.md, "Velocity input"): the driver's fix and attitude come
from k40t_sim's truth (flying east at 15 m/s, level), its velocity only from a nav_msgs/Odometry
whose twist is in the body frame (child_frame_id) and whose pose orientation is pitched and
rolled; the pod's 0x000320 (the laser-target request, every laser_target_period) must carry the
odometry's ground speed and climb rate, which differ from what the fixes alone give (15 m/s,
level), read back through the simulator's control command flight-data."""
import math
import sys
import unittest

import rospy
import rostest
from nav_msgs.msg import Odometry

from geo_truth import TruthFeeder, quaternion_enu, rotate_inverse
from k40t_test_support import SimControl, wait_until

CLIMB = 1.25      # m/s: the fixes show none
EXTRA_NORTH = 4.0  # m/s on top of the truth's: a ground speed the fixes do not show
PITCH, ROLL = 8.0, -5.0  # degrees, the odometry's orientation (not the attitude input's)


def odometry_of(truth):
    """An Odometry with the truth's velocity plus EXTRA_NORTH and CLIMB, in the body frame."""
    vn, ve = truth["velocity"]
    q = quaternion_enu(truth["heading"], PITCH, ROLL)
    body = rotate_inverse(q, (ve, vn + EXTRA_NORTH, CLIMB))
    odom = Odometry()
    odom.header.frame_id = "map"
    odom.child_frame_id = "base_link"
    (odom.pose.pose.orientation.x, odom.pose.pose.orientation.y, odom.pose.pose.orientation.z,
     odom.pose.pose.orientation.w) = q
    odom.twist.twist.linear.x, odom.twist.twist.linear.y, odom.twist.twist.linear.z = body
    return odom


def parse_flight_data(reply):
    words = reply.split()
    return {words[i]: float(words[i + 1]) for i in range(1, len(words) - 1, 2)}


class GeoOdomTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_geo_odom")
        cls.control = SimControl(rospy.get_param("~control"))
        cls.feeder = TruthFeeder(cls.control, camera_info=False, odometry=odometry_of)
        cls.feeder.start()
        assert wait_until(lambda: cls.feeder.latest is not None, 10.0), "no truth from the simulator"

    @classmethod
    def tearDownClass(cls):
        cls.feeder.running = False

    def test_0x000320_carries_the_odometrys_ground_speed_and_climb(self):
        first = parse_flight_data(self.control.ok("flight-data"))
        # Two requests after the odometry flows: the second is made from a full history.
        received = wait_until(
            lambda: (lambda d: d if d["requests"] >= first["requests"] + 2 else None)(
                parse_flight_data(self.control.ok("flight-data"))), 10.0)
        self.assertTrue(received, "the pod received no 0x000320")
        vn, ve = self.feeder.latest["velocity"]
        expected_speed = math.hypot(ve, vn + EXTRA_NORTH)
        print("GEO odometry: 0x000320 ground speed %.2f m/s (odometry %.2f, fixes alone %.2f), "
              "climb %.2f m/s (odometry %.2f)" % (received["ground_speed"], expected_speed,
                                                  math.hypot(ve, vn), received["climb"], CLIMB))
        # The wire carries centimetres per second.
        self.assertAlmostEqual(received["ground_speed"], expected_speed, delta=0.02)
        self.assertAlmostEqual(received["climb"], CLIMB, delta=0.02)


if __name__ == "__main__":
    rostest.rosrun("k40t_driver", "test_geo_odom", GeoOdomTest, sys.argv)
