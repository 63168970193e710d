#!/usr/bin/python3
"""Two simulated pods under one master (launch/two_pods.launch through two_pods.test): every
topic, service, parameter, node and diagnostic status of a pod lies in its own namespace (but for
the shared /tf, /tf_static, /diagnostics, /rosout) and the two pods mirror each other; every TF
frame of a pod carries its prefix and has one publisher, and both pods hang in one tree below the
vehicle frame at their mounts; each pod's telemetry and video arrive, named after its prefix; a
command to one pod moves, zooms and recolours that pod only (its simulator, its telemetry), and
the other pod's driver sends nothing for it."""
import math
import os
import subprocess
import sys
import threading
import time
import unittest
import xml.etree.ElementTree as ET

import rospy
import rostest
import tf2_ros
from dynamic_reconfigure.client import Client as ReconfigureClient
from diagnostic_msgs.msg import DiagnosticArray
from sensor_msgs.msg import CameraInfo, Image
from tf2_msgs.msg import TFMessage

from k40t_driver.srv import SetAngle, SetPalette, SetZoom
from k40t_test_support import Recorder, wait_until
from two_pods_support import SHARED_TOPICS, Pod, wait_for_graph, wait_for_values

PKG = "k40t_driver"
URDF_SCRIPT = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                           "scripts", "k40t_urdf.py")
# The master's own parameters (roslaunch's are under /roslaunch/).
GLOBAL_PARAMS = {"/rosdistro", "/rosversion", "/run_id"}
# Commands of test_command_to_one_pod_leaves_the_other_alone, by message id.
SET_ANGLE, SET_ZOOM, SET_PALETTE = 0x000012, 0x000304, 0x000106


class Origins:
    """Who published what: TF edges (child -> {(parent, publisher)}) and diagnostic status names
    (name -> {publisher}), from the messages' connection headers."""

    def __init__(self):
        self.lock = threading.Lock()
        self.tf = {}
        self.diagnostics = {}
        self.subs = [rospy.Subscriber(t, TFMessage, self.on_tf, queue_size=100) for t in ("/tf", "/tf_static")]
        self.subs.append(rospy.Subscriber("/diagnostics", DiagnosticArray, self.on_diagnostics, queue_size=100))

    def on_tf(self, msg):
        caller = msg._connection_header["callerid"]
        with self.lock:
            for t in msg.transforms:
                self.tf.setdefault(t.child_frame_id, set()).add((t.header.frame_id, caller))

    def on_diagnostics(self, msg):
        caller = msg._connection_header["callerid"]
        with self.lock:
            for status in msg.status:
                self.diagnostics.setdefault(status.name, set()).add(caller)

    def tf_edges(self):
        with self.lock:
            return {child: set(edges) for child, edges in self.tf.items()}

    def diagnostic_names(self):
        with self.lock:
            return {name: set(callers) for name, callers in self.diagnostics.items()}


class TwoPods(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_two_pods")
        cls.vehicle = rospy.get_param("~vehicle_frame")
        cls.pods = [Pod(**p) for p in rospy.get_param("~pods")]
        cls.origins = Origins()
        cls.tf_buffer = tf2_ros.Buffer()
        cls.tf_listener = tf2_ros.TransformListener(cls.tf_buffer)
        # Both drivers are up once attitude reports flow (generous: two pods with video start on
        # a loaded machine).
        for pod in cls.pods:
            assert pod.joints.wait_for(5, timeout=90.0), "no joint_states from %s" % pod

    def other(self, pod):
        return [p for p in self.pods if p is not pod][0]

    def owner(self, name):
        owners = [p for p in self.pods if p.owns(name)]
        return owners[0] if owners else None

    # --- telemetry and video ---------------------------------------------------------------
    def test_each_pods_telemetry_arrives_under_its_names(self):
        for pod in self.pods:
            joints = pod.joints.latest()
            self.assertEqual(list(joints.name), [pod.prefix + j for j in ("yaw_joint", "roll_joint", "pitch_joint")])
            for topic, recorder in pod.status.items():
                self.assertTrue(recorder.wait_for(1, timeout=30.0), "no %s from %s" % (topic, pod))
            self.assertEqual(pod.status["thermal/stats"].latest().header.frame_id,
                             pod.prefix + "thermal_optical_frame")

    def test_each_pods_video_arrives_from_its_own_stream(self):
        images = {pod.ns: Recorder(pod.name("image_raw"), Image, keep=3) for pod in self.pods}
        infos = {pod.ns: Recorder(pod.name("camera_info"), CameraInfo, keep=3) for pod in self.pods}
        try:
            for pod in self.pods:
                got = images[pod.ns].wait_for(3, timeout=60.0)
                self.assertGreaterEqual(len(got), 3, "%s: %d images" % (pod, len(got)))
                image = got[-1]
                self.assertEqual((image.width, image.height), (1920, 1080), "%s's visible stream" % pod)
                self.assertTrue(image.header.frame_id.startswith(pod.prefix),
                                "%s image in %s" % (pod, image.header.frame_id))
                info = infos[pod.ns].wait_for(1, timeout=10.0)
                self.assertTrue(info, "no camera_info from %s" % pod)
                self.assertEqual(info[-1].header.frame_id, image.header.frame_id)
                url = rospy.get_param(pod.name("video/url"))
                self.assertIn(":%d/" % pod.rtsp_port, url, "%s reads %s" % (pod, url))
            # The first pod's camera to thermal: its own stream turns 640x512, the other's does not
            # (a video node reading the other pod's stream, or both one, would show it).
            switched, other = self.pods
            since = time.time()
            ReconfigureClient(switched.name("driver"), timeout=30.0).update_configuration({"image_mode": 0})
            thermal = images[switched.ns].wait_for_match(lambda m: (m.width, m.height) == (640, 512), 30.0, since)
            self.assertIsNotNone(thermal, "%s's stream never turned thermal" % switched)
            self.assertEqual(thermal.header.frame_id, switched.prefix + "thermal_optical_frame")
            after = images[other.ns].wait_for(3, timeout=30.0, since=time.time())
            self.assertTrue(after, "no images from %s" % other)
            self.assertEqual({(m.width, m.height) for m in after}, {(1920, 1080)}, "%s's stream changed" % other)
        finally:
            for recorder in list(images.values()) + list(infos.values()):
                recorder.close()  # the nodelets stop converting frames nobody takes

    # --- names -----------------------------------------------------------------------------
    def test_no_topic_service_parameter_or_node_clash(self):
        graph = wait_for_graph(self.pods, timeout=60.0)
        me = rospy.get_name()
        infrastructure = {me, "/rosout", "/diagnostic_aggregator"}
        for node in graph.nodes:
            self.assertTrue(self.owner(node) or node in infrastructure, "node %s belongs to no pod" % node)
        for kind, table in (("topic", graph.topic_nodes), ("service", graph.service_nodes)):
            for name, nodes in table.items():
                pods = {self.owner(n) for n in nodes} - {None}
                if name in SHARED_TOPICS:
                    continue
                self.assertLessEqual(len(pods), 1, "%s %s used by both pods: %s" % (kind, name, sorted(nodes)))
                for pod in pods:
                    self.assertTrue(pod.owns(name), "%s %s of %s's node(s) %s is outside %s/" % (
                        kind, name, pod, sorted(nodes), pod.ns))
        for param in graph.params:
            self.assertTrue(self.owner(param) or param in GLOBAL_PARAMS or param.startswith("/roslaunch/")
                            or any(param.startswith(n + "/") for n in infrastructure),
                            "parameter %s belongs to no pod" % param)
        a, b = self.pods
        for what, table in (("topics", graph.topic_nodes), ("services", graph.service_nodes),
                            ("parameters", graph.params)):
            self.assertEqual(a.relative(table), b.relative(table), "the pods' %s differ" % what)
        for pod in self.pods:
            for name in ("robot_description", "driver/frame_prefix", "driver/joint_prefix", "video/frame_prefix"):
                self.assertIn(pod.name(name), graph.params)
            self.assertEqual(rospy.get_param(pod.name("driver/frame_prefix")), pod.prefix)
            self.assertEqual(rospy.get_param(pod.name("video/frame_prefix")), pod.prefix)

    def test_diagnostic_statuses_are_named_after_each_pods_nodes(self):
        for pod in self.pods:
            ns = pod.ns.lstrip("/")
            wanted = [ns + "/driver: link", ns + "/video: video stream"]
            self.assertTrue(wait_until(lambda: all(w in self.origins.diagnostic_names() for w in wanted), 30.0),
                            "missing %s in %s" % (wanted, sorted(self.origins.diagnostic_names())))
        for name, callers in self.origins.diagnostic_names().items():
            pods = {self.owner(c) for c in callers} - {None}
            self.assertEqual(len(pods), 1, "status '%s' published by %s" % (name, sorted(callers)))
            pod = pods.pop()
            self.assertTrue(name.startswith(pod.ns.lstrip("/") + "/"), "%s publishes status '%s'" % (pod, name))

    # --- TF ----------------------------------------------------------------------------------
    def test_tf_frames_carry_their_pods_prefix_and_form_one_tree(self):
        wanted = [f for pod in self.pods for f in pod.frames()]  # each a child on TF
        edges = wait_for_values(self.origins.tf_edges, lambda e: all(f in e for f in wanted), 30.0)
        self.assertEqual(sorted(set(wanted) - set(edges)), [], "frames never on TF")
        for child, sources in edges.items():
            self.assertEqual(len(sources), 1, "%s published as %s" % (child, sorted(sources)))
            parent, caller = next(iter(sources))
            pod = self.owner(caller)
            self.assertIsNotNone(pod, "%s -> %s published by %s" % (parent, child, caller))
            self.assertTrue(child.startswith(pod.prefix), "%s publishes %s" % (pod, child))
            self.assertTrue(parent.startswith(pod.prefix) or parent == self.vehicle,
                            "%s publishes %s -> %s" % (pod, parent, child))
        for pod in self.pods:
            for frame in pod.frames():
                self.assertTrue(self.tf_buffer.can_transform(self.vehicle, frame, rospy.Time(0), rospy.Duration(30.0)),
                                "%s not connected to %s" % (frame, self.vehicle))
            mount = self.tf_buffer.lookup_transform(self.vehicle, pod.prefix + "base_link", rospy.Time(0))
            t = mount.transform.translation
            for got, want in zip((t.x, t.y, t.z), pod.mount_xyz):
                self.assertAlmostEqual(got, want, places=6, msg="%s mounted at %s" % (pod, (t.x, t.y, t.z)))
        a, b = self.pods
        self.assertTrue(self.tf_buffer.can_transform(a.prefix + "tele_optical_frame", b.prefix + "laser_frame",
                                                     rospy.Time(0), rospy.Duration(10.0)))

    def test_each_pods_robot_description_carries_its_prefix(self):
        for pod in self.pods:
            root = ET.fromstring(rospy.get_param(pod.name("robot_description")))
            self.assertEqual({link.get("name") for link in root.findall("link")}, set(pod.frames()) | {self.vehicle})
            joints = [joint.get("name") for joint in root.findall("joint")]
            self.assertEqual([j for j in joints if not j.startswith(pod.prefix)], [], "%s's URDF" % pod)

    def test_urdf_generator_refuses_bad_names_and_numbers(self):
        for args, reason in ((["--prefix", "pod a/"], "may hold only"),
                             (["--mount-parent", "base_link", "--mount-xyz", "1 2"], "three numbers"),
                             (["--mount-parent", "base_link", "--mount-rpy", "0 0 x"], "three numbers"),
                             (["--prefix", "pod_a_", "--mount-parent", "pod_a_plate"], "own prefix")):
            run = subprocess.run([URDF_SCRIPT] + args, capture_output=True, text=True, timeout=30)
            self.assertEqual(run.returncode, 2, "k40t_urdf.py %s exited %d" % (args, run.returncode))
            self.assertIn(reason, run.stderr, "k40t_urdf.py %s" % args)
            self.assertEqual(run.stdout, "", "k40t_urdf.py %s printed a URDF" % args)

    # --- commands ----------------------------------------------------------------------------
    def test_command_to_one_pod_leaves_the_other_alone(self):
        # Each pod in turn gets a gimbal angle, a zoom and a palette of its own.
        targets = {self.pods[0].ns: (0.35, 0.5, 4.0, 7), self.pods[1].ns: (-0.2, -0.6, 2.5, 12)}
        for pod in self.pods:
            self.command_one_pod(pod, self.other(pod), *targets[pod.ns])

    def command_one_pod(self, pod, other, pitch, yaw, zoom, palette):
        other_sim = wait_for_values(other.sim_state_at_rest, lambda state: state is not None, 30.0)
        self.assertIsNotNone(other_sim, "%s never came to rest" % other)
        other_palette = other.palette()
        # joint_states order: yaw, roll, pitch (REP 103 signs, the opposite of the pod's).
        other_joints = [-math.radians(other_sim[0]), 0.0, -math.radians(other_sim[1])]
        self.assertNotEqual(other_palette, palette, "pick a palette %s does not hold" % other)
        since = time.time()
        pod.call("gimbal/set_angle", SetAngle, pitch=pitch, yaw=yaw)
        pod.call("set_zoom", SetZoom, ratio=zoom)
        pod.call("set_palette", SetPalette, palette=palette)

        # The commanded pod gets there: its simulator (pod signs: yaw right and pitch up positive,
        # the opposite of REP 103) and its joint_states.
        # It must be at rest before the other pod is looked at: the angles go out in 0.01 deg and the
        # zoom in 0.1x steps, and two readings apart equal mean it stopped there.
        want = (-math.degrees(yaw), -math.degrees(pitch), zoom)
        def there(state):
            return state is not None and all(abs(g - w) < 0.05 for g, w in zip(state, want))

        state = wait_for_values(pod.sim_state_at_rest, there, 60.0)
        self.assertTrue(there(state), "%s's simulator at %s, commanded %s" % (pod, pod.sim_state(), want))
        moved = pod.joints.wait_for_match(
            lambda m: abs(m.position[0] - yaw) < 0.01 and abs(m.position[2] - pitch) < 0.01, 30.0, since)
        self.assertIsNotNone(moved, "%s's joint_states at %s" % (pod, pod.joints.latest().position))
        self.assertEqual(pod.palette(), palette)

        # The other pod did not move, zoom or change palette, and its driver sent none of it.
        self.assertEqual(other.sim_state(), other_sim, "%s changed with %s's command" % (other, pod))
        self.assertEqual(other.palette(), other_palette)
        for m in other.joints.messages(since):
            for got, before in zip(m.position, other_joints):
                self.assertAlmostEqual(got, before, delta=0.005, msg="%s's joints moved: %s" % (other, m.position))
        self.assertTrue(other.joints.messages(since), "%s's joint_states stopped" % other)
        sent = set(other.sent_ids(since)) & {SET_ANGLE, SET_ZOOM, SET_PALETTE}
        self.assertEqual(sent, set(), "%s's driver sent %s" % (other, ["0x%06X" % i for i in sent]))


if __name__ == "__main__":
    rostest.rosrun(PKG, "two_pods", TwoPods, sys.argv)
