#!/usr/bin/python3
"""dynamic_reconfigure against the simulated pod: every parameter round-trips (set, then read
back from the pod after a reconnect), a refused change is reverted, and the pod's own settings
become the configuration on connect. A value outside its cfg range is refused, not clamped and
sent; the reply, the read-only last_refusal and the settings diagnostic tell the truth (issue 24)."""
import ast
import os
import re
import sys
import threading
import time
import unittest

import rospy
import rostest
from dynamic_reconfigure.client import Client as ReconfigureClient

from std_srvs.srv import Trigger

from k40t_driver.srv import Send, SetPalette
from k40t_test_support import OK, WARN, name, service, start_driver_test, wait_until

PKG = "k40t_driver"

# Not set: the strong-light suppression excludes the backlight compensation the derived values
# switch on; the only other stream resolution, 720p, is one the document marks unsupported (refused
# before sending); last_refusal is read-only, no setting.
NOT_SET = {"strong_light_suppression", "strong_light_level", "stream_resolution", "last_refusal"}


def enum_values(description):
    """The codes of an enum parameter's edit_method (cfg/setting_enums.txt via cfg/K40t.cfg), or
    None for a plain parameter."""
    method = description.get("edit_method") or ""
    if not method:
        return None
    return [constant["value"] for constant in ast.literal_eval(method)["enum"]]


def test_value(description, current):
    """A value for one parameter, derived from its cfg description (type, range, default, enum
    entries): different from both the cfg default and the pod's current value, so that a change
    the driver does not send, or the pod does not store, cannot read back as set. None if there is
    none."""
    avoid = {description["default"], current}
    if description["type"] == "bool":
        return not current  # the default can equal the pod's value only once
    codes = enum_values(description)
    if codes is not None:  # the enum entries after the default's, wrapping around
        start = codes.index(description["default"]) if description["default"] in codes else -1
        for code in codes[start + 1:] + codes[:start + 1]:
            if code not in avoid:
                return code
        return None
    low, high = description["min"], description["max"]
    for fraction in (1.0 / 3, 2.0 / 3, 0.5):
        value = low + (high - low) * fraction
        value = int(round(value)) if description["type"] == "int" else round(value, 1)
        if low <= value <= high and value not in avoid:
            return value
    return None


def write_only_parameters():
    """The cfg parameters whose "reconfigure" cell in the message tables of docs/protocol/*.md says
    write-only (checked against the driver's settings table by a unit test)."""
    folder = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "docs", "protocol")
    names = set()
    for file_name in sorted(os.listdir(folder)):
        if not file_name.endswith(".md"):
            continue
        with open(os.path.join(folder, file_name)) as f:
            for line in f:
                cells = [cell.strip() for cell in line.split("|")[1:-1]]
                if cells and cells[0].startswith("0x") and cells[-1].endswith("; write-only"):
                    names.update(re.findall(r"`(\w+)`", cells[-1]))
    return names


# Parameters the pod cannot report: checked by their ACK only (the value stays as set); the others
# are read back from the pod's reports (0x000100, 0x000200, the camera and the gimbal status).
WRITE_ONLY_NAMES = write_only_parameters()


class Reconfigure(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        start_driver_test(cls, "test_reconfigure", diagnostics=True)
        cls.client = ReconfigureClient(name("driver"), timeout=15.0)
        # Wait for the read-back that follows the pod coming online.
        assert wait_until(lambda: cls.diagnostics.value("settings", "read-backs") not in (None, "0"), 10.0)
        # The test value of every parameter, from the cfg's descriptions and the pod's settings.
        cls.descriptions = {d["name"]: d for d in cls.client.get_parameter_descriptions(timeout=5.0)}
        cls.initial = cls.client.get_configuration(timeout=5.0)
        cls.values = {n: test_value(d, cls.initial[n]) for n, d in cls.descriptions.items() if n not in NOT_SET}
        cls.write_only = {k: v for k, v in cls.values.items() if k in WRITE_ONLY_NAMES}
        cls.read_back = {k: v for k, v in cls.values.items() if k not in cls.write_only}

    def reconnect_and_wait_for_read_back(self):
        reads = int(self.diagnostics.value("settings", "read-backs"))
        self.sim.ok("disconnect 1")
        ok = wait_until(lambda: int(self.diagnostics.value("settings", "read-backs")) > reads, 15.0)
        self.assertTrue(ok, "no settings read-back after the pod reconnected")
        time.sleep(0.3)  # the new configuration reaches the client
        return self.client.get_configuration(timeout=5.0)

    def configuration_showing(self, expected, timeout=3.0):
        """The client's configuration once it shows `expected` ({parameter: value}), or the last
        one seen after `timeout`. The client keeps the last configuration the server published on
        its update topic; a service's answer (set_palette, read_settings) travels on another
        connection and can arrive before the update the write published under the same lock, so
        one read right after the answer may show the configuration before it (a lag, no undo: a
        write that was undone never shows and the caller's assertion fails)."""
        config = {}

        def shows():
            config.update(self.client.get_configuration(timeout=5.0))
            return all(config[key] == value for key, value in expected.items())

        wait_until(shows, timeout)
        return config

    def refusal_reported(self, text):
        """Diagnostics (published every 0.25 s) name the refused parameter."""
        return wait_until(lambda: (self.diagnostics.value("settings", "last refusal") or "").startswith(text), 3.0)

    def test_every_parameter_has_a_value_to_round_trip(self):
        self.assertLessEqual(NOT_SET, set(self.descriptions), "NOT_SET names a parameter the cfg lacks")
        for key, value in self.values.items():
            d = self.descriptions[key]
            self.assertIsNotNone(value, "%s: no value differs from the default and the pod's" % key)
            self.assertNotEqual(value, self.initial[key], key)
            if d["type"] != "bool":
                self.assertNotEqual(value, d["default"], key)
                self.assertTrue(d["min"] <= value <= d["max"], "%s: %r outside the cfg range" % (key, value))
            if enum_values(d) is not None:
                self.assertIn(value, enum_values(d), key)
        self.assertTrue(self.write_only, "no reconfigure cell of docs/protocol/*.md says write-only")

    def test_every_parameter_round_trips_through_the_pod(self):
        # One at a time, so a refusal names its parameter.
        for key, value in list(self.read_back.items()) + list(self.write_only.items()):
            config = self.client.update_configuration({key: value})
            self.assertEqual(config[key], value, "%s: set to %r, the driver kept %r" % (key, value, config[key]))
        # The backlight and the strong-light suppression are exclusive; backlight wins here.
        config = self.reconnect_and_wait_for_read_back()
        for key, value in self.read_back.items():
            if isinstance(value, float):
                self.assertAlmostEqual(config[key], value, delta=0.05, msg=key)
            else:
                self.assertEqual(config[key], value, "%s read back as %r after reconnect, set %r" % (key, config[key], value))
        for key, value in self.write_only.items():
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

    def read_from_pod(self):
        """The configuration as the pod has it now (read_settings re-reads it)."""
        response = service("read_settings", Trigger)()
        self.assertTrue(response.success, response.message)
        time.sleep(0.3)  # the new configuration reaches the client
        return self.client.get_configuration(timeout=5.0)

    def test_out_of_range_value_is_refused_not_clamped_and_sent(self):
        self.assertEqual(self.client.update_configuration({"palette": 5})["palette"], 5)
        config = self.client.update_configuration({"palette": 99})  # cfg range 1..20
        self.assertEqual(config["palette"], 5, "the reply does not show the palette in force")
        self.assertEqual(config["last_refusal"], "palette: palette 99 is outside 1..20")
        self.assertTrue(self.refusal_reported("palette: palette 99 is outside 1..20"))
        self.assertEqual(self.read_from_pod()["palette"], 5, "the pod's palette changed (20 sent?)")

    def test_mixed_change_keeps_the_refusal_until_a_later_write_succeeds(self):
        config = self.client.update_configuration({"image_mode": 0, "thermal_contrast": 40})
        self.assertEqual(config["last_refusal"], "")
        # Image mode 2 is in the cfg's 0..7 but no code of 0x000318: refused before sending; the
        # contrast is accepted after it (table order), which used to clear the refusal.
        config = self.client.update_configuration({"image_mode": 2, "thermal_contrast": 41})
        self.assertEqual(config["image_mode"], 0, "the reply does not show the image mode in force")
        self.assertEqual(config["thermal_contrast"], 41)
        self.assertTrue(config["last_refusal"].startswith("image_mode: "), config["last_refusal"])
        self.assertTrue(self.refusal_reported("image_mode: "), "the refusal is not in diagnostics")
        time.sleep(0.6)  # two more diagnostics periods: still there
        self.assertTrue(self.refusal_reported("image_mode: "), "the refusal left the diagnostics")
        self.assertTrue(self.diagnostics.wait_level("settings", WARN, 1.0))
        self.assertEqual(self.client.get_configuration(timeout=5.0)["last_refusal"], config["last_refusal"])
        # Nothing sent: the refusal stays; then a write the pod accepts clears it.
        self.assertTrue(self.client.update_configuration({"thermal_contrast": 41})["last_refusal"])
        self.assertEqual(self.client.update_configuration({"thermal_contrast": 42})["last_refusal"], "")
        self.assertTrue(wait_until(lambda: self.diagnostics.value("settings", "last refusal") == "", 3.0))

    def test_parameter_server_follows_the_configuration(self):
        # Written after the answer (served_config.h), changed parameters only.
        response = service("set_palette", SetPalette)(palette=9)
        self.assertTrue(response.success, response.message)
        self.assertTrue(wait_until(lambda: rospy.get_param(name("driver/palette")) == 9, 3.0))
        self.client.update_configuration({"thermal_sharpness": 33})
        self.assertTrue(wait_until(lambda: rospy.get_param(name("driver/thermal_sharpness")) == 33, 3.0))

    def test_service_writes_and_reconfigure_requests_do_not_undo_each_other(self):
        # set_palette in a loop while reconfigure changes the sharpness: a request built on a
        # configuration the service had not published yet would send an old palette back.
        set_palette = service("set_palette", SetPalette)
        stop = threading.Event()
        palettes = []

        def hammer():
            while not stop.is_set():
                palettes.append(1 + len(palettes) % 20)
                set_palette(palette=palettes[-1])

        thread = threading.Thread(target=hammer)
        thread.start()
        requests, deadline = 0, time.time() + 5.0
        try:  # until both sides have made 30 calls
            while (requests < 30 or len(palettes) < 30) and time.time() < deadline:
                value = 20 + requests % 60
                config = self.client.update_configuration({"thermal_sharpness": value})
                self.assertEqual(config["thermal_sharpness"], value)
                requests += 1
        finally:
            stop.set()
            thread.join()
        self.assertGreaterEqual(len(palettes), 30, "the service loop did not overlap the requests")
        expected = (palettes[-1], value)
        config = self.configuration_showing({"palette": palettes[-1], "thermal_sharpness": value})
        self.assertEqual((config["palette"], config["thermal_sharpness"]), expected)
        pod = self.read_from_pod()
        self.assertEqual((pod["palette"], pod["thermal_sharpness"]), expected)

    def test_last_refusal_is_read_only(self):
        before = self.client.get_configuration(timeout=5.0)["last_refusal"]
        config = self.client.update_configuration({"last_refusal": "written by a client"})
        self.assertEqual(config["last_refusal"], before)

    def test_refused_service_write_is_shown_to_reconfigure(self):
        response = service("set_palette", SetPalette)(palette=42)
        self.assertFalse(response.success)
        self.assertIn("palette 42 is outside 1..20", response.message)
        self.assertTrue(wait_until(lambda: self.client.get_configuration(timeout=5.0)["last_refusal"]
                                   == "palette: palette 42 is outside 1..20", 3.0))
        response = service("set_palette", SetPalette)(palette=6)
        self.assertTrue(response.success, response.message)
        config = self.configuration_showing({"palette": 6, "last_refusal": ""})
        self.assertEqual((config["palette"], config["last_refusal"]), (6, ""))

    def test_measurement_off_expects_no_thermal_report(self):
        # Section 3.2.2.4: with temperature measurement off the pod sends no 0x000004. That is no
        # missing report (it used to go ERROR "No events recorded") and no alarm (the last flags
        # used to stay shown).
        report, alarms = "thermal report (0x000004)", "temperature alarms"
        self.client.update_configuration({"thermal_measurement": False})
        try:
            time.sleep(1.5)  # two rate windows of silence
            self.assertTrue(self.diagnostics.wait_level(report, OK, 2.0), self.diagnostics.status(report))
            self.assertIn("measurement off", self.diagnostics.status(report).message)
            self.assertTrue(self.diagnostics.wait_level(alarms, OK, 2.0), self.diagnostics.status(alarms))
            self.assertIn("measurement off", self.diagnostics.status(alarms).message)
        finally:
            self.client.update_configuration({"thermal_measurement": True})
        self.assertTrue(wait_until(lambda: "measurement off" not in self.diagnostics.status(report).message, 3.0))

    def test_pod_settings_become_the_configuration_on_connect(self):
        # Change the pod behind the driver's back (raw 0x000106 palette 17), then reconnect.
        response = service("send", Send)(id=0x000106, payload=[17, 0])
        self.assertTrue(response.success, response.message)
        self.assertNotEqual(self.client.get_configuration(timeout=5.0)["palette"], 17)
        config = self.reconnect_and_wait_for_read_back()
        self.assertEqual(config["palette"], 17)


if __name__ == "__main__":
    rostest.rosrun(PKG, "reconfigure", Reconfigure, sys.argv)
