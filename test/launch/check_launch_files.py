#!/usr/bin/python3
"""Checks every launch file of the package with roslaunch's own checker (the code behind
roslaunch-check and rostest's roslaunch_add_file_check): XML, args, substitutions, that every
node's package and executable exist, and package.xml dependencies. Each file is checked with its
default args and with the arg combinations listed in VARIANTS (roslaunch reads `name:=value`
from sys.argv); the args in NODE_ARGS must reach their node's command line. Writes one JUnit
test case per check to --junit; exits 1 on any failure.

Run after a ROS build with scripts/ros_env.sh sourced (scripts/run_tests.sh does)."""
import argparse
import glob
import os
import sys
import time
import xml.etree.ElementTree as ET

import roslaunch.config
import roslaunch.rlutil

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# Arg combinations worth checking beyond the defaults: each branch of an if/unless.
VARIANTS = {
    "k40t.launch": [["sim:=true"], ["manager:=/pod_manager"], ["publish_tf:=false", "ns:=pod2"],
                    ["video:=true"], ["sim:=true", "video:=true", "manager:=/pod_manager"]],
    "skyport.launch": [["sim:=true"], ["app_key_file:=/etc/k40t/app_key", "encryption:=false"],
                       ["sim:=true", "app_name:=a", "app_id:=1", "developer_account:=d"]],
    "sim.launch": [["manager:=/pod_manager"], ["video:=true"], ["aggregate:=false"]],
    "video.launch": [["manager:=/pod_manager", "backend:=ffmpeg"]],
    "demo.launch": [["video:=false"], ["frame_prefix:=pod_a_", "mount_frame:=base_link", "manager:=manager"]],
    "two_pods.launch": [["video:=false", "aggregate:=false", "respawn:=false"]],
    "record.launch": [["raw_only:=true", "duration:=5", "chunk_kb:=768"]],
    "replay.launch": [["sim_time:=true", "rate:=2.0"], ["ns:=pod_b", "frame_prefix:=pod_b_"]],
    "latency.launch": [["in_manager:=true"]],
}

# Args that must reach a node's command line: (file, args, node name, words its args must hold).
NODE_ARGS = [
    ("sim.launch", ["video:=true", "sim_rtsp_key_interval:=15"], "pod_sim",
     "--rtsp-key-interval 15"),
    ("sim.launch", ["video:=true"], "pod_sim", "--rtsp-key-interval 30"),
]


def launch_files():
    files = sorted(glob.glob(os.path.join(ROOT, "launch", "*.launch")))
    files += sorted(glob.glob(os.path.join(ROOT, "test", "ros", "*.test")))
    files += sorted(glob.glob(os.path.join(ROOT, "bench", "ros", "*.launch")))
    files += sorted(glob.glob(os.path.join(ROOT, "bench", "video", "*.launch")))
    return files


def check(path, args):
    saved = sys.argv
    sys.argv = [saved[0]] + args  # roslaunch's loader takes name:=value mappings from sys.argv
    try:
        return roslaunch.rlutil.check_roslaunch(path, use_test_depends=path.endswith(".test"))
    except Exception as e:  # a crash of the checker is a failure of this file, not of the script
        return "checker raised %s: %s" % (type(e).__name__, e)
    finally:
        sys.argv = saved


def check_node_args(file, args, node, words):
    """None if `node` of launch/`file` with `args` is started with `words` in its arguments."""
    saved = sys.argv
    sys.argv = [saved[0]] + args
    try:
        config = roslaunch.config.load_config_default([os.path.join(ROOT, "launch", file)], None,
                                                      verbose=False)
    except Exception as e:  # a crash of the loader is a failure of this check
        return "loader raised %s: %s" % (type(e).__name__, e)
    finally:
        sys.argv = saved
    found = [n.args for n in config.nodes if n.name == node]
    if not found:
        return "no node %s" % node
    return None if words in found[0] else "%s's args are '%s', without '%s'" % (node, found[0], words)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--junit", help="JUnit XML output path")
    options = ap.parse_args()

    suite = ET.Element("testsuite", name="launch_files")
    failures = 0
    cases = 0
    for path in launch_files():
        name = os.path.relpath(path, ROOT)
        for args in [[]] + VARIANTS.get(os.path.basename(path), []):
            label = name + (" " + " ".join(args) if args else "")
            started = time.time()
            error = check(path, args)
            case = ET.SubElement(suite, "testcase", classname="launch_files", name=label,
                                 time="%.3f" % (time.time() - started))
            cases += 1
            if error:
                failures += 1
                ET.SubElement(case, "failure", message="roslaunch check failed").text = error
                print("FAIL %s\n  %s" % (label, error.replace("\n", "\n  ")))
            else:
                print("ok   %s" % label)
    for file, args, node, words in NODE_ARGS:
        label = "launch/%s %s: %s gets %s" % (file, " ".join(args), node, words)
        error = check_node_args(file, args, node, words)
        case = ET.SubElement(suite, "testcase", classname="launch_files", name=label, time="0")
        cases += 1
        if error:
            failures += 1
            ET.SubElement(case, "failure", message="node arguments").text = error
            print("FAIL %s\n  %s" % (label, error))
        else:
            print("ok   %s" % label)
    suite.set("tests", str(cases))
    suite.set("failures", str(failures))
    suite.set("errors", "0")
    if options.junit:
        os.makedirs(os.path.dirname(os.path.abspath(options.junit)), exist_ok=True)
        ET.ElementTree(suite).write(options.junit, encoding="utf-8", xml_declaration=True)
    print("%d launch checks, %d failed" % (cases, failures))
    return 1 if failures or cases == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
