#!/usr/bin/python3
"""The SKYPORT bridge answers identity verification with the MD5 of its own key; when the
simulated adapter expects another key, the answer does not prove it: verification fails."""
import sys
import unittest

import rospy
import rostest
from sensor_msgs.msg import NavSatFix

from k40t_test_support import Recorder, SimControl, name, wait_until

PKG = "k40t_driver"


class SkyportWrongKey(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_skyport_wrong_key")
        cls.skyport = SimControl(rospy.get_param("~skyport_control"))

    def test_identity_verification_fails_with_another_key(self):
        # The bridge needs a moment to open the link: until then the check gets no ACK.
        reply = wait_until(lambda: (lambda r: r if "no ACK" not in r else None)(self.skyport("identity", 10.0)), 60.0)
        self.assertTrue(reply, "the bridge never answered identity verification")
        self.assertTrue(reply.startswith("ok failed"), reply)
        self.assertIn("does not match", reply)
        status = self.skyport.ok("status")
        self.assertIn("identity_passed=0", status)

    def test_pushes_still_arrive(self):
        # Identity is the adapter's concern; the bridge still publishes what the aircraft pushes.
        fixes = Recorder(name("skyport/raw_gps"), NavSatFix)
        self.assertTrue(fixes.wait_for(1, 30.0), "no skyport/raw_gps")


if __name__ == "__main__":
    rostest.rosrun(PKG, "skyport_wrong_key", SkyportWrongKey, sys.argv)
