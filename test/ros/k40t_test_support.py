"""Helpers shared by the rostest nodes of test/ros: the simulator's control socket, topic
recorders with rates, diagnostics, service calls with waiting. Imported by the test scripts
(which run from this directory); not a test itself."""
import socket
import threading
import time

import rospy
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from sensor_msgs.msg import JointState

DRIVER_NS = "/k40t"


def name(relative):
    """A topic or service name in the driver's namespace."""
    return DRIVER_NS + "/" + relative


def wait_until(predicate, timeout, step=0.02):
    """Polls predicate() until it is true or timeout (s) passes; returns its last value."""
    deadline = time.time() + timeout
    value = predicate()
    while not value and time.time() < deadline and not rospy.is_shutdown():
        time.sleep(step)
        value = predicate()
    return value


def reply_field(reply, key):
    """The word after `key` in a reply line of a simulator's control socket: k40t_sim's `status`
    ('ok link ... | t 12.5 s yaw 12.3 pitch -4 zoom 2x ... shooting no ...') or `truth`
    ('... heading 90 ...'); the first place `key` stands as a word, '|' being no word. Raises
    AssertionError, naming the key and quoting the line, when the key is not there."""
    words = reply.replace("|", " ").split()
    for i, word in enumerate(words[:-1]):
        if word == key:
            return words[i + 1]
    raise AssertionError("no '%s' in the simulator's reply: %s" % (key, reply))


def reply_number(reply, key):
    """The number after `key` in a reply line (see reply_field); a zoom's '2x' reads 2.0."""
    return float(reply_field(reply, key).rstrip("x"))


class SimControl:
    """Client of k40t_sim's control socket (--control unix:PATH): one command, one reply line."""

    def __init__(self, path):
        self.path = path

    def __call__(self, line, timeout=5.0):
        deadline = time.time() + timeout
        while True:
            try:
                with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as s:
                    s.settimeout(timeout)
                    s.connect(self.path)
                    s.sendall((line + "\n").encode())
                    reply = b""
                    while not reply.endswith(b"\n"):
                        chunk = s.recv(4096)
                        if not chunk:
                            break
                        reply += chunk
                    return reply.decode().strip()
            except (FileNotFoundError, ConnectionRefusedError):
                if time.time() > deadline:
                    raise
                time.sleep(0.1)

    def ok(self, line):
        reply = self(line)
        if not reply.startswith("ok"):
            raise AssertionError("simulator refused '%s': %s" % (line, reply))
        return reply

    def field(self, key, command="status"):
        """The word after `key` in the reply to `command` (see reply_field)."""
        return reply_field(self.ok(command), key)

    def number(self, key, command="status"):
        """The number after `key` in the reply to `command` (see reply_number)."""
        return reply_number(self.ok(command), key)

    def busy_with(self, activity):
        """True while the simulated pod is `activity` ("shooting", "zooming" or "upgrading"), from
        its `status` line: the pod's own state, not a status topic that may be a second old."""
        return self.field(activity) == "yes"

    def wait_idle(self, timeout):
        """Waits until the pod neither shoots, zooms nor upgrades; False on timeout."""
        return wait_until(lambda: not any(self.busy_with(a) for a in ("shooting", "zooming", "upgrading")), timeout)


class Recorder:
    """Keeps every message of a topic with its arrival time (wall clock)."""

    def __init__(self, topic, msg_type, keep=100000):
        self.topic = topic
        self.keep = keep
        self.lock = threading.Lock()
        self.items = []  # (arrival, msg)
        self.sub = rospy.Subscriber(topic, msg_type, self._on_msg, queue_size=1000, tcp_nodelay=True)

    def _on_msg(self, msg):
        with self.lock:
            self.items.append((time.time(), msg))
            if len(self.items) > self.keep:
                del self.items[: len(self.items) - self.keep]

    def count(self):
        with self.lock:
            return len(self.items)

    def messages(self, since=0.0):
        with self.lock:
            return [m for t, m in self.items if t >= since]

    def latest(self):
        with self.lock:
            return self.items[-1][1] if self.items else None

    def last_arrival(self):
        with self.lock:
            return self.items[-1][0] if self.items else None

    def wait_for(self, n=1, timeout=10.0, since=0.0):
        """Waits for n messages that arrived after `since`; returns them (maybe fewer)."""
        wait_until(lambda: len(self.messages(since)) >= n, timeout)
        return self.messages(since)

    def wait_for_match(self, predicate, timeout=10.0, since=0.0):
        """The first message after `since` that satisfies predicate, or None."""
        found = []

        def check():
            for m in self.messages(since):
                if predicate(m):
                    found.append(m)
                    return True
            return False

        wait_until(check, timeout)
        return found[0] if found else None

    def rate(self, seconds):
        """Messages per second over the next `seconds`."""
        start = time.time()
        before = len(self.messages(start))
        time.sleep(seconds)
        return (len(self.messages(start)) - before) / seconds

    def close(self):
        self.sub.unregister()


class Diagnostics:
    """The latest /diagnostics status of each name (names end with ': <task>')."""

    def __init__(self):
        self.lock = threading.Lock()
        self.latest = {}
        self.history = []  # (arrival, name, level, message)
        self.sub = rospy.Subscriber("/diagnostics", DiagnosticArray, self._on_msg, queue_size=100)

    def _on_msg(self, array):
        now = time.time()
        with self.lock:
            for status in array.status:
                self.latest[status.name] = status
                self.history.append((now, status.name, status.level, status.message))

    def status(self, task):
        with self.lock:
            for key, status in self.latest.items():
                if key.endswith(": " + task):
                    return status
        return None

    def value(self, task, key):
        status = self.status(task)
        if status is None:
            return None
        for kv in status.values:
            if kv.key == key:
                return kv.value
        return None

    def first_level_since(self, task, level, since):
        """Arrival time of the first status of `task` at `level` after `since`, or None."""
        with self.lock:
            for t, n, lv, _ in self.history:
                if t >= since and n.endswith(": " + task) and lv == level:
                    return t
        return None

    def wait_level(self, task, level, timeout):
        return wait_until(lambda: self.status(task) is not None and self.status(task).level == level, timeout)


class Run:
    """One actionlib goal sent with a SimpleActionClient: its feedback, final state and result."""

    def __init__(self, client, goal):
        self.feedback = []
        self.client = client
        client.send_goal(goal, feedback_cb=self.feedback.append)

    def wait(self, timeout):
        if not self.client.wait_for_result(rospy.Duration(timeout)):
            raise AssertionError("no result within %.0f s" % timeout)
        return self.client.get_state(), self.client.get_result()


def record(owner, **topics):
    """Sets owner.ATTR to a Recorder of the driver's topic for each ATTR=(relative topic, type)."""
    for attr, (topic, msg_type) in topics.items():
        setattr(owner, attr, Recorder(name(topic), msg_type))


def start_driver_test(cls, node_name, diagnostics=False, **topics):
    """setUpClass of a rostest node against the driver and k40t_sim: the node, cls.sim (the
    simulator's control socket, ~control), cls.joints and the Recorders of `topics` (see record()),
    cls.diagnostics if asked; returns once the driver publishes telemetry."""
    rospy.init_node(node_name)
    cls.sim = SimControl(rospy.get_param("~control"))
    record(cls, joints=("joint_states", JointState), **topics)
    if diagnostics:
        cls.diagnostics = Diagnostics()
    assert cls.joints.wait_for(3, timeout=20.0), "no telemetry from the driver"


def service(relative, srv_type, timeout=15.0):
    """A ServiceProxy for a driver service, after waiting for it."""
    full = name(relative)
    rospy.wait_for_service(full, timeout=timeout)
    return rospy.ServiceProxy(full, srv_type)


OK = DiagnosticStatus.OK
WARN = DiagnosticStatus.WARN
ERROR = DiagnosticStatus.ERROR


# What the driver writes on its own schedule (pod_driver.h): time sync, answers to the pod's GPS
# requests, laser-target requests, the gimbal rate dead-man's stop, and the versions and settings
# it re-reads when the pod comes back after a silence.
BACKGROUND_IDS = {0x00030E, 0x010310, 0x000320, 0x000017, 0x000018, 0x000317, 0x000100, 0x000200}


def frame_id(data):
    """The message id of a raw frame (bytes 7..9, low byte first)."""
    return data[7] | data[8] << 8 | data[9] << 16


def ids_sent_since(raw_tx, start):
    """Message ids of the raw/tx frames (a Recorder) the driver handed to the link at or after
    `start` (rospy.Time), by each frame's own stamp: a frame sent earlier but delivered to the
    recorder late, on a loaded machine, is not counted."""
    return [frame_id(f.data) for f in raw_tx.messages() if f.stamp >= start]


def assert_rejected_without_sending(test, raw_tx, srv, srv_type, field, **args):
    """success=false, the message names `field` and gives a range, and raw/tx (a Recorder) did not
    move but for the driver's own duties."""
    proxy = service(srv, srv_type)
    start = rospy.Time.now()
    response = proxy(**args)
    time.sleep(0.2)  # anything sent would be on raw/tx by now
    test.assertFalse(response.success, "%s(%s) accepted" % (srv, args))
    test.assertIn(field, response.message, "%s: the message does not name '%s': %s" % (srv, field, response.message))
    test.assertRegex(response.message, r"\d", "%s: the message gives no range: %s" % (srv, response.message))
    # The driver's own duties may write in that window (more likely on a loaded machine): they
    # are not the rejected request. Anything else is.
    unexpected = [i for i in ids_sent_since(raw_tx, start) if i not in BACKGROUND_IDS]
    test.assertEqual(unexpected, [], "%s(%s) sent frames %s: %s" % (
        srv, args, ["0x%06X" % i for i in unexpected], response.message))


def make_every_topic_flow(ns=DRIVER_NS):
    """Periodic laser ranging on, and a latched fix and attitude for the laser-target requests, so
    that every decoded topic of the live driver in `ns` flows. Returns the publishers: keep them."""
    from dynamic_reconfigure.client import Client as ReconfigureClient
    from sensor_msgs.msg import Imu, NavSatFix

    ReconfigureClient(ns + "/driver", timeout=15.0).update_configuration({"periodic_ranging": True})
    fix_pub = rospy.Publisher(ns + "/fix", NavSatFix, queue_size=1, latch=True)
    imu_pub = rospy.Publisher(ns + "/attitude", Imu, queue_size=1, latch=True)
    fix = NavSatFix()
    fix.latitude, fix.longitude, fix.altitude = 47.3977, 8.5456, 500.0
    imu = Imu()
    imu.orientation.w = 1.0
    fix_pub.publish(fix)
    imu_pub.publish(imu)
    time.sleep(1.5)
    return fix_pub, imu_pub
