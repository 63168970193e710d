#!/usr/bin/python3
"""`k40t bag` against launch/replay.launch: the raw frames of a live run on the simulated pod are
recorded into a bag; replay.launch plays that bag through a replay-mode driver (on a ROS master of
the test's own, because it runs in the recorded namespace /k40t, where the live driver is) while
`rosbag record` records everything it publishes; `k40t bag` decodes the same bag offline. The two
bags must hold the same topics and, topic by topic, the same messages in the same order: serialized
bytes equal, so header.seq, stamps and content included. Only /tf_static differs by design (live
it is stamped with the driver's start time): its transforms are compared without stamps.
The error cases: a bag without raw/rx and a truncated bag are reported and skipped, the next bag is
still decoded, and the exit code is 1. The exports (--jsonl, --csv) are checked against the frames."""
import csv
import glob
import io
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
import unittest

import rosbag
import rosgraph
import rospkg
import rospy
import rostest

from k40t_driver.msg import Frame
from k40t_test_support import Recorder, make_every_topic_flow, wait_until

PKG = "k40t_driver"
NS = "/k40t"
CONFIG = os.path.join(rospkg.RosPack().get_path(PKG), "config", "k40t.yaml")
# What replay.launch's processes publish that is not decoded from frames: the played input, the
# log, diagnostics (wall-clock driven) and the driver's dynamic_reconfigure descriptions.
NOT_DECODED = ("/rosout", "/rosout_agg", "/diagnostics", NS + "/raw/rx", NS + "/raw/tx")


def serialized(msg):
    buffer = io.BytesIO()
    msg.serialize(buffer)
    return buffer.getvalue()


def read_bag(path):
    """{topic: [message, ...]} in bag order."""
    topics = {}
    with rosbag.Bag(path) as bag:
        for topic, msg, _ in bag.read_messages():
            topics.setdefault(topic, []).append(msg)
    return topics


def decoded_topics(topics):
    return {t: m for t, m in topics.items()
            if t not in NOT_DECODED and not t.endswith("/parameter_descriptions")
            and not t.endswith("/parameter_updates")}


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def k40t_bag(*args):
    """Runs `k40t bag ARGS` as a user would (rosrun finds the k40t tool, which runs k40t_bag)."""
    return subprocess.run(["rosrun", PKG, "k40t", "bag"] + list(args), stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, timeout=120, universal_newlines=True)


class BagDecode(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_bag_decode")
        cls.dir = tempfile.mkdtemp(prefix="k40t_bag_test_")
        cls.raw = os.path.join(cls.dir, "flight.bag")
        cls.frames = cls.record_live(8.0)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    @classmethod
    def record_live(cls, seconds):
        """raw/rx and raw/tx of the live driver into cls.raw; returns the rx frames."""
        if not Recorder(NS + "/joint_states", rospy.AnyMsg).wait_for(3, timeout=20.0):
            raise AssertionError("no live driver")
        cls.publishers = make_every_topic_flow(NS)
        rx = Recorder(NS + "/raw/rx", Frame)
        tx = Recorder(NS + "/raw/tx", Frame)
        time.sleep(seconds)
        rx.close()
        tx.close()
        with rosbag.Bag(cls.raw, "w") as bag:
            for arrival, frame in rx.items:
                bag.write(NS + "/raw/rx", frame, rospy.Time.from_sec(arrival))
            for arrival, frame in tx.items:
                bag.write(NS + "/raw/tx", frame, rospy.Time.from_sec(arrival))
            # A frame-less message 2 s after the last frame: replay.launch ends when `rosbag play`
            # does, and play then waits for it, so every real frame has long reached the replay
            # driver. It decodes to nothing on both paths.
            last = rx.items[-1][0]
            end = Frame()
            end.direction = Frame.RX
            end.stamp = rospy.Time.from_sec(last + 2.0)
            bag.write(NS + "/raw/rx", end, rospy.Time.from_sec(last + 2.0))
        cls.tx_count = len(tx.items)
        return [f for _, f in rx.items]

    def replay_launch(self, output):
        """Records, with `rosbag record -a`, what replay.launch publishes from cls.raw."""
        port = free_port()
        env = dict(os.environ, ROS_MASTER_URI="http://127.0.0.1:%d" % port)
        log = open(os.path.join(self.dir, "replay.log"), "w")
        processes = []

        def start(*cmd):
            processes.append(subprocess.Popen(list(cmd), env=env, stdout=log, stderr=subprocess.STDOUT))
            return processes[-1]

        try:
            start("roscore", "-p", str(port))
            master = rosgraph.Master("/test_bag_decode", master_uri=env["ROS_MASTER_URI"])
            self.assertTrue(wait_until(lambda: self.online(master), 20.0), "no master for the replay")
            record = start("rosbag", "record", "--quiet", "-a", "-O", output)
            wait_until(lambda: self.online_node(master, "/record"), 10.0)
            launch = start("roslaunch", "--wait", PKG, "replay.launch", "bag:=" + self.raw,
                           "config:=" + CONFIG, "play_delay:=3")
            self.assertEqual(launch.wait(timeout=120), 0, "replay.launch failed: see " + log.name)
            time.sleep(1.0)
            record.send_signal(signal.SIGINT)
            record.wait(timeout=20)
        finally:
            for p in reversed(processes):
                if p.poll() is None:
                    p.send_signal(signal.SIGINT)
                    try:
                        p.wait(timeout=20)
                    except subprocess.TimeoutExpired:
                        p.kill()
            log.close()

    @staticmethod
    def online(master):
        try:
            master.getPid()
            return True
        except Exception:  # not up yet
            return False

    @staticmethod
    def online_node(master, prefix):
        try:
            return any(n.startswith(prefix) for _, nodes in master.getSystemState()[0] for n in nodes)
        except Exception:  # not up yet
            return False

    def test_decoded_bag_equals_replay_launch(self):
        replayed_path = os.path.join(self.dir, "replayed.bag")
        decoded_path = os.path.join(self.dir, "decoded.bag")
        self.replay_launch(replayed_path)
        run = k40t_bag(self.raw, "--output", decoded_path, "--config", CONFIG)
        self.assertEqual(run.returncode, 0, run.stderr)

        replayed = decoded_topics(read_bag(replayed_path))
        decoded = read_bag(decoded_path)
        sys.stderr.write("replayed: %s\ndecoded: %s\n" % ({t: len(m) for t, m in read_bag(replayed_path).items()},
                                                       {t: len(m) for t, m in decoded.items()}))
        self.assertEqual(sorted(decoded), sorted(replayed), "decoded topics differ from the replay's")
        for topic in [NS + "/joint_states", NS + "/gimbal/attitude", NS + "/gimbal/status", NS + "/camera/status",
                      NS + "/visible/status", NS + "/thermal/stats", NS + "/laser/range", NS + "/laser/target", "/tf"]:
            self.assertIn(topic, decoded, "nothing decoded on " + topic)
        for topic, messages in decoded.items():
            got = replayed[topic]
            if topic == "/tf_static":
                for msgs in (got, messages):
                    for m in msgs:
                        for t in m.transforms:
                            t.header.stamp = rospy.Time()
            self.assertEqual(len(messages), len(got), "%s: %d decoded, %d replayed" % (topic, len(messages), len(got)))
            for i, (mine, theirs) in enumerate(zip(messages, got)):
                self.assertEqual(serialized(mine), serialized(theirs), "%s message %d differs:\n%s\n---\n%s" % (topic, i, mine, theirs))
        # The stamps are the frames' and seq counts from 0, as a live recording has them.
        joints = decoded[NS + "/joint_states"]
        self.assertEqual([m.header.seq for m in joints], list(range(len(joints))))
        frame_stamps = {f.stamp for f in self.frames}
        self.assertTrue(all(m.header.stamp in frame_stamps for m in joints))

    def test_bad_bags_are_reported_and_the_next_one_is_decoded(self):
        no_raw = os.path.join(self.dir, "no_raw.bag")
        with rosbag.Bag(no_raw, "w") as bag:
            bag.write(NS + "/joint_states", self.frames[0], rospy.Time(1))  # a Frame, on another topic
        truncated = os.path.join(self.dir, "truncated.bag")
        with open(self.raw, "rb") as f:
            data = f.read()
        with open(truncated, "wb") as f:
            f.write(data[: len(data) // 2])
        not_a_bag = os.path.join(self.dir, "not_a_bag.bag")
        with open(not_a_bag, "w") as f:
            f.write("hello\n")
        out = os.path.join(self.dir, "out")
        os.mkdir(out)
        run = k40t_bag(no_raw, truncated, not_a_bag, self.raw, "--out-dir", out, "--config", CONFIG)
        self.assertEqual(run.returncode, 1, run.stderr)
        self.assertIn("no_raw.bag: no raw/rx topic", run.stderr)
        self.assertIn("truncated.bag: cannot read the bag", run.stderr)
        self.assertIn("not_a_bag.bag: cannot read the bag", run.stderr)
        self.assertIn("3 of 4 bags failed", run.stderr)
        self.assertEqual(sorted(os.listdir(out)), ["flight.decoded.bag"], "a failed bag left an output")
        # The good bag, after three bad ones, decodes as it does alone.
        alone = os.path.join(self.dir, "alone.bag")
        self.assertEqual(k40t_bag(self.raw, "--output", alone, "--config", CONFIG).returncode, 0)
        after_errors = read_bag(os.path.join(out, "flight.decoded.bag"))
        self.assertTrue(after_errors.get(NS + "/joint_states"), "the good bag was not decoded")
        self.assertEqual({t: [serialized(m) for m in ms] for t, ms in after_errors.items()},
                         {t: [serialized(m) for m in ms] for t, ms in read_bag(alone).items()})

    def test_exports(self):
        jsonl = os.path.join(self.dir, "frames.jsonl")
        csv_dir = os.path.join(self.dir, "csv")
        run = k40t_bag(self.raw, "--output", os.path.join(self.dir, "export.bag"), "--config", CONFIG,
                       "--jsonl", jsonl, "--csv", csv_dir)
        self.assertEqual(run.returncode, 0, run.stderr)
        with open(jsonl) as f:
            lines = [json.loads(line) for line in f]
        rx = [l for l in lines if l["topic"] == NS + "/raw/rx"]
        self.assertEqual(len(rx), len([f for f in self.frames if f.data]))
        self.assertEqual(len(lines) - len(rx), self.tx_count)
        self.assertEqual([l["stamp_ns"] for l in rx], [f.stamp.to_nsec() for f in self.frames if f.data])
        attitude = [l for l in rx if l["frame"]["id"] == "0x000002"]
        self.assertTrue(attitude and all("yaw_deg" in l["frame"]["fields"] for l in attitude))
        [attitude_csv] = glob.glob(os.path.join(csv_dir, "0x000002_*.csv"))
        with open(attitude_csv) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual(len(rows), len(attitude))
        self.assertEqual([int(r["stamp_ns"]) for r in rows], [l["stamp_ns"] for l in attitude])

    def test_two_pods_in_one_bag_with_their_frame_prefixes(self):
        two = os.path.join(self.dir, "two_pods.bag")
        with rosbag.Bag(self.raw) as raw, rosbag.Bag(two, "w") as bag:
            for topic, msg, t in raw.read_messages(raw=True):
                for ns in ("/pod_a", "/pod_b"):
                    bag.write(topic.replace(NS, ns, 1), msg, t, raw=True)
        run = k40t_bag(two, "--output", os.path.join(self.dir, "two.decoded.bag"), "--config", CONFIG,
                       "--frame-prefix", "pod_a=pod_a_,/pod_b/=pod_b_")
        self.assertEqual(run.returncode, 0, run.stderr)
        decoded = read_bag(os.path.join(self.dir, "two.decoded.bag"))
        alone = os.path.join(self.dir, "one.decoded.bag")
        self.assertEqual(k40t_bag(self.raw, "--output", alone, "--config", CONFIG).returncode, 0)
        one = read_bag(alone)
        for ns in ("/pod_a", "/pod_b"):
            joints = decoded[ns + "/joint_states"]
            # Each pod is a driver of its own: its own seq from 0, its own frame ids, the same stamps.
            self.assertEqual([m.header.seq for m in joints], list(range(len(one[NS + "/joint_states"]))))
            self.assertEqual([m.header.stamp for m in joints], [m.header.stamp for m in one[NS + "/joint_states"]])
            self.assertTrue(all(n.startswith(ns[1:] + "_") for m in joints for n in m.name), joints[0].name)
            self.assertEqual(decoded[ns + "/thermal/stats"][0].header.frame_id, ns[1:] + "_thermal_optical_frame")
        children = {t.child_frame_id for m in decoded["/tf"] for t in m.transforms}
        self.assertEqual(children, {"pod_a_yaw_link", "pod_a_roll_link", "pod_a_pitch_link",
                                    "pod_b_yaw_link", "pod_b_roll_link", "pod_b_pitch_link"})
        twice = k40t_bag(two, "--frame-prefix", "a=x_,/a=y_")
        self.assertEqual(twice.returncode, 2)
        self.assertIn("--frame-prefix names /a twice", twice.stderr)


if __name__ == "__main__":
    rostest.rosrun(PKG, "bag_decode", BagDecode, sys.argv)
