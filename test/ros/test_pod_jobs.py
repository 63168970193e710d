#!/usr/bin/python3
"""Issue 10 against the simulated pod: every long operation's status frame is a typed topic
carrying its state and text; precise_reshoot (the simulator keeps the resolution of byte 2),
tf_upgrade and read_settings work and refuse bad input with nothing sent; set_palette and
set_photo_mode change the published configuration at once (one write path); sbus/set says
exactly what took effect; one reconfigure can swap backlight compensation for strong-light
suppression."""
import statistics
import sys
import threading
import time
import unittest

import rostest
from dynamic_reconfigure.client import Client as ReconfigureClient
from std_srvs.srv import Trigger

from k40t_driver.msg import (CameraUpgradeStatus, Frame, PreciseReshootStatus, SdFormatStatus, TfCardUpgradeStatus, VisibleStatus,
                             ZoomStatus)
from k40t_driver.srv import (Focus, FocusRequest, GetSbus, PreciseReshoot, PreciseReshootRequest, Send, SetPalette, SetPhotoMode,
                             SetPhotoModeRequest, SetSbus, SetZoom)
from k40t_test_support import assert_rejected_without_sending, frame_id, name, service, start_driver_test, wait_until

PKG = "k40t_driver"
SBUS_CHANNELS = dict(stream_channel=8, zoom_channel=9, photo_channel=10, record_channel=11, pitch_channel=12,
                     yaw_channel=13, centre_channel=14)


class PodJobs(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        start_driver_test(cls, "test_pod_jobs", raw_tx=("raw/tx", Frame), visible=("visible/status", VisibleStatus),
                          zoom=("zoom/status", ZoomStatus), reshoot=("reshoot/status", PreciseReshootStatus),
                          tf_upgrade=("tf_card_upgrade/status", TfCardUpgradeStatus),
                          sd_format=("sd_format/status", SdFormatStatus),
                          camera_upgrade=("camera/upgrade_status", CameraUpgradeStatus))
        cls.client = ReconfigureClient(name("driver"), timeout=15.0)
        time.sleep(1.5)  # the read-back that follows the pod coming online

    def setUp(self):
        self.sim.ok("clear")
        self.sim.ok("refuse 0")

    def call_ok(self, srv, srv_type, **args):
        response = service(srv, srv_type)(**args)
        self.assertTrue(response.success, "%s(%s) failed: %s" % (srv, args, response.message))
        return response

    def config(self):
        return self.client.get_configuration(timeout=5.0)

    def config_becomes(self, **expected):
        """The published configuration reaches `expected` (it arrives on parameter_updates a moment
        after the service returns)."""
        def matches():
            config = self.config()
            return all(config[k] == v for k, v in expected.items())
        return wait_until(matches, 3.0)

    def state_seen(self, recorder, state, text, timeout, since):
        """The first message of `recorder` after `since` in `state`: asserts that it arrives within
        `timeout` seconds and names its state `text`."""
        msg = recorder.wait_for_match(lambda m: m.state == state, timeout, since)
        self.assertIsNotNone(msg, "no '%s' on %s" % (text, recorder.topic))
        self.assertEqual(msg.state_text, text)
        return msg

    # --- status topics ---------------------------------------------------------------------
    def test_zoom_status_says_zooming_then_done(self):
        since = time.time()
        self.call_ok("set_zoom", SetZoom, ratio=20.0)
        self.state_seen(self.zoom, ZoomStatus.STATE_ZOOMING, "zooming", 5.0, since)
        done = self.state_seen(self.zoom, ZoomStatus.STATE_DONE, "zoom done", 10.0, since)
        self.assertGreater(done.header.stamp.to_sec(), 0)

    def test_format_sd_progress_at_5_hz(self):
        since = time.time()
        self.call_ok("format_sd", Trigger)
        self.state_seen(self.sd_format, SdFormatStatus.STATE_DONE, "format done", 15.0, since)
        stamps = [m.header.stamp.to_sec() for m in self.sd_format.messages(since)
                  if m.state == SdFormatStatus.STATE_FORMATTING]
        self.assertGreaterEqual(len(stamps), 3, "too few 'formatting' frames to see a rate")
        period = statistics.median([b - a for a, b in zip(stamps, stamps[1:])])
        self.assertAlmostEqual(period, 0.2, delta=0.08, msg="section 3.2.4.12: 5 Hz")

    # --- precise_reshoot --------------------------------------------------------------------
    def test_precise_reshoot_shoots_at_its_resolution(self):
        self.assertTrue(self.visible.wait_for(1, 5.0), "no visible/status")
        since = time.time()
        response = self.call_ok("precise_reshoot", PreciseReshoot, lens=PreciseReshootRequest.LENS_VISIBLE,
                                resolution=PreciseReshootRequest.RESOLUTION_5664x4248, zoom_ratio=4.0,
                                focal_length_mm=0.0, folder="", name="reshoot_a")
        self.assertAlmostEqual(response.zoom_ratio, 4.0, places=3)
        reshooting = self.reshoot.wait_for_match(lambda m: m.state == PreciseReshootStatus.STATE_RESHOOTING, 5.0, since)
        self.assertIsNotNone(reshooting, "no 'reshooting' on reshoot/status")
        self.assertEqual(reshooting.lens, PreciseReshootStatus.LENS_VISIBLE)
        self.state_seen(self.reshoot, PreciseReshootStatus.STATE_DONE, "photo taken", 10.0, since)
        self.assertIn("reshoot_a.jpg 5664x4248", self.sim.ok("photos"))

    def test_precise_reshoot_refuses_bad_input_sending_nothing(self):
        args = dict(lens=2, resolution=21, zoom_ratio=4.0, focal_length_mm=10.0, folder="", name="x")
        for field, bad in (("resolution", dict(resolution=24)), ("zoom_ratio", dict(zoom_ratio=161.0)),
                           ("focal_length_mm", dict(focal_length_mm=700.0)), ("lens", dict(lens=4)),
                           ("name", dict(name="n" * 33))):
            call = dict(args)
            call.update(bad)
            assert_rejected_without_sending(self, self.raw_tx, "precise_reshoot", PreciseReshoot, field, **call)

    # --- focus area ------------------------------------------------------------------------
    def test_area_focus_reaches_the_pod_with_its_corners(self):
        self.call_ok("focus", Focus, mode=FocusRequest.AREA_AUTO, x1=800, y1=400, x2=1120, y2=680)
        self.assertIn("focus area 800,400-1120,680", self.sim.ok("status"))
        self.call_ok("focus", Focus, mode=FocusRequest.ONE_TOUCH, x1=0, y1=0, x2=0, y2=0)
        self.assertIn("focus centre", self.sim.ok("status"))
        assert_rejected_without_sending(self, self.raw_tx, "focus", Focus, "area_right_px",
                                        mode=FocusRequest.AREA_AUTO, x1=800, y1=400, x2=800, y2=680)

    # --- tf_upgrade -------------------------------------------------------------------------
    def test_tf_upgrade_reports_until_it_succeeds(self):
        since = time.time()
        self.call_ok("tf_upgrade", Trigger)
        self.state_seen(self.tf_upgrade, TfCardUpgradeStatus.STATE_UPGRADING, "upgrading", 5.0, since)
        done = self.tf_upgrade.wait_for_match(lambda m: m.state == TfCardUpgradeStatus.STATE_SUCCEEDED, 20.0, since)
        self.assertIsNotNone(done, "no 'upgrade succeeded' on tf_card_upgrade/status")
        # The 1 Hz upgrade report (0x000008) counts the progress on camera/upgrade_status.
        progress = [m.progress_percent for m in self.camera_upgrade.messages(since)
                    if m.state == CameraUpgradeStatus.STATE_UPGRADING]
        self.assertGreaterEqual(len(progress), 3, "no progress on camera/upgrade_status")
        self.assertEqual(progress, sorted(progress), "upgrade progress went backwards")

    def test_use_flight_controller_attitude_sends_0x000030(self):
        since = time.time()
        self.call_ok("gimbal/use_flight_controller_attitude", Trigger)
        sent = self.raw_tx.wait_for_match(lambda f: frame_id(f.data) == 0x000030, 2.0, since)
        self.assertIsNotNone(sent, "0x000030 not on raw/tx")

    def test_tf_upgrade_without_a_card_is_the_pods_refusal(self):
        self.sim.ok("sd absent")
        try:
            response = service("tf_upgrade", Trigger)()
            self.assertFalse(response.success)
            self.assertIn("no SD card", response.message)
        finally:
            self.sim.ok("sd insert")

    # --- settings: one write path, read_settings --------------------------------------------
    def test_set_palette_is_published_at_once_and_bad_values_send_nothing(self):
        self.call_ok("set_palette", SetPalette, palette=13)
        self.assertTrue(self.config_becomes(palette=13), "set_palette did not reach the configuration")
        assert_rejected_without_sending(self, self.raw_tx, "set_palette", SetPalette, "palette", palette=25)
        time.sleep(0.3)
        self.assertEqual(self.config()["palette"], 13)

    def test_set_photo_mode_is_published_at_once(self):
        self.call_ok("set_photo_mode", SetPhotoMode, mode=SetPhotoModeRequest.BURST,
                     timelapse_interval_s=7, burst_count=3)
        self.assertTrue(self.config_becomes(photo_mode=1, burst_count=3, timelapse_interval=7),
                        "set_photo_mode did not reach the configuration: %s" % self.config())
        self.call_ok("set_photo_mode", SetPhotoMode, mode=0, timelapse_interval_s=5, burst_count=5)

    def test_read_settings_picks_up_a_change_made_behind_the_driver(self):
        # 0x000106 (section 3.2.2.3): byte 1 palette 1..20, byte 2 reserved. Through `send`, the
        # driver's configuration does not know about it until read_settings.
        self.call_ok("set_palette", SetPalette, palette=2)
        self.assertTrue(self.config_becomes(palette=2))
        self.call_ok("send", Send, id=0x000106, payload=[17, 0])
        time.sleep(0.3)
        self.assertEqual(self.config()["palette"], 2)  # the driver does not know yet
        response = self.call_ok("read_settings", Trigger)
        self.assertIn("0x000100", response.message)
        self.assertTrue(self.config_becomes(palette=17), "read_settings did not republish")

    def test_a_setting_written_during_a_read_keeps_the_written_value(self):
        # read_settings reads 0x000100 (palette) and 0x000200, then waits for the 1 Hz camera
        # report: a set_palette in that wait is accepted by the pod after its palette was read,
        # so the read's palette is stale and must not replace the written one.
        self.call_ok("set_palette", SetPalette, palette=3)
        self.assertTrue(self.config_becomes(palette=3))
        since = time.time()
        read = {}
        reading = threading.Thread(target=lambda: read.update(response=service("read_settings", Trigger)()))
        reading.start()
        sent = lambda: [frame_id(f.data) for f in self.raw_tx.messages(since)]
        self.assertTrue(wait_until(lambda: 0x000200 in sent(), 5.0), "read_settings sent no 0x000200")
        self.call_ok("set_palette", SetPalette, palette=9)
        reading.join(10.0)
        self.assertTrue(read["response"].success, read["response"].message)
        self.assertIn("palette 9 ", self.sim.ok("status") + " ")
        self.assertTrue(self.config_becomes(palette=9), "the read replaced the written palette: %s" % self.config())
        time.sleep(0.5)
        self.assertEqual(self.config()["palette"], 9)

    def test_a_value_outside_the_cfg_range_is_not_sent_back_clamped(self):
        # 0x010200 byte 3 may report 0x16 (5160x3870), which the cfg (0x14..0x15) does not hold.
        self.sim.ok("photo-resolution 0x16")
        try:
            self.call_ok("read_settings", Trigger)
            self.assertTrue(self.config_becomes(photo_resolution=0x16), "the pod's value was not published as is")
            since = time.time()
            config = self.client.update_configuration({"palette": 4})  # nothing clamps the rest (served_config.h)
            self.assertEqual(config["photo_resolution"], 0x16)
            self.assertEqual(config["palette"], 4)
            time.sleep(0.3)
            sent = [frame_id(f.data) for f in self.raw_tx.messages(since)]
            self.assertIn(0x000106, sent)
            self.assertNotIn(0x000202, sent, "the clamped photo resolution was sent to the pod")
            self.call_ok("read_settings", Trigger)  # the pod still holds it
            self.assertTrue(self.config_becomes(photo_resolution=0x16))
        finally:
            self.sim.ok("photo-resolution 0x15")
            service("read_settings", Trigger)()

    # --- sbus/set -----------------------------------------------------------------------------
    def test_sbus_set_says_what_took_effect(self):
        self.call_ok("sbus/set", SetSbus, max_value=1811, min_value=172, **SBUS_CHANNELS)
        self.sim.ok("refuse 0x000501")
        response = service("sbus/set", SetSbus)(max_value=1900, min_value=100, **SBUS_CHANNELS)
        self.assertFalse(response.success)
        self.assertFalse(response.range_applied, response.message)
        self.assertFalse(response.channels_applied)
        self.assertIn("nothing changed", response.message)
        self.assertIn("0x000501", response.message)
        self.sim.ok("refuse 0")
        got = self.call_ok("sbus/get", GetSbus)
        self.assertEqual((got.max_value, got.min_value), (1811, 172), "the previous range was not restored")
        ok = self.call_ok("sbus/set", SetSbus, max_value=1900, min_value=100, **SBUS_CHANNELS)
        self.assertTrue(ok.range_applied and ok.channels_applied and ok.power_cycle_needed)
        self.assertIn("powered off and on", ok.message)

    def test_refused_range_changes_nothing(self):
        self.sim.ok("refuse 0x000500")
        response = service("sbus/set", SetSbus)(max_value=1800, min_value=200, **SBUS_CHANNELS)
        self.assertFalse(response.success)
        self.assertFalse(response.range_applied or response.channels_applied or response.power_cycle_needed)
        self.assertIn("0x000500", response.message)

    # --- time zone -----------------------------------------------------------------------------
    def test_time_sync_carries_the_time_zone_parameter(self):
        since = time.time()
        sync = self.raw_tx.wait_for_match(lambda f: frame_id(f.data) == 0x00030E, 5.0, since)
        self.assertIsNotNone(sync, "no time sync (0x00030E) on raw/tx")
        # Section 3.2.4.13: payload = int64 ms, int32 tz_minuteswest, int32 tz_dsttime, low byte
        # first; the payload starts at frame byte 10. time_zone_minutes_west -480 = 20 FE FF FF.
        self.assertEqual(list(bytearray(sync.data[18:22])), [0x20, 0xFE, 0xFF, 0xFF])

    # --- strong light / backlight -------------------------------------------------------------
    def test_strong_light_replaces_backlight_in_one_change(self):
        self.client.update_configuration({"strong_light_suppression": False, "backlight_compensation": False})
        config = self.client.update_configuration({"backlight_compensation": True})
        self.assertTrue(config["backlight_compensation"])
        config = self.client.update_configuration({"backlight_compensation": False, "strong_light_suppression": True})
        self.assertTrue(config["strong_light_suppression"], "strong light was refused: backlight went off too late")
        self.assertFalse(config["backlight_compensation"])
        config = self.client.update_configuration({"backlight_compensation": True, "strong_light_suppression": False})
        self.assertTrue(config["backlight_compensation"])
        self.assertFalse(config["strong_light_suppression"])


if __name__ == "__main__":
    rostest.rosrun(PKG, "pod_jobs", PodJobs, sys.argv)
