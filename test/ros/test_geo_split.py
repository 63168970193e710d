#!/usr/bin/env python3
"""locate_pixel in split screen (docs/geo.md, docs/video.md) against k40t_sim's ground truth: the
pod is put into split screen (dynamic_reconfigure image_mode 7) with the thermal digital zoom at 2,
the video node publishes each panel's camera_info (split/visible/camera_info,
split/thermal/camera_info), and the hot object's pixel, computed from the truth and the panel's
camera_info, is located in the thermal (right) panel and in the visible (left) panel, at about
100 m and 500 m slant, within 1 % of the slant range. The thermal pixel is also checked against
the image itself: the hot object is the brightest blob of the white-hot thermal panel."""
import math
import sys
import time
import unittest

import rospy
import rostest
from dynamic_reconfigure.client import Client as ReconfigureClient
from sensor_msgs.msg import CameraInfo, Image, JointState

from geo_truth import Aiming, TruthFeeder, distance_m, fix_point, parse_truth, pixel_of
from k40t_driver.srv import LocatePixel, LocatePixelRequest, SetAngle
from k40t_test_support import Recorder, SimControl, name, service, wait_until

THERMAL_ZOOM = 2
THERMAL_FX_1X = 640 * 13.0 / 7.68  # the nominal thermal lens (config/video.yaml)


def hot_blob_centre(image, roi):
    """Centroid of the brightest pixels (within 40 of the maximum, blue channel of bgr8) inside
    roi: the hot object of a white-hot thermal image."""
    data, step = image.data, image.step
    rows = []
    for y in range(roi.y_offset, roi.y_offset + roi.height):
        start = y * step + roi.x_offset * 3
        rows.append(data[start:start + roi.width * 3:3])
    top = max(max(row) for row in rows)
    sum_u = sum_v = count = 0
    for j, row in enumerate(rows):
        for i, value in enumerate(row):
            if value >= top - 40:
                sum_u += i
                sum_v += j
                count += 1
    return roi.x_offset + sum_u / count, roi.y_offset + sum_v / count, count


class GeoSplitTest(Aiming, unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_geo_split")
        cls.control = SimControl(rospy.get_param("~control"))
        cls.feeder = TruthFeeder(cls.control, camera_info=False)  # the video node's
        cls.feeder.start()
        cls.joints = Recorder(name("joint_states"), JointState, keep=100)
        cls.panels = [Recorder(name("split/visible/camera_info"), CameraInfo),
                      Recorder(name("split/thermal/camera_info"), CameraInfo)]
        cls.set_angle = service("gimbal/set_angle", SetAngle)
        cls.locate = service("locate_pixel", LocatePixel)
        assert wait_until(lambda: cls.feeder.latest is not None, 10.0), "no truth from the simulator"
        ReconfigureClient(name("driver"), timeout=30.0).update_configuration(
            {"image_mode": 7, "thermal_zoom": THERMAL_ZOOM})

    @classmethod
    def tearDownClass(cls):
        cls.feeder.running = False

    def current_panel(self, index, since):
        panel = self.panels[index].wait_for_match(lambda m: True, timeout=20.0, since=since)
        self.assertTrue(panel, "no %s camera_info" % ("visible", "thermal")[index])
        return panel

    def locate_in(self, truth, panel, use_laser=False):
        u, v = pixel_of(truth, truth["hot"], panel.K)
        roi = panel.roi
        self.assertTrue(roi.x_offset <= u < roi.x_offset + roi.width and
                        roi.y_offset <= v < roi.y_offset + roi.height,
                        "the hot object (%.1f, %.1f) is outside the panel" % (u, v))
        res = self.locate(LocatePixelRequest(u=u, v=v, plane_reference=LocatePixelRequest.MSL,
                                             plane_height=truth["hot"][3], use_laser=use_laser))
        self.assertTrue(res.success, res.message)
        return (u, v), res

    def check_at(self, slant):
        self.place_and_aim(slant)
        self.aim_off(2.0, 0.7)  # off the laser axis: the plane, not the laser range
        since = time.time()
        thermal, visible = self.current_panel(1, since), self.current_panel(0, since)
        self.assertEqual(thermal.header.frame_id, "k40t_thermal_optical_frame")
        self.assertEqual(visible.header.frame_id, "k40t_tele_optical_frame")
        # The thermal panel is 640 px shown 960 px wide, at the thermal camera's own zoom.
        self.assertAlmostEqual(thermal.K[0], 1.5 * THERMAL_FX_1X * THERMAL_ZOOM, delta=0.5)
        truth = parse_truth(self.control.ok("truth"))  # hovering: the truth holds
        true_slant = distance_m(truth["pod"][0:3], truth["hot"][0:3])
        (u, v), in_thermal = self.locate_in(truth, thermal)
        self.assertEqual(in_thermal.fix.header.frame_id, "k40t_thermal_optical_frame")
        (vu, vv), in_visible = self.locate_in(truth, visible)
        self.assertEqual(in_visible.fix.header.frame_id, "k40t_tele_optical_frame")
        # The image agrees: the brightest blob of the thermal panel is where the truth puts it.
        image = rospy.wait_for_message(name("image_raw"), Image, timeout=10.0)
        bu, bv, count = hot_blob_centre(image, thermal.roi)
        thermal_error = distance_m(fix_point(in_thermal.fix), truth["hot"][0:3])
        visible_error = distance_m(fix_point(in_visible.fix), truth["hot"][0:3])
        print("GEO split slant %.1f m: thermal panel pixel (%.1f, %.1f) %.3f m (image blob at "
              "(%.1f, %.1f), %d px); visible panel pixel (%.1f, %.1f) %.3f m"
              % (true_slant, u, v, thermal_error, bu, bv, count, vu, vv, visible_error))
        # The simulator samples the thermal scene every 4 px (6 px of the panel): a few px.
        self.assertLess(math.hypot(bu - u, bv - v), 8.0, "the image's hot blob is elsewhere")
        for label, error in (("thermal panel", thermal_error), ("visible panel", visible_error)):
            self.assertLessEqual(error, 0.01 * true_slant,
                                 "%s: %.3f m at %.1f m" % (label, error, true_slant))

    def test_hot_object_in_both_panels_at_100_and_500_m(self):
        for slant in (100.0, 500.0):
            self.check_at(slant)

    def test_a_pixel_between_the_panels_is_refused(self):
        self.current_panel(1, time.time())
        # The camera_infos reach the driver on connections of its own: until its first ones
        # arrive it has none ("no camera_info received") or still sees the whole image (the
        # switch itself takes up to a status period to show).
        answers = []

        def refused_between_panels():
            answers.append(self.locate(LocatePixelRequest(u=100.0, v=100.0)))  # the black bar
            return "neither panel" in answers[-1].message                       # above the visible
        self.assertTrue(wait_until(refused_between_panels, 10.0, step=0.1),
                        "last answer: %s" % answers[-1])
        self.assertFalse(answers[-1].success)


if __name__ == "__main__":
    rostest.rosrun("k40t_driver", "test_geo_split", GeoSplitTest, sys.argv)
