#!/usr/bin/python3
"""The package works from an install space, not only from the source tree and devel space.

Reuses the finished build (build/ros): installs it as `catkin_make install` does, below a
temporary directory (`DESTDIR=TMP cmake --install build/ros`: the install space is TMP + the
configured prefix; catkin installs its setup files to the absolute prefix, so `--prefix` would not
move them), then, in an environment that knows nothing of the source tree (only the install
space's setup.bash sourced):

  files           every file the installed package is run with is there: package.xml, the
                  launch files, config/, urdf/, rviz/, nodelet_plugins.xml and rviz_plugins.xml
                  with the libraries they name, every executable a launch file starts from
                  k40t_driver, every `$(find k40t_driver)/...` path a launch file uses, the
                  generated Python messages and dynamic_reconfigure cfg module, the lens module
                  libk40t_opencv_lens.so the driver opens beside its library;
  rospack_find    `rospack find k40t_driver` is the install space's share/k40t_driver;
  sim_launch      `roslaunch k40t_driver sim.launch` (its own master on a free port, its pty in the
                  temporary directory) publishes joint_states within 30 s, and stops on SIGINT.

Writes one JUnit test case per check to --junit; exits 1 on any failure.
Run by the launch tier of scripts/run_tests.sh after the build (scripts/build.sh ros)."""
import argparse
import glob
import os
import random
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

from checks_report import run_checks

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PACKAGE = "k40t_driver"
SHARE_DIRS = ["launch", "config", "urdf", "rviz"]
FIND = re.compile(r"\$\(find k40t_driver\)/([^\s\"'<>)]+)")


def free_port():
    """A free TCP port below the kernel's ephemeral range: a port the kernel hands out itself could
    be given again to roslaunch's own XML-RPC server before the master binds it."""
    low = int(open("/proc/sys/net/ipv4/ip_local_port_range").read().split()[0])
    while True:
        port = random.randrange(20000, low)
        with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
            try:
                s.bind(("", port))
                return port
            except OSError:
                continue


def clean_env(prefix, home):
    """Only the install space: nothing of the source tree, its devel space or a user's ROS setup."""
    env = {"PATH": "/usr/bin:/bin:/usr/sbin:/sbin", "HOME": home, "ROS_HOME": home,
           "LANG": os.environ.get("LANG", "C.UTF-8"), "K40T_PREFIX": prefix}
    return env


def bash(prefix, home, command, stdout=subprocess.PIPE):
    script = 'set +u; source "$K40T_PREFIX/setup.bash"; ' + command
    return subprocess.Popen(["/bin/bash", "-c", script], env=clean_env(prefix, home),
                            stdout=stdout, stderr=subprocess.STDOUT, text=True,
                            start_new_session=True)


BUILD = os.path.join(ROOT, "build", "ros")


def configured_prefix():
    """CMAKE_INSTALL_PREFIX of the ROS build, or None without one."""
    cache = os.path.join(BUILD, "CMakeCache.txt")
    if not os.path.isfile(cache):
        return None
    for line in open(cache):
        if line.startswith("CMAKE_INSTALL_PREFIX:"):
            return line.split("=", 1)[1].strip()
    return None


def install(destdir, prefix):
    env = dict(os.environ, DESTDIR=destdir)
    done = subprocess.run(["cmake", "--install", BUILD], env=env, capture_output=True, text=True,
                          check=False)
    if done.returncode != 0:
        return "cmake --install failed:\n" + done.stdout[-3000:] + done.stderr[-3000:]
    if not os.path.isfile(os.path.join(prefix, "setup.bash")):
        return "cmake --install wrote no setup.bash to %s" % prefix
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
    # Opened with dlopen beside libk40t_pod.so on the first pixel located (camera/opencv_lens.h).
    need(os.path.join(lib, "libk40t_opencv_lens.so"), "locate_pixel's lens distortion")
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


def processes_under(directory):
    """Pids of the processes whose command line names `directory` (what this check started: the
    nodes' paths and log names are in its temporary directory)."""
    found = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open("/proc/%s/cmdline" % pid, "rb") as cmdline:
                if directory.encode() in cmdline.read():
                    found.append(int(pid))
        except OSError:
            continue
    return [pid for pid in found if pid != os.getpid()]


def stop(launch, work):
    """SIGINT to roslaunch, as Ctrl-C; None if it and every node it started ended within 30 s."""
    if launch.poll() is None:
        os.killpg(launch.pid, signal.SIGINT)
    try:
        launch.wait(timeout=30)
    except subprocess.TimeoutExpired:
        os.killpg(launch.pid, signal.SIGKILL)
        launch.wait()
    deadline = time.time() + 10
    while processes_under(work) and time.time() < deadline:
        time.sleep(0.2)
    left = processes_under(work)
    for pid in left:
        os.kill(pid, signal.SIGKILL)
    if launch.returncode != 0 or left:
        return "roslaunch exit %s, %d processes left after it" % (launch.returncode, len(left))
    return None


def check_sim_launch(prefix, home):
    failure = sim_launch_once(prefix, home)
    if failure is not None and "is already in use" in failure:
        print("  the master's port was taken meanwhile; once more on another port")
        failure = sim_launch_once(prefix, home)
    return failure


def sim_launch_once(prefix, home):
    work = os.path.dirname(home)
    port = free_port()
    log_path = os.path.join(home, "roslaunch.out")
    with open(log_path, "w") as log:
        launch = bash(prefix, home, "exec roslaunch -p %d %s sim.launch sim_link:=%s "
                      "respawn:=false" % (port, PACKAGE, os.path.join(home, "pod_pty")),
                      stdout=log)
    failure = None
    try:
        # The master comes up with roslaunch: ask again until it answers and a message comes.
        deadline = time.time() + 40
        while True:
            if launch.poll() is not None:
                failure = "roslaunch ended (exit %d) before any joint_states" % launch.returncode
                break
            echo = bash(prefix, home, "export ROS_MASTER_URI=http://127.0.0.1:%d; "
                        "exec timeout 5 rostopic echo -n 1 /k40t/joint_states" % port)
            out, _ = echo.communicate(timeout=15)
            if echo.returncode == 0 and "position:" in out:
                break
            if time.time() > deadline:
                failure = "no joint_states from sim.launch in the install space:\n" + out[-2000:]
                break
            time.sleep(0.5)
    finally:
        stopped = stop(launch, work)
    if failure is None and stopped is not None:
        failure = stopped
    if failure is not None:
        failure += "\nroslaunch's output:\n" + open(log_path).read()[-3000:]
    return failure


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--junit", help="write JUnit XML here")
    parser.add_argument("--keep", action="store_true", help="keep the install space (prints where)")
    parser.add_argument("--remove", action="append", default=[], metavar="PATH",
                        help="delete PATH (relative to the install space) after installing: the "
                             "checks must then fail")
    args = parser.parse_args()
    installed_prefix = configured_prefix()
    if installed_prefix is None:
        print("FAIL install: no ROS build at %s: run scripts/build.sh ros first" % BUILD)
        return 1
    work = tempfile.mkdtemp(prefix="k40t_install_")
    destdir = os.path.join(work, "destdir")
    prefix = destdir + installed_prefix
    home = os.path.join(work, "home")
    os.makedirs(home)
    def install_and_remove():
        failure = install(destdir, prefix)
        for path in args.remove:  # shows that a file missing from the install space is found
            os.remove(os.path.join(prefix, path))
        return failure

    checks = [("install", install_and_remove),
              ("files", lambda: check_files(prefix)),
              ("rospack_find", lambda: check_rospack(prefix, home)),
              ("sim_launch", lambda: check_sim_launch(prefix, home))]
    try:
        failures = run_checks("install_space", checks, args.junit)
    finally:
        if args.keep:
            print("install space kept in " + prefix)
        else:
            shutil.rmtree(work, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
