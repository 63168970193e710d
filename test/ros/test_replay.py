#!/usr/bin/python3
"""Replay: raw frames recorded from the simulator into a bag, played back through a second
driver in replay mode, regenerate the decoded topics message by message and bit for bit
(serialized bytes equal, recorded stamps included; only header.seq, which roscpp assigns per
publisher, is left out)."""
import io
import os
import subprocess
import sys
import tempfile
import time
import unittest

import rosbag
import rospy
import rostest
from geometry_msgs.msg import QuaternionStamped
from sensor_msgs.msg import JointState, NavSatFix, Range

from k40t_driver.msg import CameraStatus, Frame, GimbalStatus, ThermalStats, VisibleStatus
from k40t_test_support import Recorder, make_every_topic_flow, wait_until

PKG = "k40t_driver"
LIVE = "/k40t"
REPLAY = "/replay"
DECODED = {
    "joint_states": JointState, "gimbal/attitude": QuaternionStamped, "gimbal/status": GimbalStatus,
    "camera/status": CameraStatus, "visible/status": VisibleStatus, "thermal/stats": ThermalStats,
    "laser/range": Range, "laser/target": NavSatFix,
}


def serialized(msg):
    """The message's bytes, with header.seq zeroed: roscpp numbers the messages of each publisher
    itself (the replay driver's publishers start at 0), so seq is not part of what is regenerated."""
    msg.header.seq = 0
    buffer = io.BytesIO()
    msg.serialize(buffer)
    return buffer.getvalue()


class Replay(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_replay")
        cls.bag_path = os.path.join(tempfile.mkdtemp(prefix="k40t_replay_"), "raw.bag")

    def record_live(self, seconds):
        """Records live raw/rx and decoded topics into the bag; returns the decoded messages."""
        raw = Recorder(LIVE + "/raw/rx", Frame)
        decoded = {topic: Recorder(LIVE + "/" + topic, cls) for topic, cls in DECODED.items()}
        time.sleep(seconds)
        for r in [raw] + list(decoded.values()):
            r.close()
        with rosbag.Bag(self.bag_path, "w") as bag:
            for arrival, frame in raw.items:
                bag.write(LIVE + "/raw/rx", frame, rospy.Time.from_sec(arrival))
            for topic, r in decoded.items():
                for arrival, msg in r.items:
                    bag.write(LIVE + "/" + topic, msg, rospy.Time.from_sec(arrival))
        frames = [f for _, f in raw.items]
        return frames, {topic: [m for _, m in r.items] for topic, r in decoded.items()}

    def test_replay_regenerates_every_decoded_topic(self):
        self.assertTrue(Recorder(LIVE + "/joint_states", JointState).wait_for(3, timeout=20.0), "no live driver")
        publishers = make_every_topic_flow(LIVE)  # noqa: F841 (latched: kept alive)

        frames, recorded = self.record_live(8.0)
        self.assertGreater(len(frames), 150, "too few raw frames recorded")
        for topic, msgs in recorded.items():
            self.assertTrue(msgs, "nothing recorded on %s" % topic)

        replayed = {topic: Recorder(REPLAY + "/" + topic, cls) for topic, cls in DECODED.items()}
        time.sleep(1.0)  # subscriptions connect before the first frame is played
        # --delay: rosbag advertises, waits for the replay driver to connect, then plays.
        play = subprocess.run(["rosbag", "play", "--quiet", "--delay=1", "--topics", LIVE + "/raw/rx", "--bags=" + self.bag_path,
                               LIVE + "/raw/rx:=" + REPLAY + "/raw/rx"],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60)
        self.assertEqual(play.returncode, 0, play.stdout.decode(errors="replace"))
        time.sleep(1.0)

        for topic, recorder in replayed.items():
            got = [m for _, m in recorder.items]
            self.assertTrue(got, "replay mode published nothing on %s" % topic)
            # Compare where both recordings were listening: the raw frames' span, narrowed to the
            # span of this topic's live messages (its subscription may have connected later).
            live_stamps = [m.header.stamp for m in recorded[topic]]
            first = max(frames[0].stamp, min(live_stamps))
            last = min(frames[-1].stamp, max(live_stamps))
            live = {m.header.stamp: m for m in recorded[topic] if first <= m.header.stamp <= last}
            got_by_stamp = {m.header.stamp: m for m in got if first <= m.header.stamp <= last}
            self.assertEqual(len(got), len({m.header.stamp for m in got}), "%s: duplicate stamps in replay" % topic)
            missing = sorted(set(live) - set(got_by_stamp))
            extra = sorted(set(got_by_stamp) - set(live))
            self.assertFalse(missing, "%s: %d of %d recorded messages not regenerated" % (topic, len(missing), len(live)))
            self.assertFalse(extra, "%s: %d replayed messages never published live" % (topic, len(extra)))
            for stamp, msg in got_by_stamp.items():
                self.assertEqual(serialized(msg), serialized(live[stamp]), "%s at %s differs" % (topic, stamp))

if __name__ == "__main__":
    rostest.rosrun(PKG, "replay", Replay, sys.argv)
