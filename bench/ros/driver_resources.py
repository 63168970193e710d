#!/usr/bin/python3
"""Measures the driver process's CPU share and memory at full telemetry: every periodic report
(the simulator's rates), periodic laser ranging, a fix for laser-target requests, and
subscribers on every topic (so each message is really serialised and sent). Prints CPU as % of
one core over the window, RSS at the end and the peak (VmHWM), the number of threads, and the CPU
of each thread by name (what `top -H` shows; the driver names its threads k40t_*)."""
import argparse
import os
import sys
import time

import rosnode
import rospy
import rosgraph
from dynamic_reconfigure.client import Client as ReconfigureClient
from geometry_msgs.msg import QuaternionStamped
from sensor_msgs.msg import Imu, JointState, NavSatFix, Range

from k40t_driver.msg import CameraStatus, Frame, GimbalStatus, ThermalStats, VisibleStatus


def node_pid(node):
    master = rosgraph.Master("/driver_resources")
    uri = rosnode.get_api_uri(master, node, skip_cache=True)
    import xmlrpc.client
    code, _, pid = xmlrpc.client.ServerProxy(uri).getPid("/driver_resources")
    return pid


def cpu_seconds(pid):
    fields = open("/proc/%d/stat" % pid).read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")  # utime + stime


def thread_cpu_seconds(pid):
    """{thread id: (name, CPU seconds)} of every thread of the process."""
    out = {}
    for tid in os.listdir("/proc/%d/task" % pid):
        try:
            stat = open("/proc/%d/task/%s/stat" % (pid, tid)).read()
        except OSError:
            continue  # ended meanwhile
        name = stat[stat.index("(") + 1:stat.rindex(")")]
        fields = stat.rsplit(")", 1)[1].split()
        out[tid] = (name, (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK"))
    return out


def threads_by_name(before, after, seconds):
    """'name xN p.pp %' per thread name, the busiest first: CPU over the window by name."""
    share = {}
    count = {}
    for tid, (name, cpu) in after.items():
        start = before.get(tid, (name, 0.0))[1]
        share[name] = share.get(name, 0.0) + 100.0 * (cpu - start) / seconds
        count[name] = count.get(name, 0) + 1
    ordered = sorted(share, key=lambda n: (-share[n], n))
    return ", ".join("%s x%d %.2f %%" % (n, count[n], share[n]) for n in ordered)


def memory_kb(pid, key):
    for line in open("/proc/%d/status" % pid):
        if line.startswith(key + ":"):
            return int(line.split()[1])
    return 0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--seconds", type=float, default=60)
    ap.add_argument("--node", default="/k40t/driver")
    args = ap.parse_args(rospy.myargv()[1:])
    rospy.init_node("driver_resources")
    ns = args.node.rsplit("/", 1)[0]
    deadline = time.time() + 30
    pid = None
    while pid is None and time.time() < deadline:
        try:
            pid = node_pid(args.node)
        except Exception:
            time.sleep(0.5)
    if pid is None:
        print("driver node %s not found" % args.node)
        return 1
    subs = [rospy.Subscriber(ns + "/" + t, c, lambda m: None) for t, c in [
        ("joint_states", JointState), ("gimbal/attitude", QuaternionStamped), ("gimbal/status", GimbalStatus),
        ("camera/status", CameraStatus), ("visible/status", VisibleStatus), ("thermal/stats", ThermalStats),
        ("laser/range", Range), ("laser/target", NavSatFix), ("raw/rx", Frame), ("raw/tx", Frame)]]
    ReconfigureClient(args.node, timeout=20).update_configuration({"periodic_ranging": True})
    fix = rospy.Publisher(ns + "/fix", NavSatFix, queue_size=1, latch=True)
    imu = rospy.Publisher(ns + "/attitude", Imu, queue_size=1, latch=True)
    f = NavSatFix()
    f.latitude, f.longitude, f.altitude = 47.4, 8.5, 500.0
    fix.publish(f)
    i = Imu()
    i.orientation.w = 1.0
    imu.publish(i)
    time.sleep(3.0)  # settle: connections made, settings read
    cpu0, t0, threads0 = cpu_seconds(pid), time.time(), thread_cpu_seconds(pid)
    time.sleep(args.seconds)
    cpu1, t1, threads1 = cpu_seconds(pid), time.time(), thread_cpu_seconds(pid)
    share = 100.0 * (cpu1 - cpu0) / (t1 - t0)
    print("driver (pid %d) over %.0f s: CPU %.2f %% of one core; RSS %.1f MB, peak %.1f MB; %d threads" %
          (pid, t1 - t0, share, memory_kb(pid, "VmRSS") / 1024.0, memory_kb(pid, "VmHWM") / 1024.0,
           len(threads1)))
    print("  CPU by thread: " + threads_by_name(threads0, threads1, t1 - t0))
    del subs
    return 0


if __name__ == "__main__":
    sys.exit(main())
