#!/usr/bin/python3
"""Stops every nodelet and node of the package at random moments and checks that each stop is clean.

  1. Unload cycles: each nodelet (PodNodelet, VideoNodelet, SkyportNodelet) is loaded into one
     long-lived nodelet manager by `nodelet load` and unloaded by SIGINT to that loader at a random
     moment of a scenario (while connecting, during the settings read-back, in the middle of a
     service call, while the link reconnects, while the video opens, ...). Checked: the loader ends
     in bounded time, the nodelet leaves the manager, the manager stays alive and answers, its
     thread count does not grow from cycle to cycle (every thread joined). One more cycle per
     nodelet signals the loader while it is still loading.
  2. Manager shutdowns: a manager with all three nodelets loaded gets SIGINT together with its
     loaders, as roslaunch's Ctrl-C does. Checked: exit code 0 within bounded time, no process left.
  3. Nodes: k40t_node, k40t_video_node and k40t_skyport_node get SIGINT or SIGTERM at a random
     moment. Checked: exit code 0 within bounded time.
Every log is searched for "terminate called", aborts and crashes.

It runs its own master, simulated pod (with its RTSP stream) and simulated SKYPORT adapter, all on
127.0.0.1 and pseudo-terminals. Run after a ROS build with scripts/ros_env.sh sourced
(scripts/run_tests.sh does). Writes one JUnit test case per check group to --junit.

  clean_stop.py [--cycles N] [--shutdowns N] [--node-runs N] [--seed N] [--junit FILE]
                [--logs DIR] [--stock-manager]"""
import argparse
import os
import random
import signal
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from stop_harness import Harness, Failure  # noqa: E402

NODELETS = {
    # name: (type, scenarios)
    "pod": ("k40t_driver/PodNodelet",
            ["connecting", "readback", "service_call", "reconnecting", "random"]),
    "video": ("k40t_driver/VideoNodelet", ["opening", "unreachable", "random"]),
    "skyport": ("k40t_driver/SkyportNodelet", ["handshake", "no_adapter", "random"]),
}
NODES = ["k40t_node", "k40t_video_node", "k40t_skyport_node"]


class Results:
    def __init__(self):
        self.cases = []  # (group, name, failure or None, seconds)

    def add(self, group, name, failure, seconds):
        self.cases.append((group, name, failure, seconds))
        status = "ok" if not failure else "FAIL: " + failure
        print("  %-8s %-40s %5.1f s  %s" % (group, name, seconds, status), flush=True)

    def write_junit(self, path):
        failures = [c for c in self.cases if c[2]]
        suite = ET.Element("testsuite", name="clean_stop", tests=str(len(self.cases)),
                           failures=str(len(failures)))
        for group, name, failure, seconds in self.cases:
            case = ET.SubElement(suite, "testcase", classname="clean_stop." + group, name=name,
                                 time="%.1f" % seconds)
            if failure:
                ET.SubElement(case, "failure", message=failure)
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
        ET.ElementTree(suite).write(path, encoding="unicode", xml_declaration=True)


def run_case(results, group, name, body):
    start = time.monotonic()
    try:
        body()
        results.add(group, name, None, time.monotonic() - start)
    except Failure as e:
        results.add(group, name, str(e), time.monotonic() - start)


def unload_cycles(h, results, rng, cycles):
    manager = h.start_manager("stop_manager")
    for kind, (nodelet_type, scenarios) in NODELETS.items():
        baseline = None
        for i in range(cycles):
            scenario = scenarios[i % len(scenarios)]

            def cycle():
                nonlocal baseline
                h.unload_cycle(manager, kind, nodelet_type, scenario, rng, "%s_%d" % (kind, i))
                # The first cycle creates the manager's lasting threads (roscpp's, GStreamer's
                # clock); after it, a cycle that leaves a thread behind shows as growth. A service
                # call in progress holds the nodelet until it returns, so its threads may end a
                # moment after the nodelet left the manager's list.
                if baseline is None:
                    time.sleep(1.0)
                    baseline = h.thread_count(manager)
                    return
                deadline = time.monotonic() + 5.0
                while h.thread_count(manager) > baseline and time.monotonic() < deadline:
                    time.sleep(0.05)
                threads = h.thread_count(manager)
                if threads > baseline:
                    raise Failure("manager has %d threads 5 s after the unload, %d after the "
                                  "first cycle: a thread was not joined" % (threads, baseline))

            run_case(results, "unload", "%s_%02d_%s" % (kind, i, scenario), cycle)
        run_case(results, "unload", "%s_during_load" % kind,
                 lambda: h.unload_during_load(manager, kind, nodelet_type, rng,
                                              "%s_during_load" % kind))
    h.stop_manager(manager)
    run_case(results, "unload", "manager_log_clean", lambda: h.check_log(manager.log))


def manager_shutdowns(h, results, rng, count):
    for i in range(count):
        run_case(results, "shutdown", "all_three_%02d" % i,
                 lambda: h.manager_shutdown(rng, "shutdown_%d" % i))


def node_stops(h, results, rng, runs):
    for i in range(runs):
        for node in NODES:
            sig = signal.SIGINT if i % 2 == 0 else signal.SIGTERM
            run_case(results, "node", "%s_%s_%02d" % (node, sig.name, i),
                     lambda: h.node_stop(node, sig, rng, "%s_%d" % (node, i)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cycles", type=int, default=20, help="unload cycles per nodelet")
    ap.add_argument("--shutdowns", type=int, default=10, help="manager shutdowns")
    ap.add_argument("--node-runs", type=int, default=4, help="stops per node (SIGINT, SIGTERM...)")
    ap.add_argument("--seed", type=int, default=None, help="seed of the random moments")
    ap.add_argument("--junit", help="JUnit XML output path")
    ap.add_argument("--logs", help="directory for the processes' logs (default: a temporary one)")
    ap.add_argument("--stock-manager", action="store_true",
                    help="use `nodelet manager` instead of k40t_manager (to see it abort)")
    options = ap.parse_args()

    seed = options.seed if options.seed is not None else random.randrange(1 << 30)
    rng = random.Random(seed)
    logs = options.logs or tempfile.mkdtemp(prefix="k40t_clean_stop_")
    os.makedirs(logs, exist_ok=True)
    print("clean_stop: seed %d, logs in %s" % (seed, logs), flush=True)
    results = Results()
    start = time.monotonic()
    with Harness(logs, options.stock_manager) as h:
        unload_cycles(h, results, rng, options.cycles)
        manager_shutdowns(h, results, rng, options.shutdowns)
        node_stops(h, results, rng, options.node_runs)
        run_case(results, "all", "no_process_left", h.check_no_process_left)
    if options.junit:
        results.write_junit(options.junit)
    failed = sum(1 for c in results.cases if c[2])
    print("clean_stop: %d checks, %d failed, %.0f s (seed %d)"
          % (len(results.cases), failed, time.monotonic() - start, seed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
