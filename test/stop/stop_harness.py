"""The processes clean_stop.py drives: a private master, the simulated pod and SKYPORT adapter,
nodelet managers, `nodelet load` loaders and the standalone nodes; and the checks of one stop."""
import os
import re
import signal
import socket
import subprocess
import threading
import time

import rosgraph
import rospy
from k40t_driver.srv import GetVersions
from nodelet.srv import NodeletList

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
NODELET = "/usr/lib/nodelet/nodelet"
CRASH = re.compile(r"terminate called|Aborted|core dumped|Segmentation fault|"
                   r"stack smashing|double free|corrupted|AddressSanitizer")
EXIT_TIMEOUT_S = 15.0   # a loader, node or manager must end this long after its signal
UNLOAD_TIMEOUT_S = 15.0  # a nodelet must leave its manager this long after its loader's signal
BOND_CONNECT_TIMEOUT_S = 10.0  # bondcpp's default: a loader that never connects is given up then


class Failure(Exception):
    pass


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def program(name):
    """A program of this package, from the devel space scripts/ros_env.sh put on the path."""
    for prefix in os.environ.get("CMAKE_PREFIX_PATH", "").split(":"):
        path = os.path.join(prefix, "lib", "k40t_driver", name)
        if os.path.exists(path):
            return path
    raise Failure("no program %s in the devel space: build first" % name)


class Proc:
    def __init__(self, args, log, env):
        self.log = log
        self.args = args
        with open(log, "w") as out:
            self.popen = subprocess.Popen(args, stdout=out, stderr=subprocess.STDOUT, env=env,
                                          stdin=subprocess.DEVNULL, start_new_session=True)

    @property
    def pid(self):
        return self.popen.pid

    def alive(self):
        return self.popen.poll() is None

    def catches(self, sig):
        """Whether the process has a handler for `sig` (the SigCgt mask of /proc/<pid>/status)."""
        try:
            with open("/proc/%d/status" % self.popen.pid) as f:
                for line in f:
                    if line.startswith("SigCgt:"):
                        return bool(int(line.split()[1], 16) & (1 << (sig - 1)))
        except OSError:
            pass
        return False

    def wait_until_catching(self, sig, timeout):
        """Waits until the process has a handler for `sig`: the dynamic loader's work before it
        (0.1 to 0.3 s for the ~290 libraries of the video node on a loaded machine) runs no code of
        ours, so no program can catch a signal there. The nodes install theirs first thing, from
        the executable's .preinit_array (src/ros/early/early_stop_signals.cpp)."""
        deadline = time.monotonic() + timeout
        while not self.catches(sig) and self.alive() and time.monotonic() < deadline:
            time.sleep(0.002)
        return self.catches(sig)

    def signal(self, sig):
        if self.alive():
            self.popen.send_signal(sig)

    def wait(self, timeout):
        """The exit code, or None if it is still running after `timeout` seconds."""
        try:
            return self.popen.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            return None

    def kill(self):
        if self.alive():
            os.killpg(self.popen.pid, signal.SIGKILL)
            self.popen.wait()


class Harness:
    def __init__(self, logs, stock_manager=False):
        self.logs = logs
        self.stock_manager = stock_manager
        self.procs = []  # everything the checks start (not the master and the simulators)
        self.infra = []
        self.pending_calls = []  # service calls made in the service_call scenario
        self.tag = "k40t_stop_%d" % os.getpid()
        self.pod_link = "/tmp/%s_pod" % self.tag
        self.skyport_link = "/tmp/%s_skyport" % self.tag
        self.control = "/tmp/%s_ctl" % self.tag
        self.rtsp_port = free_port()
        self.env = dict(os.environ)
        self.env["ROS_MASTER_URI"] = "http://127.0.0.1:%d" % free_port()
        self.env["ROS_HOSTNAME"] = "127.0.0.1"
        os.environ.update({k: self.env[k] for k in ("ROS_MASTER_URI", "ROS_HOSTNAME")})
        self.key_file = os.path.join(ROOT, "config", "skyport_sim_app_key")

    # --- set-up ----------------------------------------------------------------------------
    def __enter__(self):
        port = self.env["ROS_MASTER_URI"].rsplit(":", 1)[1]
        self.infra.append(self.spawn(["roscore", "-p", port], "roscore", infra=True))
        self.infra.append(self.spawn([program("k40t_sim"), "--link", "pty:" + self.pod_link,
                                      "--control", "unix:" + self.control,
                                      "--rtsp-port", str(self.rtsp_port)], "k40t_sim", infra=True))
        self.infra.append(self.spawn([program("skyport_sim"), "--link", "pty:" + self.skyport_link,
                                      "--app-key-file", self.key_file], "skyport_sim", infra=True))
        master = rosgraph.Master("/clean_stop")
        deadline = time.monotonic() + 30
        while True:
            try:
                master.getPid()
                break
            except Exception:
                if time.monotonic() > deadline:
                    raise Failure("the master did not start (see roscore.log)")
                time.sleep(0.2)
        rospy.init_node("clean_stop", anonymous=True, disable_signals=True)
        return self

    def __exit__(self, *exc):
        for p in self.procs:
            p.kill()
        for p in reversed(self.infra):
            p.signal(signal.SIGINT)
            if p.wait(5) is None:
                p.kill()
        rospy.signal_shutdown("clean_stop done")
        return False

    def spawn(self, args, label, infra=False):
        p = Proc(args, os.path.join(self.logs, label + ".log"), self.env)
        if not infra:
            self.procs.append(p)
        return p

    # --- the simulated pod -------------------------------------------------------------------
    def pod_control(self, command):
        with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as s:
            s.settimeout(5)
            s.connect(self.control)
            s.sendall((command + "\n").encode())
            return s.recv(4096).decode()

    # --- nodelet managers ------------------------------------------------------------------
    def start_manager(self, name):
        # The package's manager (src/ros/nodes/k40t_manager.cpp): `nodelet manager` of nodelet 1.10
        # aborts on Ctrl-C when bonded nodelets unload while it exits (see that file).
        command = [NODELET, "manager"] if self.stock_manager else [program("k40t_manager")]
        manager = self.spawn(command + ["__name:=" + name], name)
        manager.name = name
        self.wait_for(lambda: self.loaded(manager) is not None, 20,
                      "manager %s did not come up" % name)
        return manager

    def stop_manager(self, manager):
        manager.signal(signal.SIGINT)
        code = manager.wait(EXIT_TIMEOUT_S)
        if code is None:
            manager.kill()
            raise Failure("manager %s still running %.0f s after SIGINT" % (manager.name,
                                                                           EXIT_TIMEOUT_S))
        if code != 0:
            raise Failure("manager %s exited with %d" % (manager.name, code))

    def loaded(self, manager):
        """The manager's loaded nodelets, or None if it does not answer."""
        try:
            proxy = rospy.ServiceProxy("/%s/list" % manager.name, NodeletList)
            return list(proxy().nodelets)
        except Exception:
            return None

    def thread_count(self, proc):
        return len(os.listdir("/proc/%d/task" % proc.pid))

    def nodelet_params(self, kind, scenario):
        absent = "serial:///tmp/%s_absent" % self.tag
        rtsp = "rtsp://127.0.0.1:%d/live/single" % self.rtsp_port
        if kind == "pod":
            return {"device": absent if scenario == "connecting" else "serial://" + self.pod_link}
        if kind == "video":
            closed = "rtsp://127.0.0.1:%d/live/single" % free_port()
            return {"url": closed if scenario == "unreachable" else rtsp}
        return {"device": absent if scenario == "no_adapter" else "serial://" + self.skyport_link,
                "app_key_file": self.key_file}

    def start_loader(self, manager, kind, nodelet_type, scenario, label):
        params = ["_%s:=%s" % kv for kv in self.nodelet_params(kind, scenario).items()]
        loader = self.spawn([NODELET, "load", nodelet_type, "/" + manager.name,
                             "__name:=" + kind, "__ns:=/stop_" + kind] + params, label)
        loader.nodelet_name = "/stop_%s/%s" % (kind, kind)
        return loader

    def wait_for(self, predicate, timeout, message):
        deadline = time.monotonic() + timeout
        while not predicate():
            if time.monotonic() > deadline:
                raise Failure(message)
            time.sleep(0.05)

    # --- one unload at a chosen moment -----------------------------------------------------
    def unload_during_load(self, manager, kind, nodelet_type, rng, label):
        """SIGINT while `nodelet load` is still loading. Before the loader has installed its own
        SIGINT handler the signal ends it at once (nodelet's tool starts roscpp without one), so
        nobody unloads the nodelet: the manager's bond to the dead loader does, when its connect
        timeout (10 s) expires. Checked: the loader ends, and the nodelet is gone after that."""
        loader = self.start_loader(manager, kind, nodelet_type, "random", label)
        try:
            time.sleep(rng.uniform(0.0, 0.5))
            loader.signal(signal.SIGINT)
            code = loader.wait(EXIT_TIMEOUT_S)
            if code is None:
                raise Failure("the loader still running %.0f s after SIGINT (see %s)"
                              % (EXIT_TIMEOUT_S, loader.log))
            if code not in (0, -signal.SIGINT):
                raise Failure("the loader exited with %d (see %s)" % (code, loader.log))
            time.sleep(BOND_CONNECT_TIMEOUT_S + 1.0)
            self.wait_for(lambda: loader.nodelet_name not in (self.loaded(manager) or [None]),
                          UNLOAD_TIMEOUT_S, "%s still loaded %.0f s after its loader ended"
                          % (nodelet_type, BOND_CONNECT_TIMEOUT_S + 1 + UNLOAD_TIMEOUT_S))
            if not manager.alive():
                raise Failure("the manager died (see %s)" % manager.log)
            self.check_log(manager.log)
        finally:
            loader.kill()

    def unload_cycle(self, manager, kind, nodelet_type, scenario, rng, label):
        if scenario == "service_call":
            self.pod_control("delay-acks 250")  # the call is still waiting when SIGINT comes
        loader = self.start_loader(manager, kind, nodelet_type, scenario, label)
        try:
            self.wait_for(lambda: loader.nodelet_name in (self.loaded(manager) or []) or
                          not loader.alive(), 20, "%s was not loaded in 20 s" % nodelet_type)
            if not loader.alive():
                raise Failure("the loader exited before SIGINT (code %s, see %s)"
                              % (loader.popen.returncode, loader.log))
            self.at_moment(kind, scenario, rng)
            loader.signal(signal.SIGINT)
            code = loader.wait(EXIT_TIMEOUT_S)
            if code is None:
                raise Failure("the loader still running %.0f s after SIGINT (see %s)"
                              % (EXIT_TIMEOUT_S, loader.log))
            self.wait_for(lambda: loader.nodelet_name not in (self.loaded(manager) or [None]),
                          UNLOAD_TIMEOUT_S, "%s still loaded %.0f s after its loader's SIGINT"
                          % (nodelet_type, UNLOAD_TIMEOUT_S))
            if code != 0:
                raise Failure("the loader exited with %d (see %s)" % (code, loader.log))
            if not manager.alive():
                raise Failure("the manager died (see %s)" % manager.log)
            self.check_log(loader.log)
            self.check_log(manager.log)
        finally:
            loader.kill()
            if scenario == "service_call":
                self.pod_control("clear")

    def call_get_versions(self):
        try:
            rospy.ServiceProxy("/stop_pod/get_versions", GetVersions)()
        except Exception:  # the nodelet went away under the call: that is the scenario
            pass

    def at_moment(self, kind, scenario, rng):
        """Waits for the scenario's moment after the nodelet's onInit returned."""
        if scenario == "readback":
            time.sleep(rng.uniform(0.0, 0.6))  # the pod comes online, the settings are read
        elif scenario == "service_call":
            # In this process, so that the call is surely waiting for the pod's (delayed) ACK
            # when the SIGINT comes: the driver answers it only after 250 ms.
            call = threading.Thread(target=self.call_get_versions, daemon=True)
            call.start()
            self.pending_calls.append(call)
            time.sleep(rng.uniform(0.05, 0.2))
        elif scenario == "reconnecting":
            time.sleep(0.5)
            self.pod_control("disconnect 1")
            time.sleep(rng.uniform(0.0, 1.2))
        elif scenario in ("opening", "handshake"):
            time.sleep(rng.uniform(0.0, 1.0))
        else:  # connecting, unreachable, no_adapter, random
            time.sleep(rng.uniform(0.0, 2.5))

    # --- a manager with all three nodelets -------------------------------------------------
    def manager_shutdown(self, rng, label):
        manager = self.start_manager(label)
        loaders = [self.start_loader(manager, kind, t, "random", "%s_%s" % (label, kind))
                   for kind, t in (("pod", "k40t_driver/PodNodelet"),
                                   ("video", "k40t_driver/VideoNodelet"),
                                   ("skyport", "k40t_driver/SkyportNodelet"))]
        names = [l.nodelet_name for l in loaders]
        self.wait_for(lambda: all(n in (self.loaded(manager) or []) for n in names), 30,
                      "the three nodelets were not loaded in 30 s")
        time.sleep(rng.uniform(0.0, 3.0))
        for p in [manager] + loaders:  # roslaunch's Ctrl-C: every process at once
            p.signal(signal.SIGINT)
        code = manager.wait(EXIT_TIMEOUT_S)
        stuck = [l.log for l in loaders if l.wait(EXIT_TIMEOUT_S) is None]
        for loader in loaders:
            loader.kill()
        if stuck:
            raise Failure("loaders still running %.0f s after SIGINT: %s" % (EXIT_TIMEOUT_S,
                                                                           ", ".join(stuck)))
        if code is None:
            manager.kill()
            raise Failure("manager still running %.0f s after SIGINT (see %s)"
                          % (EXIT_TIMEOUT_S, manager.log))
        if code != 0:
            raise Failure("manager exited with %d (see %s)" % (code, manager.log))
        self.check_log(manager.log)

    # --- standalone nodes ------------------------------------------------------------------
    def node_stop(self, node, sig, rng, label):
        params = {"k40t_node": self.nodelet_params("pod", "random"),
                  "k40t_video_node": self.nodelet_params("video", "random"),
                  "k40t_skyport_node": self.nodelet_params("skyport", "random")}[node]
        args = [program(node), "__name:=" + label, "__ns:=/stop_nodes"]
        proc = self.spawn(args + ["_%s:=%s" % kv for kv in params.items()], label)
        if not proc.wait_until_catching(sig, 10.0):
            raise Failure("%s has no %s handler 10 s after its start (see %s)"
                          % (node, sig.name, proc.log))
        time.sleep(rng.uniform(0.0, 2.8))  # any moment from then on, the early one included
        if not proc.alive():
            raise Failure("%s exited before the signal (code %s, see %s)"
                          % (node, proc.popen.returncode, proc.log))
        proc.signal(sig)
        code = proc.wait(EXIT_TIMEOUT_S)
        if code is None:
            proc.kill()
            raise Failure("%s still running %.0f s after %s (see %s)"
                          % (node, EXIT_TIMEOUT_S, sig.name, proc.log))
        if code != 0:
            raise Failure("%s exited with %d after %s (see %s)" % (node, code, sig.name, proc.log))
        self.check_log(proc.log)

    # --- checks ----------------------------------------------------------------------------
    def check_log(self, path):
        with open(path, errors="replace") as f:
            for line in f:
                if CRASH.search(line):
                    raise Failure("%s: %s" % (os.path.basename(path), line.strip()[:200]))

    def check_no_process_left(self):
        stuck = [c for c in self.pending_calls if (c.join(EXIT_TIMEOUT_S) or c.is_alive())]
        if stuck:
            raise Failure("%d service calls never returned after their nodelet was unloaded"
                          % len(stuck))
        left = [p for p in self.procs if p.alive()]
        if left:
            raise Failure("still running: " + ", ".join(" ".join(p.args[:3]) for p in left))
