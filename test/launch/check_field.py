#!/usr/bin/python3
"""The launch files as a user in the field starts them, each on a ROS master of its own:

- sim.launch, demo.launch (video on) and two_pods.launch (video off: two encoders would take the
  CPU of the whole test machine) start without a single WARN/ERROR line;
- sim.launch runs the diagnostics aggregator (/diagnostics_agg);
- `roswtf`, run from the repository root against the running sim.launch, runs and finds no error;
- the flight recorder: record.launch beside sim.launch, its rosbag process killed with SIGKILL
  after RECORD_S seconds (a power cut), keeps all but at most 1 s of raw/rx after
  `rosbag reindex`; it subscribes to every decoded topic the driver publishes; `k40t bag` decodes
  the recovered bag (docs/recording.md's steps);
- replay.launch of that bag ends by itself, cleanly: exit 0, no "REQUIRED process has died".

Writes one JUnit test case per check to --junit; exits 1 on any failure. Run after a ROS build with
scripts/ros_env.sh sourced (scripts/run_tests.sh's launch tier does)."""
import argparse
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
import xml.etree.ElementTree as ET

import rosbag
import rosgraph

from launch_session import LaunchSession, free_port

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
NS = "/k40t"
RECORD_S = 20.0  # the figure: killed after 20 s, >= 19 s of raw/rx kept
MAX_LOSS_S = 1.0
QUIET_S = 10.0  # how long a start is watched for warnings once the driver is up
# Topics of the driver that are not "decoded topics users look at": the raw frames (recorded
# anyway), the dynamic_reconfigure descriptions and the latched results of one service call.
NOT_DECODED = ("/raw/", "/parameter_descriptions", "/parameter_updates", "/located_")


class Report:
    def __init__(self):
        self.cases = []  # (name, seconds, failure text or None)
        self.lock = threading.Lock()

    def add(self, name, started, failure):
        with self.lock:
            self.cases.append((name, time.time() - started, failure))
        print(("FAIL %s\n  %s" % (name, failure.replace("\n", "\n  "))) if failure else "ok   " + name,
              flush=True)


def driver_up(session, ns=NS, timeout=60.0):
    """Waits until the driver's joint_states flow on the session's master (rostopic fails at once
    while roslaunch is still starting the master: try again until the deadline)."""
    deadline = time.time() + timeout
    while time.time() < deadline and session.process.poll() is None:
        try:
            if session.run("rostopic", "echo", "-n", "1", ns + "/joint_states",
                           timeout=deadline - time.time())[0] == 0:
                return True
        except subprocess.TimeoutExpired:
            return False
        time.sleep(0.5)
    return False


def quiet_start(report, launch_file, args, namespaces=(NS,)):
    """Starts launch_file, watches QUIET_S s once the driver is up, fails on any bad line."""
    started = time.time()
    session = LaunchSession(launch_file, args)
    try:
        up = all(driver_up(session, ns) for ns in namespaces)
        time.sleep(QUIET_S)
        until = time.time()
        bad = session.bad_lines(until)
    finally:
        session.stop()
    failure = None
    if not up:
        failure = "the driver never published joint_states:\n" + "\n".join(session.text()[-30:])
    elif bad:
        failure = "a normal start printed:\n" + "\n".join(bad)
    report.add("quiet start: %s %s" % (launch_file, " ".join(args)), started, failure)


def descendants(pid):
    """Pids of pid's children, grandchildren... (from /proc): `rosbag record` is a Python wrapper
    whose child /usr/lib/rosbag/record does the writing, and a power cut stops both."""
    parents = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open("/proc/%s/stat" % entry) as f:
                    parents[int(entry)] = int(f.read().rsplit(")", 1)[1].split()[1])
            except (OSError, IndexError, ValueError):
                pass
    found, frontier = [], [pid]
    while frontier:
        children = [p for p, parent in parents.items() if parent in frontier]
        found += children
        frontier = children
    return found


def decoded_topics_published(session):
    """The driver's decoded topics, from the master: every topic below NS that it publishes."""
    master = rosgraph.Master("/check_field", master_uri=session.env["ROS_MASTER_URI"])
    publishers, subscribers, _ = master.getSystemState()
    subscribed = {topic: nodes for topic, nodes in subscribers}
    driven = [t for t, nodes in publishers if NS + "/driver" in nodes and t != "/rosout"]
    # actionlib's own topics (goal status, feedback, result of the actions) are not decoded topics.
    actions = set(t.rsplit("/", 1)[0] for t in driven if t.endswith("/feedback"))
    return [t for t in driven if not any(n in t for n in NOT_DECODED)
            and t.rsplit("/", 1)[0] not in actions], subscribed


def roswtf(report, session):
    """roswtf from the repository root, as docs/ros_interface.md tells, against sim.launch."""
    started = time.time()
    done = subprocess.run(["roswtf"], cwd=ROOT, env=session.env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, timeout=120)
    out = done.stdout.decode("utf-8", "replace")
    failure = None
    if done.returncode != 0 or "Traceback" in out or "ERROR" in out or "not appear to be running" in out:
        failure = "roswtf (exit %d) said:\n%s" % (done.returncode, out)
    report.add("roswtf against sim.launch", started, failure)


def aggregator(report, session):
    started = time.time()
    code, out = session.run("rostopic", "echo", "-n", "1", "/diagnostics_agg/status[0]/name",
                            timeout=30)
    report.add("sim.launch publishes /diagnostics_agg", started,
               None if code == 0 else "no /diagnostics_agg message within 30 s:\n" + out)


def recorder_subscribed(session):
    """True once a k40t_record node is subscribed to raw/rx: the recording has begun."""
    _, subscribed = decoded_topics_published(session)
    return any("k40t_record" in n for n in subscribed.get(NS + "/raw/rx", []))


def cut_recording(report, session, bag):
    """record.launch beside the driver, SIGKILLed RECORD_S s after it subscribed; returns the
    times (s) it began recording and was killed."""
    t0 = time.time()
    record = subprocess.Popen(["roslaunch", "k40t_driver", "record.launch", "bag:=" + bag],
                              env=session.env, stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT,
                              start_new_session=True)
    while not recorder_subscribed(session) and time.time() < t0 + 30:
        time.sleep(0.05)
    # Recording has begun when the first chunk reaches the file (the bag's header comes first).
    active = bag + ".active"
    header_only = None
    while time.time() < t0 + 40:
        size = os.path.getsize(active) if os.path.exists(active) else None
        if header_only is None:
            header_only = size
        elif size is not None and size > header_only:
            break
        time.sleep(0.02)
    started = time.time()
    time.sleep(RECORD_S / 2)
    topics, subscribed = decoded_topics_published(session)
    recorders = set(n for nodes in subscribed.values() for n in nodes if "k40t_record" in n)
    missing = [t for t in topics if not recorders & set(subscribed.get(t, []))]
    time.sleep(max(0.0, started + RECORD_S - time.time()))
    # The power cut: the recorder and its roslaunch die at once, nothing gets to close the bag.
    killed = time.time()
    for pid in [record.pid] + descendants(record.pid):
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    record.wait()
    failure = None
    if not recorders:
        failure = "no k40t_record node subscribed within 30 s"
    elif missing:
        failure = "record.launch does not record the decoded topics %s" % " ".join(missing)
    report.add("record.launch records every decoded topic", t0, failure)
    return started, killed


def recover(report, bag, started, killed):
    """docs/recording.md's recovery: rosbag reindex, rename, then the raw/rx kept."""
    t0 = time.time()
    active = bag + ".active"
    done = subprocess.run(["rosbag", "reindex", active], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, timeout=120)
    failure = None
    if done.returncode != 0:
        failure = "rosbag reindex %s failed:\n%s" % (active, done.stdout.decode())
    else:
        os.rename(active, bag)
        with rosbag.Bag(bag) as b:
            rx = [t.to_sec() for _, _, t in b.read_messages(topics=[NS + "/raw/rx"])]
        lost = killed - rx[-1] if rx else RECORD_S
        kept = rx[-1] - rx[0] if rx else 0.0
        # No hole either: the chunks before the last one are all there. (When the first raw/rx
        # came after the bag's first chunk depends on how soon that connection was made, which
        # on a loaded machine can be a second after the other topics': not what a cut loses.)
        gap = max((b - a for a, b in zip(rx, rx[1:])), default=RECORD_S)
        print("  cut bag: recorder killed %.1f s after its start; raw/rx kept %.2f s (%d frames, "
              "largest gap %.2f s), the last %.2f s before the kill lost"
              % (killed - started, kept, len(rx), gap, lost))
        if lost > MAX_LOSS_S or gap > MAX_LOSS_S or kept < RECORD_S / 2:
            failure = ("killed after %.1f s, the reindexed bag keeps %.2f s of raw/rx with a gap of "
                       "up to %.2f s and loses its last %.2f s (at most %.1f s may be lost)"
                       % (killed - started, kept, gap, lost, MAX_LOSS_S))
    report.add("a recording killed with SIGKILL keeps raw/rx up to 1 s before the kill", t0, failure)
    return failure is None


def decode_cut_bag(report, bag, tmp):
    started = time.time()
    done = subprocess.run(["rosrun", "k40t_driver", "k40t", "bag", bag, "--config",
                           os.path.join(ROOT, "config", "k40t.yaml")],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=120)
    out = done.stdout.decode("utf-8", "replace")
    decoded = os.path.join(tmp, "flight.decoded.bag")
    failure = None
    if done.returncode != 0 or not os.path.exists(decoded):
        failure = "k40t bag (exit %d) did not decode the recovered bag:\n%s" % (done.returncode, out)
    else:
        with rosbag.Bag(decoded) as b:
            count = b.get_message_count(NS + "/joint_states")
        if count < 10 * (RECORD_S - 2):
            failure = "k40t bag decoded only %d joint_states from %.0f s of raw/rx" % (count, RECORD_S)
    report.add("k40t bag decodes the recovered bag", started, failure)


def replay_ends_cleanly(report, bag):
    started = time.time()
    session = LaunchSession("replay.launch", ["bag:=" + bag, "rate:=4", "play_delay:=1"])
    code = session.wait(timeout=60)
    if code is None:
        session.stop()
    bad = session.bad_lines()
    failure = None
    if code is None:
        failure = "replay.launch did not end within 60 s of a %.0f s bag played at 4x" % RECORD_S
    elif code != 0 or bad:
        failure = "replay.launch ended with exit code %d and printed:\n%s" % (code, "\n".join(bad))
    report.add("replay.launch ends cleanly with its bag", started, failure)


def sim_session(report):
    tmp = tempfile.mkdtemp(prefix="k40t_field_")
    bag = os.path.join(tmp, "flight.bag")
    started = time.time()
    session = LaunchSession("sim.launch", ["sim_link:=" + os.path.join(tmp, "pod")])
    try:
        if not driver_up(session):
            report.add("quiet start: sim.launch", started,
                       "the driver never published joint_states:\n" + "\n".join(session.text()[-30:]))
            return
        # The recording runs its RECORD_S s while the other checks use the same running driver.
        recording = {}

        def record():
            try:
                recording["times"] = cut_recording(report, session, bag)
            except Exception as e:  # reported as this check's failure, the others still run
                report.add("record.launch records every decoded topic", started, "raised %r" % e)

        recorder = threading.Thread(target=record)
        recorder.start()
        aggregator(report, session)
        roswtf(report, session)
        recorder.join()
        until = time.time()
        bad = session.bad_lines(until)
        report.add("quiet start: sim.launch", started,
                   "a normal run printed:\n" + "\n".join(bad) if bad else None)
    finally:
        session.stop()
    if "times" in recording and recover(report, bag, *recording["times"]):
        decode_cut_bag(report, bag, tmp)
        replay_ends_cleanly(report, bag)
    shutil.rmtree(tmp, ignore_errors=True)


def write_junit(report, path):
    suite = ET.Element("testsuite", name="field", tests=str(len(report.cases)), errors="0",
                       failures=str(sum(1 for c in report.cases if c[2])))
    for name, seconds, failure in report.cases:
        case = ET.SubElement(suite, "testcase", classname="field", name=name, time="%.3f" % seconds)
        if failure:
            ET.SubElement(case, "failure", message=failure.splitlines()[0]).text = failure
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    ET.ElementTree(suite).write(path, encoding="utf-8", xml_declaration=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--junit", help="JUnit XML output path")
    options = ap.parse_args()
    report = Report()
    tmp = tempfile.mkdtemp(prefix="k40t_field_links_")
    # sim.launch's session is the longest (RECORD_S s of recording): the other starts run beside it.
    checks = [threading.Thread(target=sim_session, args=(report,)),
              threading.Thread(target=quiet_start, args=(report, "demo.launch", [
                  "sim_link:=%s/demo" % tmp, "sim_rtsp_port:=%d" % free_port()])),
              threading.Thread(target=quiet_start, args=(report, "two_pods.launch", [
                  "video:=false", "a_sim_link:=%s/a" % tmp, "b_sim_link:=%s/b" % tmp],
                                                           ("/pod_a", "/pod_b")))]
    for check in checks:
        check.start()
    for check in checks:
        check.join()
    shutil.rmtree(tmp, ignore_errors=True)
    if options.junit:
        write_junit(report, options.junit)
    failures = sum(1 for c in report.cases if c[2])
    print("%d field checks, %d failed" % (len(report.cases), failures))
    return 1 if failures or not report.cases else 0


if __name__ == "__main__":
    sys.exit(main())
