"""One pod of test_two_pods.py (launch/two_pods.launch): its namespace and frame prefix, the
simulator behind it, its telemetry, and the ROS graph seen from the master. Not a test itself."""
import re
import time

import rosgraph
import rospy
from sensor_msgs.msg import JointState

from k40t_driver.msg import CameraStatus, Frame, GimbalStatus, ThermalStats, VisibleStatus
from k40t_driver.srv import Send
from k40t_test_support import Recorder, SimControl, wait_until

# What every pod shares with the rest of the system: TF, diagnostics and logging.
SHARED_TOPICS = {"/tf", "/tf_static", "/diagnostics", "/rosout"}
# Each pod's frames, after its prefix (urdf/k40t.urdf).
POD_FRAMES = ["base_link", "yaw_link", "roll_link", "pitch_link", "tele_optical_frame",
              "wide_optical_frame", "thermal_optical_frame", "laser_frame"]
# The nodes each pod runs: its manager, the nodelets' loaders and robot_state_publisher.
POD_NODES = ["manager", "driver", "video", "robot_state_publisher"]
SIM_STATE = re.compile(r"\byaw (\S+) pitch (\S+) zoom (\S+)x ")


class Pod:
    def __init__(self, ns, prefix, control, rtsp_port, mount_xyz):
        self.ns = "/" + ns.strip("/")
        self.prefix = prefix
        self.sim = SimControl(control)
        self.rtsp_port = int(rtsp_port)
        self.mount_xyz = [float(v) for v in str(mount_xyz).split()]
        self.joints = Recorder(self.name("joint_states"), JointState)
        self.raw_tx = Recorder(self.name("raw/tx"), Frame)
        self.status = {
            "gimbal/status": Recorder(self.name("gimbal/status"), GimbalStatus),
            "camera/status": Recorder(self.name("camera/status"), CameraStatus),
            "visible/status": Recorder(self.name("visible/status"), VisibleStatus),
            "thermal/stats": Recorder(self.name("thermal/stats"), ThermalStats),
        }

    def __repr__(self):
        return self.ns

    def name(self, relative):
        return self.ns + "/" + relative

    def owns(self, name):
        """Whether a graph name (topic, service, parameter, node) lies in this pod's namespace."""
        return name.startswith(self.ns + "/")

    def relative(self, names):
        return {n[len(self.ns) + 1:] for n in names if self.owns(n)}

    def frames(self):
        return [self.prefix + f for f in POD_FRAMES]

    def call(self, relative, srv_type, timeout=30.0, **args):
        """Calls a service of this pod's driver; fails the test unless it succeeds."""
        rospy.wait_for_service(self.name(relative), timeout=timeout)
        response = rospy.ServiceProxy(self.name(relative), srv_type)(**args)
        if not response.success:
            raise AssertionError("%s(%s) failed: %s" % (self.name(relative), args, response.message))
        return response

    def sim_state(self):
        """(yaw deg, pitch deg, zoom) as the simulated pod holds them (its control socket)."""
        reply = self.sim.ok("status")
        match = SIM_STATE.search(reply)
        if not match:
            raise AssertionError("no angles and zoom in the simulator's status: " + reply)
        return tuple(float(v) for v in match.groups())

    def sim_state_at_rest(self, interval=0.3):
        """sim_state() if it did not change over `interval` (s), else None (still moving)."""
        before = self.sim_state()
        time.sleep(interval)
        after = self.sim_state()
        return after if after == before else None

    def palette(self):
        """The palette the pod itself reports (0x000100 read thermal settings, ACK byte 3)."""
        return self.call("send", Send, id=0x000100, payload=[1, 0]).ack[2]

    def sent_ids(self, since):
        """Message ids of the frames this pod's driver wrote after `since` (raw/tx)."""
        return [f.data[7] | f.data[8] << 8 | f.data[9] << 16 for f in self.raw_tx.messages(since)]


class Graph:
    """The master's view: nodes, topics (published or subscribed), services and parameters."""

    def __init__(self):
        master = rosgraph.Master(rospy.get_name())
        publishers, subscribers, services = master.getSystemState()
        self.topic_nodes = {}
        for name, nodes in publishers + subscribers:
            self.topic_nodes.setdefault(name, set()).update(nodes)
        self.service_nodes = {name: set(nodes) for name, nodes in services}
        self.params = set(master.getParamNames())
        self.nodes = set()
        for nodes in list(self.topic_nodes.values()) + list(self.service_nodes.values()):
            self.nodes |= nodes


def wait_for_graph(pods, timeout):
    """The graph once every pod's nodes are up and the pods' names mirror each other (a pod that
    is still advertising would look like a missing name), or the last one seen."""
    graph = [Graph()]

    def settled():
        graph[0] = Graph()
        g = graph[0]
        for pod in pods:
            if not all(pod.name(n) in g.nodes for n in POD_NODES):
                return False
        first = pods[0]
        return all(pod.relative(g.topic_nodes) == first.relative(g.topic_nodes)
                   and pod.relative(g.service_nodes) == first.relative(g.service_nodes)
                   and pod.relative(g.params) == first.relative(g.params) for pod in pods[1:])

    wait_until(settled, timeout, step=0.5)
    return graph[0]


def wait_for_values(read, predicate, timeout, step=0.2):
    """Polls read() until predicate(value) holds or timeout (s) passes; returns the last value."""
    deadline = time.time() + timeout
    value = read()
    while not predicate(value) and time.time() < deadline and not rospy.is_shutdown():
        time.sleep(step)
        value = read()
    return value
