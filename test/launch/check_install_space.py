#!/usr/bin/python3
"""The package works from an install space, not only from the source tree and devel space.

Reuses the finished build (build/ros): installs it into a temporary prefix
(`cmake --install build/ros --prefix DIR`, what `catkin_make install` does), then, in an
environment that knows nothing of the source tree (only DIR/setup.bash sourced):

  files           every file the installed package is run with is there: package.xml, the
                  launch files, config/, urdf/, rviz/, nodelet_plugins.xml and rviz_plugins.xml
                  with the libraries they name, every executable a launch file starts from
                  k40t_driver, every `$(find k40t_driver)/...` path a launch file uses, the
                  generated Python messages and dynamic_reconfigure cfg module;
  rospack_find    `rospack find k40t_driver` is the install space's share/k40t_driver;
  sim_launch      `roslaunch k40t_driver sim.launch` (its own master on a free port, its pty in the
                  temporary directory) publishes joint_states within 30 s, and stops on SIGINT.

Writes one JUnit test case per check to --junit; exits 1 on any failure.
Run by the launch tier of scripts/run_tests.sh after the build (scripts/build.sh ros)."""
import argparse
import glob
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

from checks_report import run_checks

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PACKAGE = "k40t_driver"
SHARE_DIRS = ["launch", "config", "urdf", "rviz"]
FIND = re.compile(r"\$\(find k40t_driver\)/([^\s\"'<>)]+)")


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def clean_env(prefix, home):
    """Only the install space: nothing of the source tree, its devel space or a user's ROS setup."""
    env = {"PATH": "/usr/bin:/bin:/usr/sbin:/sbin", "HOME": home, "ROS_HOME": home,
           "LANG": os.environ.get("LANG", "C.UTF-8"), "K40T_PREFIX": prefix}
    return env


def bash(prefix, home, command, **kwargs):
    script = 'set +u; source "$K40T_PREFIX/setup.bash"; ' + command
    return subprocess.Popen(["/bin/bash", "-c", script], env=clean_env(prefix, home),
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            start_new_session=True, **kwargs)


def install(prefix):
    build = os.path.join(ROOT, "build", "ros")
    if not os.path.isfile(os.path.join(build, "CMakeCache.txt")):
        return "no ROS build at %s: run scripts/build.sh ros first" % build
    done = subprocess.run(["cmake", "--install", build, "--prefix", prefix],
                          capture_output=True, text=True, check=False)
    if done.returncode != 0:
        return "cmake --install failed:\n" + done.stdout[-3000:] + done.stderr[-3000:]
    return None


def launch_needs():
    """(executables of k40t_driver started by launch files, $(find k40t_driver)/ paths used)."""
    executables, paths = set(), set()
    for launch in glob.glob(os.path.join(ROOT, "launch", "*.launch")):
        text = open(launch).read()
        paths |= set(FIND.findall(text))
        for node in ET.parse(launch).getroot().iter("node"):
            if node.get("pkg") == PACKAGE:
                executables.add(node.get("type"))
    return executables, paths


def plugin_libraries(xml_file):
    return [lib.get("path") for lib in ET.parse(xml_file).getroot().iter("library")]


def check_files(prefix):
    share = os.path.join(prefix, "share", PACKAGE)
    lib = os.path.join(prefix, "lib")
    missing = []

    def need(path, what):
        if not os.path.exists(path):
            missing.append("%s (%s)" % (os.path.relpath(path, prefix), what))

    need(os.path.join(share, "package.xml"), "rospack")
    for directory in SHARE_DIRS:
        for source in glob.glob(os.path.join(ROOT, directory, "**", "*"), recursive=True):
            if os.path.isfile(source):
                need(os.path.join(share, os.path.relpath(source, ROOT)), "installed directory")
    for plugins in ("nodelet_plugins.xml", "rviz_plugins.xml"):
        need(os.path.join(share, plugins), "plugin declarations")
        for library in plugin_libraries(os.path.join(ROOT, plugins)):
            # pluginlib looks the library up under the prefixes' lib/ as lib<name>.so
            need(os.path.join(prefix, os.path.dirname(library),
                              os.path.basename(library) + ".so"), plugins)
    executables, paths = launch_needs()
    for executable in sorted(executables):
        need(os.path.join(lib, PACKAGE, executable), "started by a launch file")
    for path in sorted(paths):
        need(os.path.join(share, path), "$(find k40t_driver) in a launch file")
    python = glob.glob(os.path.join(lib, "python3*", "dist-packages", PACKAGE))
    if not python:
        missing.append("lib/python3/dist-packages/%s (generated messages)" % PACKAGE)
    else:
        for cfg in glob.glob(os.path.join(ROOT, "cfg", "*.cfg")):
            name = os.path.splitext(os.path.basename(cfg))[0] + "Config.py"
            need(os.path.join(python[0], "cfg", name), "dynamic_reconfigure")
        for msg in glob.glob(os.path.join(ROOT, "msg", "*.msg")):
            name = "_" + os.path.splitext(os.path.basename(msg))[0] + ".py"
            need(os.path.join(python[0], "msg", name), "generated message")
    if missing:
        return "missing from the install space:\n  " + "\n  ".join(missing)
    return None


def check_rospack(prefix, home):
    process = bash(prefix, home, "rospack find %s" % PACKAGE)
    out, _ = process.communicate(timeout=30)
    expected = os.path.join(prefix, "share", PACKAGE)
    if out.strip().splitlines()[-1:] != [expected]:
        return "rospack find %s gave %r, expected %s" % (PACKAGE, out.strip(), expected)
    return None


def check_sim_launch(prefix, home):
    port = free_port()
    pty = os.path.join(home, "pod_pty")
    launch = bash(prefix, home, "exec roslaunch -p %d %s sim.launch sim_link:=%s respawn:=false"
                  % (port, PACKAGE, pty))
    try:
        echo = bash(prefix, home, "export ROS_MASTER_URI=http://127.0.0.1:%d; "
                    "exec timeout 30 rostopic echo -n 1 /k40t/joint_states" % port)
        out, _ = echo.communicate(timeout=40)
        if echo.returncode != 0 or "position:" not in out:
            return "no joint_states from sim.launch in the install space:\n" + out[-2000:]
        return None
    finally:
        os.killpg(launch.pid, signal.SIGINT)
        try:
            log, _ = launch.communicate(timeout=20)
        except subprocess.TimeoutExpired:
            os.killpg(launch.pid, signal.SIGKILL)
            log, _ = launch.communicate()
        if launch.returncode not in (0, -signal.SIGINT):
            print("roslaunch exit %s:\n%s" % (launch.returncode, log[-3000:]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--junit", help="write JUnit XML here")
    parser.add_argument("--keep", action="store_true", help="keep the install space (prints where)")
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="k40t_install_")
    prefix = os.path.join(work, "install")
    home = os.path.join(work, "home")
    os.makedirs(home)
    failure = install(prefix)
    checks = [("install", lambda: failure)]
    if failure is None:
        checks += [("files", lambda: check_files(prefix)),
                   ("rospack_find", lambda: check_rospack(prefix, home)),
                   ("sim_launch", lambda: check_sim_launch(prefix, home))]
    failures = run_checks("install_space", checks, args.junit)
    if args.keep:
        print("install space kept in " + prefix)
    else:
        shutil.rmtree(work, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
