#!/usr/bin/python3
"""Live telemetry of the K40T driver on one line, refreshed twice a second: gimbal angles, zoom,
thermal extremes, laser range, SD card, video (frame rate, size and frame id from camera_info),
link health. With --tour it also drives the pod through
its services (turn, zoom, look down and range, palette, photo) so the numbers move.

  scripts/k40t_status.py [--ns /k40t] [--tour] [--seconds N]"""
import argparse
import math
import sys
import threading
import time

import rospy
from dynamic_reconfigure.client import Client as ReconfigureClient
from diagnostic_msgs.msg import DiagnosticArray
from sensor_msgs.msg import CameraInfo, JointState, Range
from std_srvs.srv import Trigger

from k40t_driver.msg import CameraStatus, ThermalStats, VisibleStatus
from k40t_driver.srv import MeasureRange, SetAngle, SetPalette, SetZoom, TakePhoto

LEVELS = {0: "OK", 1: "WARN", 2: "ERROR", 3: "STALE"}


class Status:
    def __init__(self, ns):
        self.latest = {}
        self.link = "no diagnostics yet"
        for topic, cls in [("joint_states", JointState), ("visible/status", VisibleStatus),
                           ("thermal/stats", ThermalStats), ("laser/range", Range), ("camera/status", CameraStatus)]:
            rospy.Subscriber(ns + "/" + topic, cls, self._keep, callback_args=topic, queue_size=1)
        rospy.Subscriber("/diagnostics", DiagnosticArray, self._diagnostics, queue_size=10)
        # camera_info has the image's header and size without the pixels: cheap to count.
        self.video_stamps = []
        rospy.Subscriber(ns + "/camera_info", CameraInfo, self._camera_info, queue_size=10)

    def _camera_info(self, info):
        self.latest["camera_info"] = info
        now = time.time()
        self.video_stamps = [t for t in self.video_stamps if now - t < 2.0] + [now]

    def _keep(self, msg, topic):
        self.latest[topic] = msg

    def _diagnostics(self, array):
        for s in array.status:
            if s.name.endswith(": link"):
                self.link = "%s %s" % (LEVELS.get(s.level, "?"), s.message)

    def line(self):
        parts = []
        js = self.latest.get("joint_states")
        if js:
            yaw, roll, pitch = (math.degrees(a) if abs(a) > 1e-5 else 0.0 for a in js.position)  # no "-0.00"
            parts.append("yaw %+7.2f° roll %+6.2f° pitch %+6.2f°" % (yaw, roll, pitch))
        vis = self.latest.get("visible/status")
        if vis:
            parts.append("zoom %5.1fx" % vis.zoom_ratio)
        th = self.latest.get("thermal/stats")
        if th:
            parts.append("thermal %.1f..%.1f °C" % (th.min_degC, th.max_degC))
        rng = self.latest.get("laser/range")
        if rng:
            parts.append("laser %s" % ("no return" if math.isinf(rng.range) else "%.1f m" % rng.range))
        cam = self.latest.get("camera/status")
        if cam:
            parts.append("SD %s %.0f/%.0f MB" % (cam.sd_state_text, cam.sd_used_mb, cam.sd_total_mb))
        info = self.latest.get("camera_info")
        if info and self.video_stamps and time.time() - self.video_stamps[-1] < 1.0:
            parts.append("video %.0f fps %dx%d %s" % (len(self.video_stamps) / 2.0, info.width, info.height,
                                                     info.header.frame_id))
        elif info:
            parts.append("video stalled")
        parts.append("link %s" % self.link)
        return " | ".join(parts)


def tour(ns):
    """Drives the pod in a loop so the telemetry changes; prints each call's outcome."""
    def call(srv, cls, args):  # args as a dict: TakePhoto has a field called "name"
        try:
            rospy.wait_for_service(ns + "/" + srv, timeout=10.0)
            r = rospy.ServiceProxy(ns + "/" + srv, cls)(**args)
            extra = " range %.1f m" % r.range if cls is MeasureRange and r.success else ""
            print("\n  %s(%s): %s%s" % (srv, ", ".join("%s=%s" % kv for kv in args.items()), r.message, extra))
        except (rospy.ROSException, rospy.ServiceException) as e:
            print("\n  %s: %s" % (srv, e))

    clients = []  # one dynamic_reconfigure client, made on first use (it waits for the driver)

    def reconfigure(**settings):
        try:
            if not clients:
                clients.append(ReconfigureClient(ns + "/driver", timeout=10.0))
            done = clients[0].update_configuration(settings)
            print("\n  reconfigure %s: now %s" % (settings, {k: done[k] for k in settings}))
        except Exception as e:  # the client raises plain Exceptions on timeouts
            print("\n  reconfigure %s: %s" % (settings, e))

    steps = [
        ("image_mode", None, dict(image_mode=7)),  # split screen: visible | thermal
        ("gimbal/set_angle", SetAngle, dict(pitch=0.35, yaw=0.8)),
        ("set_zoom", SetZoom, dict(ratio=10.0)),
        ("gimbal/look_down", Trigger, {}),
        ("laser/measure", MeasureRange, {}),
        ("set_palette", SetPalette, dict(palette=5)),
        ("take_photo", TakePhoto, dict(lens=0, stop=False, folder="demo", name="")),
        ("set_zoom", SetZoom, dict(ratio=1.0)),
        ("gimbal/set_angle", SetAngle, dict(pitch=0.1, yaw=-0.8)),
        ("gimbal/center", Trigger, {}),
        ("image_mode", None, dict(image_mode=0)),  # thermal only
    ]
    while not rospy.is_shutdown():
        for name, cls, args in steps:
            if rospy.is_shutdown():
                return
            if cls is None:
                reconfigure(**args)
            else:
                call(name, cls, args)
            time.sleep(3.0)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ns", default="/k40t")
    ap.add_argument("--tour", action="store_true", help="drive the pod through its services")
    ap.add_argument("--seconds", type=float, default=0, help="stop after this long (0: until Ctrl-C)")
    args = ap.parse_args(rospy.myargv()[1:])
    rospy.init_node("k40t_status", anonymous=True, disable_signals=False)
    status = Status(args.ns.rstrip("/"))
    if args.tour:
        threading.Thread(target=tour, args=(args.ns.rstrip("/"),), daemon=True).start()
    end = time.time() + args.seconds if args.seconds > 0 else None
    while not rospy.is_shutdown() and (end is None or time.time() < end):
        sys.stdout.write("\r\033[K" + status.line() if sys.stdout.isatty() else status.line() + "\n")
        sys.stdout.flush()
        time.sleep(0.5)
    print()


if __name__ == "__main__":
    main()
