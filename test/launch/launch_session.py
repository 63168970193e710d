"""A roslaunch run on a ROS master of its own, for the launch tier's checks that start launch files
(test/launch/check_field.py): a free port, temporary pty and bag paths, the output kept line by
line with its arrival time, and the lines a normal run must not print. Not a test itself."""
import os
import re
import signal
import socket
import subprocess
import threading
import time

# What a normal run must not print: rosconsole and rospy lines of severity WARN and above
# (scripts/ros_env.sh's ROSCONSOLE_FORMAT '[${severity}] ...', rospy's '[WARN] [...]'), OpenCV's
# own log ('[ WARN:0@1.2] global cap_gstreamer.cpp ...'), GLib's and GStreamer's ('** WARNING **',
# 'CRITICAL **') and roslaunch's own complaints (a process that died, a required one).
BAD_LINE = re.compile(r"\[\s*(WARN|ERROR|FATAL)\b|\bWARNING \*\*|CRITICAL \*\*|"
                      r"has died|REQUIRED process|Traceback|RLException")


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class LaunchSession:
    """`roslaunch -p PORT PKG FILE ARGS` (roslaunch starts the master) with its output collected."""

    def __init__(self, launch_file, args=(), pkg="k40t_driver"):
        self.port = free_port()
        self.env = dict(os.environ, ROS_MASTER_URI="http://127.0.0.1:%d" % self.port,
                        ROS_HOSTNAME="127.0.0.1")
        self.env.pop("ROS_IP", None)
        self.lines = []  # (arrival time, text)
        self.lock = threading.Lock()
        self.started = time.time()
        self.process = subprocess.Popen(
            ["roslaunch", "-p", str(self.port), "--screen", pkg, launch_file] + list(args),
            env=self.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True)
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()

    def _read(self):
        for raw in iter(self.process.stdout.readline, b""):
            with self.lock:
                self.lines.append((time.time(), raw.decode("utf-8", "replace").rstrip()))

    def text(self, until=None):
        with self.lock:
            return [t for when, t in self.lines if until is None or when <= until]

    def bad_lines(self, until=None):
        return [t for t in self.text(until) if BAD_LINE.search(t)]

    def wait_for_line(self, pattern, timeout):
        deadline = time.time() + timeout
        while time.time() < deadline:
            if any(re.search(pattern, t) for t in self.text()):
                return True
            if self.process.poll() is not None:
                return False
            time.sleep(0.1)
        return False

    def run(self, *cmd, timeout=60):
        """A command against this session's master; returns (exit code, output)."""
        done = subprocess.run(list(cmd), env=self.env, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, timeout=timeout)
        return done.returncode, done.stdout.decode("utf-8", "replace")

    def wait(self, timeout):
        """Waits for roslaunch to end by itself; returns its exit code (None: still running)."""
        try:
            code = self.process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            return None
        self.reader.join(5.0)
        return code

    def stop(self):
        """Ctrl-C, as a user ends a launch; SIGKILL of the whole group if that hangs."""
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGINT)
            try:
                self.process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                os.killpg(self.process.pid, signal.SIGKILL)
                self.process.wait()
        self.reader.join(5.0)
