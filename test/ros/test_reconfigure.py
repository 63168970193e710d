#!/usr/bin/python3
"""dynamic_reconfigure against the simulated pod: every parameter round-trips (set, then read
back from the pod after a reconnect), a refused change is reverted, and the pod's own settings
become the configuration on connect."""
import os
import re
import sys
import time
import unittest

import rostest
from dynamic_reconfigure.client import Client as ReconfigureClient

from k40t_driver.srv import Send
from k40t_test_support import WARN, name, service, start_driver_test, wait_until

PKG = "k40t_driver"

# A value different from the simulator's default for every parameter.
VALUES = {
    "palette": 9, "thermal_zoom": 4, "thermal_measurement": False, "thermal_gain": 1,
    "thermal_sharpness": 33, "thermal_brightness": 61, "thermal_contrast": 72,
    "thermal_denoise": True, "thermal_denoise_level": 44, "thermal_enhancement": 6,
    "high_alarm": True, "high_alarm_degC": 150.5, "low_alarm": True, "low_alarm_degC": -20.0,
    "difference_alarm": True, "difference_alarm_degC": 42.0,
    "threshold_alarm": True, "threshold_reference_degC": 25.0, "threshold_float_degC": 7.5,
    "video_resolution": 0x26, "photo_resolution": 0x14, "iso": 3, "shutter": 13, "ev": 0x1C,
    "white_balance": 5, "anti_flicker": 2, "backlight_compensation": True, "backlight_level": 30,
    "ae_lock": True, "metering": 3, "osd_watermark": True,
    "camera_mode": 1, "image_mode": 7, "stream_bitrate": 6, "stream_encoding": 1,
    "photo_mode": 2, "timelapse_interval": 30, "burst_count": 5, "stabilisation": True,
    "pitch_dial_speed": 100, "yaw_dial_speed": 25, "periodic_ranging": True, "thermal_overlay": True,
}
# Not set: the strong-light suppression excludes the backlight compensation set above; the only
# other stream resolution, 720p, is one the document marks unsupported (refused before sending).
NOT_SET = {"strong_light_suppression", "strong_light_level", "stream_resolution"}


def write_only_parameters():
    """The cfg parameters of the write-only rows of the settings table in docs/ros_interface.md
    (generated from the driver's settings table and checked against it by a unit test)."""
    doc = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "docs", "ros_interface.md")
    with open(doc) as f:
        text = f.read()
    table = text.split("<!-- settings table begin")[1].split("<!-- settings table end")[0]
    rows = [[cell.strip() for cell in line.split("|")[1:-1]] for line in table.splitlines()[3:]]
    names = set()
    for row in rows:
        if row[3] == "write-only":
            names.update(re.findall(r"`(\w+)`", row[1]))
    return names


# Parameters the pod cannot report: checked by their ACK only (the value stays as set); the others
# are read back from the pod's reports (0x000100, 0x000200, the camera and the gimbal status).
WRITE_ONLY = {k: v for k, v in VALUES.items() if k in write_only_parameters()}
READ_BACK = {k: v for k, v in VALUES.items() if k not in WRITE_ONLY}


class Reconfigure(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        start_driver_test(cls, "test_reconfigure", diagnostics=True)
        cls.client = ReconfigureClient(name("driver"), timeout=15.0)
        # Wait for the read-back that follows the pod coming online.
        assert wait_until(lambda: cls.diagnostics.value("settings", "read-backs") not in (None, "0"), 10.0)

    def reconnect_and_wait_for_read_back(self):
        reads = int(self.diagnostics.value("settings", "read-backs"))
        self.sim.ok("disconnect 1")
        ok = wait_until(lambda: int(self.diagnostics.value("settings", "read-backs")) > reads, 15.0)
        self.assertTrue(ok, "no settings read-back after the pod reconnected")
        time.sleep(0.3)  # the new configuration reaches the client
        return self.client.get_configuration(timeout=5.0)

    def refusal_reported(self, text):
        """Diagnostics (published every 0.25 s) name the refused parameter."""
        return wait_until(lambda: (self.diagnostics.value("settings", "last refusal") or "").startswith(text), 3.0)

    def test_every_parameter_has_a_value_to_round_trip(self):
        described = {p["name"] for p in self.client.get_parameter_descriptions()}
        self.assertEqual(set(VALUES) | NOT_SET, described)
        self.assertTrue(WRITE_ONLY, "the docs' settings table lists no write-only setting")

    def test_every_parameter_round_trips_through_the_pod(self):
        # One at a time, so a refusal names its parameter.
        for key, value in list(READ_BACK.items()) + list(WRITE_ONLY.items()):
            config = self.client.update_configuration({key: value})
            self.assertEqual(config[key], value, "%s: set to %r, the driver kept %r" % (key, value, config[key]))
        # The backlight and the strong-light suppression are exclusive; backlight wins here.
        config = self.reconnect_and_wait_for_read_back()
        for key, value in READ_BACK.items():
            if isinstance(value, float):
                self.assertAlmostEqual(config[key], value, delta=0.05, msg=key)
            else:
                self.assertEqual(config[key], value, "%s read back as %r after reconnect, set %r" % (key, config[key], value))
        for key, value in WRITE_ONLY.items():
            self.assertEqual(config[key], value, "%s lost on reconnect" % key)

    def test_refused_change_is_reverted_and_reported(self):
        before = self.client.get_configuration(timeout=5.0)["thermal_brightness"]
        self.sim.ok("drop-acks 1")
        try:
            config = self.client.update_configuration({"thermal_brightness": (before + 17) % 100})
        finally:
            self.sim.ok("drop-acks 0")
        self.assertEqual(config["thermal_brightness"], before, "a timed-out change was not reverted")
        self.assertTrue(self.refusal_reported("thermal_brightness"), "the refusal is not in diagnostics")
        self.assertTrue(self.diagnostics.wait_level("settings", WARN, 3.0))

    def test_invalid_enum_value_is_reverted_without_sending(self):
        before = self.client.get_configuration(timeout=5.0)["ev"]
        config = self.client.update_configuration({"ev": 5})  # in 0..35 but not an EV code
        self.assertEqual(config["ev"], before)
        self.assertTrue(self.refusal_reported("ev: "), "the refusal is not in diagnostics")

    def test_pod_settings_become_the_configuration_on_connect(self):
        # Change the pod behind the driver's back (raw 0x000106 palette 17), then reconnect.
        response = service("send", Send)(id=0x000106, payload=[17, 0])
        self.assertTrue(response.success, response.message)
        self.assertNotEqual(self.client.get_configuration(timeout=5.0)["palette"], 17)
        config = self.reconnect_and_wait_for_read_back()
        self.assertEqual(config["palette"], 17)


if __name__ == "__main__":
    rostest.rosrun(PKG, "reconfigure", Reconfigure, sys.argv)
