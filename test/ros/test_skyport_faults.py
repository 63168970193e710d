#!/usr/bin/python3
"""The SKYPORT bridge under faults: diagnostics go ERROR while skyport_sim is silent, the bridge
answers DJI Pilot's polls from the last known state while the pod is unplugged (memory bounded),
and a battery power-off announcement stops the pod's recording before the bridge acks ready."""
import sys
import time
import xmlrpc.client

import rostest
import rosgraph
from diagnostic_msgs.msg import DiagnosticStatus

from k40t_test_support import name, wait_until
from skyport_test_support import SkyportCase


PKG = "k40t_driver"


def manager_rss_kb():
    """Resident memory of the nodelet manager that runs the bridge (its pid from its XML-RPC API)."""
    uri = rosgraph.Master("/test_skyport").lookupNode(name("manager"))
    _, _, pid = xmlrpc.client.ServerProxy(uri).getPid("/test_skyport")
    with open("/proc/%d/status" % pid) as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise AssertionError("no VmRSS for pid %d" % pid)


class SkyportFaults(SkyportCase):
    NODE_NAME = "test_skyport_faults"

    def test_y_diagnostics_error_while_the_adapter_is_silent(self):
        self.assertTrue(self.diagnostics.wait_level("SKYPORT link", DiagnosticStatus.OK, 20.0))
        since = time.time()
        self.skyport.ok("silence 3")

        def silent_error():
            with self.diagnostics.lock:
                return [m for t, n, lv, m in self.diagnostics.history
                        if t >= since and n.endswith(": SKYPORT link") and lv == DiagnosticStatus.ERROR]
        errors = wait_until(silent_error, 10.0)
        self.assertTrue(errors, "no ERROR while the adapter was silent: %s" % self.diagnostics.status("SKYPORT link"))
        self.assertIn("silent", errors[0])
        self.assertTrue(self.diagnostics.wait_level("SKYPORT link", DiagnosticStatus.OK, 15.0),
                        "not OK again after the silence")

    def test_yy_unplugged_pod_while_dji_pilot_polls(self):
        # The pod's link is cut (k40t_sim closes it; the driver's status topics stop and its
        # services fail) while the adapter keeps polling: the bridge answers every getter from the
        # last known state at once, diagnostics mark that state stale, and nothing piles up.
        self.assertTrue(self.diagnostics.wait_level("SKYPORT link", DiagnosticStatus.OK, 20.0))
        before, _ = self.command("gimbal_state")
        self.assertEqual(before, 0x00)
        self.pod.ok("disconnect 15")
        self.assertTrue(wait_until(lambda: self.diagnostics.value("SKYPORT link", "pod state stale") == "True",
                                   10.0), self.diagnostics.status("SKYPORT link"))
        codes = []

        def poll(rounds):
            for _ in range(rounds):
                for getter in ("gimbal_state", "record_state"):
                    codes.append(self.command(getter)[0])
                self.command("gimbal_return")  # a pod call: refused or busy, never waited for
        poll(5)
        rss_before = manager_rss_kb()
        poll(15)  # three times as many: memory must not grow with them (a bounded queue)
        rss_after = manager_rss_kb()
        print("manager resident memory while the pod is unplugged: %d kB after 5 polling rounds, %d kB after 15 more"
              % (rss_before, rss_after))
        self.assertEqual(codes, [0x00] * len(codes))
        self.assertLess(rss_after - rss_before, 2048,
                        "the manager grew from %d to %d kB while the pod was unplugged" % (rss_before, rss_after))
        status = self.diagnostics.status("SKYPORT link")
        self.assertIn("stale", status.message)
        self.assertLessEqual(int(self.diagnostics.value("SKYPORT link", "pod jobs queued")), 8)
        # Plugged in again: the state is fresh, diagnostics OK.
        self.assertTrue(wait_until(lambda: self.diagnostics.value("SKYPORT link", "pod state stale") == "False",
                                   30.0), self.diagnostics.status("SKYPORT link"))

    # --- power-off: last (the announcement stays) -------------------------------------------------

    def test_zz_power_off_stops_recording_then_acks_ready(self):
        self.video_mode()
        self.command_ok("record start")
        self.assertTrue(wait_until(lambda: "recording yes" in self.pod_status(), 10.0), self.pod_status())
        self.skyport.ok("power_off")
        self.assertTrue(self.power_off.wait_for_match(lambda m: m.data, 10.0), "no power-off warning topic")
        self.assertTrue(wait_until(lambda: "power_off_ready=1" in self.skyport.ok("status"), 15.0),
                        self.skyport.ok("status"))
        # "Ready" comes only after the driver's record service had the pod acknowledge the stop (the
        # simulated pod closes the file on its next tick).
        self.assertTrue(wait_until(lambda: "recording no" in self.pod_status(), 5.0), self.pod_status())


if __name__ == "__main__":
    rostest.rosrun(PKG, "skyport_faults", SkyportFaults, sys.argv)
