#!/usr/bin/python3
"""The SKYPORT bridge's camera and gimbal commands act on k40t_sim (the pod) through the driver:
photos geotagged and named by the pushed UTC, recording, zoom, gimbal angles in either layout,
and DJI Pilot's widgets; replies are checked on skyport_sim's side (return code + data) and the
pod's state through k40t_sim's control socket."""
import struct
import sys
import time

import rostest

from k40t_test_support import reply_number, wait_until
from skyport_test_support import SkyportCase


PKG = "k40t_driver"


def wrap_deg(deg):
    """An angle in degrees brought into [-180, 180)."""
    return (deg + 180.0) % 360.0 - 180.0


class SkyportCameraGimbal(SkyportCase):
    NODE_NAME = "test_skyport_camera_gimbal"

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
        self.assertTrue(wait_until(lambda: abs(self.pod.number("zoom") - 2.0) < 0.05, 15.0),
                        self.pod_status())
        code, _ = self.command("focal 9.4")  # optical 2x, times digital 2x
        self.assertEqual(code, 0x00)
        self.assertTrue(wait_until(lambda: abs(self.pod.number("zoom") - 4.0) < 0.05, 15.0),
                        self.pod_status())
        code, _ = self.command("zoom 100")  # beyond the pod's 160x hybrid with 2x optical
        self.assertEqual(code, 0x01)

    # --- gimbal ----------------------------------------------------------------------------------

    def pod_heading(self):
        """The aircraft heading k40t_sim uses (degrees from north, clockwise), once it has held for
        0.3 s: the bridge's view of the pod's attitude lags the pod by a fraction of that."""
        heading = self.pod.number("heading", "truth")
        for _ in range(10):
            time.sleep(0.3)
            again = self.pod.number("heading", "truth")
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
        after = self.pod.number("heading", "truth")
        turned = wrap_deg(after - before)  # the flight turns clockwise: >= 0

        def joints_there():
            status = self.pod_status()
            offset = wrap_deg(20 - reply_number(status, "yaw") - before)
            return (abs(reply_number(status, "pitch") + 30) < 1.0 and
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
            ned_yaw = reply_number(status, "yaw") + self.pod.number("heading", "truth")
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


if __name__ == "__main__":
    rostest.rosrun(PKG, "skyport_camera_gimbal", SkyportCameraGimbal, sys.argv)
