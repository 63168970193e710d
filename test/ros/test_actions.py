#!/usr/bin/python3
"""The driver's actions against the simulated pod, through actionlib's SimpleActionClient: each
succeeds with feedback, can be cancelled (the gimbal and the zoom stop; the others end the goal
while the pod carries on), times out with a readable reason, and refuses bad goals with nothing
sent on raw/tx. Shutdown during a goal: test_action_shutdown.py."""
import math
import os
import sys
import time
import unittest
from xmlrpc.client import ServerProxy

import actionlib
import rosgraph
import rospy
import rostest
from actionlib_msgs.msg import GoalStatus, GoalStatusArray
from dynamic_reconfigure.client import Client as ReconfigureClient

from k40t_driver.msg import (Frame, FormatSdAction, FormatSdGoal, GimbalCalibrateAction, GimbalCalibrateGoal,
                             GimbalMoveToAction, GimbalMoveToGoal, PreciseReshootAction, PreciseReshootGoal,
                             TfUpgradeAction, TfUpgradeGoal, VisibleStatus, ZoomToAction, ZoomToGoal)
from k40t_driver.srv import SetZoom
from k40t_test_support import (BACKGROUND_IDS, Recorder, Run, frame_id, ids_sent_since, name, service,
                               start_driver_test, wait_until)

PKG = "k40t_driver"

RES_4000x3000 = PreciseReshootGoal.RESOLUTION_4000x3000
YAW = 0  # joint_states order: yaw, roll, pitch
PITCH = 2


class Actions(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        start_driver_test(cls, "test_actions", raw_tx=("raw/tx", Frame), visible=("visible/status", VisibleStatus))
        cls.clients = {}
        cls.specs = {}
        for action, spec in (("gimbal/move_to", GimbalMoveToAction), ("gimbal/calibrate", GimbalCalibrateAction),
                             ("zoom_to", ZoomToAction), ("format_sd", FormatSdAction),
                             ("precise_reshoot", PreciseReshootAction), ("tf_upgrade", TfUpgradeAction)):
            client = actionlib.SimpleActionClient(name(action), spec)
            assert client.wait_for_server(rospy.Duration(20.0)), "no action server " + action
            cls.clients[action] = client
            cls.specs[action] = spec
        assert cls.visible.wait_for(1, timeout=10.0), "no visible/status"
        time.sleep(1.0)  # the settings read when the pod comes online

    def setUp(self):
        self.sim.ok("clear")
        # A photo, zoom or upgrade still under way from the test before would be refused "busy".
        self.assertTrue(self.sim.wait_idle(30.0), self.sim.ok("status"))

    # --- helpers ---------------------------------------------------------------------------
    def run_goal(self, action, goal):
        return Run(self.clients[action], goal)

    def sent_ids(self, since):
        return [frame_id(f.data) for f in self.raw_tx.messages(since)]

    def assert_refused_without_sending(self, action, goal, field):
        # A client of its own for each refused goal: once, under load, the fifth goal in a row
        # sent through one SimpleActionClient got no result, a client-side race of actionlib's
        # Python client with goals that end at once; the server's refusal is what is checked here.
        client = actionlib.SimpleActionClient(name(action), self.specs[action])
        self.assertTrue(client.wait_for_server(rospy.Duration(10.0)), "no action server " + action)
        start = rospy.Time.now()
        state, result = Run(client, goal).wait(5.0)
        time.sleep(0.2)  # anything sent would be on raw/tx by now
        self.assertEqual(state, GoalStatus.ABORTED, "%s accepted %s" % (action, goal))
        self.assertFalse(result.success)
        self.assertIn(field, result.message, "%s: the reason does not name '%s': %s" % (action, field, result.message))
        unexpected = [i for i in ids_sent_since(self.raw_tx, start) if i not in BACKGROUND_IDS]
        self.assertEqual(unexpected, [], "%s sent %s for a bad goal" % (action, ["0x%06X" % i for i in unexpected]))

    def cancel_after(self, action, goal, seconds):
        """Sends goal, cancels it after `seconds`; returns the final state and result."""
        run = self.run_goal(action, goal)
        time.sleep(seconds)
        self.clients[action].cancel_goal()
        return run.wait(5.0)

    def assert_cancel_lets_the_pod_carry_on(self, action, goal, seconds):
        """For what the pod cannot stop: the goal ends PREEMPTED and says the pod carries on."""
        state, result = self.cancel_after(action, goal, seconds)
        self.assertEqual(state, GoalStatus.PREEMPTED, result.message)
        self.assertFalse(result.success)
        self.assertIn("carries on", result.message)

    def assert_rising_progress(self, run, distinct):
        """Feedback percentages from 0x000008: at least `distinct` values, never going back."""
        progress = [f.progress for f in run.feedback if f.progress >= 0]
        self.assertGreaterEqual(len(set(progress)), distinct, "percentages from 0x000008: %s" % progress)
        self.assertEqual(progress, sorted(progress))

    def joint(self, index):
        return self.joints.latest().position[index]

    def move_home(self):
        state, result = self.run_goal("gimbal/move_to", GimbalMoveToGoal(pitch=0.0, yaw=0.0)).wait(30.0)
        self.assertEqual(state, GoalStatus.SUCCEEDED, result.message)

    # --- every action ----------------------------------------------------------------------
    def test_idle_goal_threads_sleep(self):
        """With no goal running, the six goal threads sleep until a goal comes (actionlib's own
        execute thread woke 10 times a second each): a count of wake-ups, not a timing."""
        uri = rosgraph.Master(rospy.get_name()).lookupNode(name("driver"))
        _, _, pid = ServerProxy(uri).getPid(rospy.get_name())
        tasks = "/proc/%d/task" % pid

        def goal_threads():
            found = []
            for tid in os.listdir(tasks):
                with open("%s/%s/comm" % (tasks, tid)) as comm:
                    if comm.read().strip() == "k40t_goal":
                        found.append(tid)
            return found

        def wakeups(tids):
            total = 0
            for tid in tids:
                with open("%s/%s/status" % (tasks, tid)) as status:
                    total += sum(int(line.split()[1]) for line in status if "ctxt_switches" in line)
            return total

        tids = goal_threads()
        self.assertEqual(len(tids), 6, "goal threads: %s" % tids)
        before = wakeups(tids)
        time.sleep(2.0)
        woke = wakeups(tids) - before
        # Polling would be 6 threads x 10 a second x 2 s = 120; a goal ending from the test before
        # may still wake its thread once or twice.
        self.assertLessEqual(woke, 12, "idle goal threads woke %d times in 2 s" % woke)

    def test_idle_status_once_a_second(self):
        """k40t.launch's actionlib_status_frequency: an idle server re-publishes its status once a
        second (actionlib's default is 5 a second); a count of messages, not a timing."""
        status = Recorder(name("zoom_to/status"), GoalStatusArray)
        try:
            self.assertTrue(status.wait_for(1, timeout=5.0), "no zoom_to/status")
            per_second = status.rate(3.0)
        finally:
            status.close()
        self.assertLessEqual(per_second, 2.0, "zoom_to/status at %.1f a second" % per_second)

    # --- gimbal/move_to --------------------------------------------------------------------
    def test_move_to_arrives_with_feedback(self):
        self.move_home()
        since = time.time()
        run = self.run_goal("gimbal/move_to", GimbalMoveToGoal(pitch=0.5, yaw=-0.4, tolerance=0.01))
        state, result = run.wait(30.0)
        self.assertEqual(state, GoalStatus.SUCCEEDED, result.message)
        self.assertTrue(result.success)
        self.assertIn(0x000012, self.sent_ids(since))
        self.assertLessEqual(abs(result.pitch - 0.5), 0.01)
        self.assertLessEqual(abs(result.yaw + 0.4), 0.01)
        # Feedback: the joints on their way, in REP 103 signs like joint_states.
        self.assertGreater(len(run.feedback), 3)
        pitches = [f.pitch for f in run.feedback if not math.isnan(f.pitch)]
        self.assertLess(pitches[0], pitches[-1])
        errors = [f.error for f in run.feedback if not math.isnan(f.error)]
        self.assertLess(errors[-1], errors[0])
        self.assertTrue(wait_until(lambda: abs(self.joint(PITCH) - 0.5) < 0.02, 2.0))

    def test_move_to_cancel_stops_the_gimbal(self):
        self.move_home()
        since = time.time()
        state, result = self.cancel_after("gimbal/move_to", GimbalMoveToGoal(pitch=0.0, yaw=3.0), 1.5)  # 172 deg: ~9 s
        self.assertEqual(state, GoalStatus.PREEMPTED, result.message)
        self.assertIn("gimbal stopped", result.message)
        self.assertIn(0x000010, self.sent_ids(since))
        time.sleep(0.3)
        stopped_at = self.joint(YAW)
        time.sleep(1.0)
        self.assertAlmostEqual(self.joint(YAW), stopped_at, delta=0.005, msg="the gimbal kept turning")
        self.assertLess(stopped_at, 2.0)

    def test_move_to_times_out_and_stops(self):
        self.move_home()
        state, result = self.run_goal("gimbal/move_to", GimbalMoveToGoal(pitch=0.0, yaw=-3.0, timeout=1.0)).wait(10.0)
        self.assertEqual(state, GoalStatus.ABORTED, result.message)
        self.assertIn("timed out after 1.0 s", result.message)
        self.assertIn("gimbal stopped", result.message)
        time.sleep(0.3)
        stopped_at = self.joint(YAW)
        time.sleep(0.8)
        self.assertAlmostEqual(self.joint(YAW), stopped_at, delta=0.005)

    def test_move_to_refuses_bad_goals(self):
        self.assert_refused_without_sending("gimbal/move_to", GimbalMoveToGoal(pitch=2.0), "pitch")
        self.assert_refused_without_sending("gimbal/move_to", GimbalMoveToGoal(yaw=-3.3), "yaw")
        self.assert_refused_without_sending("gimbal/move_to", GimbalMoveToGoal(tolerance=-0.1), "tolerance")
        self.assert_refused_without_sending("gimbal/move_to", GimbalMoveToGoal(timeout=-1.0), "timeout")

    # --- zoom_to ---------------------------------------------------------------------------
    def zoom_to(self, ratio):
        state, result = self.run_goal("zoom_to", ZoomToGoal(ratio=ratio)).wait(20.0)
        self.assertEqual(state, GoalStatus.SUCCEEDED, result.message)
        return result

    def test_zoom_to_ends_at_the_ratio_with_ratio_feedback(self):
        self.zoom_to(1.0)
        run = self.run_goal("zoom_to", ZoomToGoal(ratio=8.0))
        state, result = run.wait(20.0)
        self.assertEqual(state, GoalStatus.SUCCEEDED, result.message)
        # Arrived means 0x000005 shows the ratio asked for ("done" alone is not enough: a pod may
        # stop elsewhere), so the result carries it.
        self.assertRegex(result.message, r"zoom: (done|at 8\.0x)")
        self.assertAlmostEqual(result.ratio, 8.0, delta=0.05)
        ratios = [f.ratio for f in run.feedback if not math.isnan(f.ratio)]
        self.assertGreater(len(ratios), 2, "no ratio feedback")
        self.assertLess(ratios[0], ratios[-1])
        self.assertIn("zooming", [f.status for f in run.feedback])

    def test_zoom_to_cancel_stops_the_zoom(self):
        self.zoom_to(1.0)
        state, result = self.cancel_after("zoom_to", ZoomToGoal(ratio=160.0), 1.0)  # ~3.7 s to get there
        self.assertEqual(state, GoalStatus.PREEMPTED, result.message)
        self.assertIn("zoom stopped", result.message)
        self.assertTrue(wait_until(lambda: not self.visible.latest().zooming, 2.0))
        self.assertLess(self.visible.latest().zoom_ratio, 100.0)

    def test_zoom_to_times_out(self):
        self.zoom_to(1.0)
        state, result = self.run_goal("zoom_to", ZoomToGoal(ratio=160.0, timeout=0.5)).wait(10.0)
        self.assertEqual(state, GoalStatus.ABORTED, result.message)
        self.assertIn("timed out after 0.5 s", result.message)
        self.assertIn("0x000005", result.message)
        self.assertIn("zoom stopped", result.message)

    def test_zoom_to_refuses_bad_goals(self):
        self.assert_refused_without_sending("zoom_to", ZoomToGoal(ratio=0.5), "ratio")
        self.assert_refused_without_sending("zoom_to", ZoomToGoal(ratio=200.0), "ratio")
        self.assert_refused_without_sending("zoom_to", ZoomToGoal(ratio=2.0, timeout=float("nan")), "timeout")

    # --- format_sd -------------------------------------------------------------------------
    def test_format_sd_progress_then_done(self):
        run = self.run_goal("format_sd", FormatSdGoal())
        state, result = run.wait(20.0)
        self.assertEqual(state, GoalStatus.SUCCEEDED, result.message)
        self.assertIn("format done", result.message)
        # 0x02030D at 5 Hz for the simulator's 2 s format.
        self.assertGreaterEqual(max(f.reports for f in run.feedback), 5)
        self.assertIn("formatting", [f.status for f in run.feedback])

    def test_format_sd_times_out_when_the_pod_goes_silent(self):
        run = self.run_goal("format_sd", FormatSdGoal(timeout=3.0))
        self.assertTrue(wait_until(lambda: run.feedback and run.feedback[-1].status == "formatting", 3.0))
        self.sim.ok("silence 4")
        state, result = run.wait(10.0)
        self.assertEqual(state, GoalStatus.ABORTED, result.message)
        self.assertIn("timed out after 3.0 s", result.message)
        self.assertIn("last status 'formatting'", result.message)
        self.assertTrue(wait_until(lambda: self.joints.last_arrival() > time.time() - 0.5, 10.0))

    def test_format_sd_cancel_and_refusals(self):
        self.assert_cancel_lets_the_pod_carry_on("format_sd", FormatSdGoal(), 0.5)
        time.sleep(2.5)  # the format ends on its own
        # The pod's refusal comes back as the reason: no card.
        self.sim.ok("sd absent")
        try:
            state, result = self.run_goal("format_sd", FormatSdGoal()).wait(10.0)
            self.assertEqual(state, GoalStatus.ABORTED)
            self.assertIn("refused", result.message)
        finally:
            self.sim.ok("sd insert")
        self.assert_refused_without_sending("format_sd", FormatSdGoal(timeout=-2.0), "timeout")

    # --- precise_reshoot -------------------------------------------------------------------
    def test_precise_reshoot_takes_the_photo(self):
        goal = PreciseReshootGoal(lens=PreciseReshootGoal.LENS_VISIBLE, resolution=PreciseReshootGoal.RESOLUTION_5664x4248,
                                  zoom_ratio=2.0, folder="acts", name="reshoot")
        run = self.run_goal("precise_reshoot", goal)
        state, result = run.wait(20.0)
        self.assertEqual(state, GoalStatus.SUCCEEDED, result.message)
        self.assertIn("photo taken", result.message)
        self.assertIn("precise re-shoot in progress", [f.status for f in run.feedback])
        # The simulator took it at the goal's resolution (its byte 2).
        self.assertIn("acts/reshoot.jpg 5664x4248", self.sim.ok("photos"))

    def test_precise_reshoot_waits_for_the_zoom_times_out_and_cancels(self):
        # The pod shoots once the zoom is still: a long zoom keeps the re-shoot waiting.
        # The simulator's own state decides when the pod is idle: visible/status comes at 1 Hz, so
        # its latest message may predate a zoom that has just started.
        self.assertTrue(service("set_zoom", SetZoom)(ratio=1.0).success)
        self.assertTrue(self.sim.wait_idle(15.0), self.sim.ok("status"))
        self.assertTrue(service("set_zoom", SetZoom)(ratio=160.0).success)
        state, result = self.run_goal("precise_reshoot", PreciseReshootGoal(resolution=RES_4000x3000, zoom_ratio=1.0,
                                                                               timeout=0.5)).wait(5.0)
        self.assertEqual(state, GoalStatus.ABORTED, result.message)
        self.assertIn("timed out after 0.5 s", result.message)
        self.assertTrue(self.sim.wait_idle(30.0), self.sim.ok("status"))  # that photo is taken once the zoom stops
        # A re-shoot cancelled while it waits for a long zoom: the pod takes the photo later.
        self.assertTrue(service("set_zoom", SetZoom)(ratio=160.0).success)
        self.assertTrue(wait_until(lambda: self.sim.busy_with("zooming"), 5.0), self.sim.ok("status"))
        self.assert_cancel_lets_the_pod_carry_on("precise_reshoot", PreciseReshootGoal(resolution=RES_4000x3000), 0.3)
        self.assertTrue(self.sim.wait_idle(30.0), self.sim.ok("status"))

    def test_precise_reshoot_refuses_bad_goals(self):
        self.assert_refused_without_sending("precise_reshoot", PreciseReshootGoal(resolution=0x18), "resolution")
        self.assert_refused_without_sending("precise_reshoot", PreciseReshootGoal(resolution=RES_4000x3000, zoom_ratio=170.0),
                                            "zoom_ratio")
        self.assert_refused_without_sending("precise_reshoot", PreciseReshootGoal(resolution=RES_4000x3000, lens=9), "lens")
        self.assert_refused_without_sending("precise_reshoot",
                                            PreciseReshootGoal(resolution=RES_4000x3000, focal_length_mm=-1.0),
                                            "focal_length_mm")
        self.assert_refused_without_sending("precise_reshoot", PreciseReshootGoal(resolution=RES_4000x3000, name="n" * 33),
                                            "name")

    def test_precise_reshoot_in_video_mode_is_refused_with_the_reason(self):
        # A precise re-shoot is a photo request: in video mode the pod does not answer it (section
        # 3.2.4.1), so the goal is refused at once, naming the mode, with nothing sent.
        reconfigure = ReconfigureClient(name("driver"), timeout=10.0)
        self.assertEqual(reconfigure.update_configuration({"camera_mode": 1})["camera_mode"], 1)
        try:
            self.assert_refused_without_sending("precise_reshoot", PreciseReshootGoal(resolution=RES_4000x3000),
                                                "video mode")
        finally:
            reconfigure.update_configuration({"camera_mode": 0})

    # --- tf_upgrade ------------------------------------------------------------------------
    def test_tf_upgrade_times_out_cancels_and_succeeds(self):
        # The simulator's upgrade takes 10 s and refuses a second one meanwhile (busy).
        started = time.time()
        state, result = self.run_goal("tf_upgrade", TfUpgradeGoal(timeout=1.0)).wait(5.0)
        self.assertEqual(state, GoalStatus.ABORTED, result.message)
        self.assertIn("timed out after 1.0 s", result.message)
        self.assertIn("last status 'upgrading'", result.message)
        state, result = self.run_goal("tf_upgrade", TfUpgradeGoal()).wait(5.0)
        self.assertEqual(state, GoalStatus.ABORTED, result.message)
        self.assertIn("refused", result.message)
        self.assertTrue(self.sim.wait_idle(max(0.0, started + 20.0 - time.time())), self.sim.ok("status"))
        self.assert_cancel_lets_the_pod_carry_on("tf_upgrade", TfUpgradeGoal(), 1.5)
        self.assertTrue(self.sim.busy_with("upgrading"), "a cancelled goal stopped the pod's upgrade")
        self.assertTrue(self.sim.wait_idle(20.0), self.sim.ok("status"))
        run = self.run_goal("tf_upgrade", TfUpgradeGoal())
        state, result = run.wait(20.0)
        self.assertEqual(state, GoalStatus.SUCCEEDED, result.message)
        self.assertIn("upgrade succeeded", result.message)
        self.assert_rising_progress(run, 5)
        self.assert_refused_without_sending("tf_upgrade", TfUpgradeGoal(timeout=-1.0), "timeout")

    # --- gimbal/calibrate ------------------------------------------------------------------
    def test_calibrate_progress_timeout_cancel(self):
        run = self.run_goal("gimbal/calibrate", GimbalCalibrateGoal(kind=GimbalCalibrateGoal.DRIFT))  # 5 s
        state, result = run.wait(20.0)
        self.assertEqual(state, GoalStatus.SUCCEEDED, result.message)
        self.assertIn("drift calibration: done", result.message)
        self.assert_rising_progress(run, 3)
        started = time.time()
        state, result = self.run_goal("gimbal/calibrate",
                                      GimbalCalibrateGoal(kind=GimbalCalibrateGoal.LINEAR, timeout=1.0)).wait(5.0)
        self.assertEqual(state, GoalStatus.ABORTED, result.message)
        self.assertIn("timed out after 1.0 s", result.message)
        time.sleep(max(0.0, started + 9.0 - time.time()))  # the linear calibration takes 8 s
        self.assert_cancel_lets_the_pod_carry_on(
            "gimbal/calibrate", GimbalCalibrateGoal(kind=GimbalCalibrateGoal.ACCELEROMETER), 1.0)
        time.sleep(6.0)
        self.assert_refused_without_sending("gimbal/calibrate", GimbalCalibrateGoal(kind=5), "kind")

if __name__ == "__main__":
    rostest.rosrun(PKG, "actions", Actions, sys.argv)
