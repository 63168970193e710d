"""Runs rviz with the PodPanel on a virtual X display of its own and works the panel through its
test hook (src/rviz/panel_test_hook.h): each command line becomes real mouse or key events on a
named widget. Used by test_panel.py; not a test itself."""
import os
import re
import shutil
import signal
import subprocess
import tempfile
import time


class PanelError(AssertionError):
    pass


class RvizPanel:
    def __init__(self, rviz_config, namespace, startup_timeout=120.0):
        """rviz with a copy of `rviz_config` whose PodPanel has the driver namespace `namespace`."""
        self.dir = tempfile.mkdtemp(prefix="k40t_panel_")
        config = os.path.join(self.dir, "panel.rviz")
        with open(rviz_config) as f:
            text, count = re.subn(r"^(\s+Namespace: ).*$", r"\g<1>" + namespace, f.read(), flags=re.M)
        if count != 1:
            raise PanelError("%s: %d PodPanel Namespace lines, expected 1" % (rviz_config, count))
        with open(config, "w") as f:
            f.write(text)
        self.commands = os.path.join(self.dir, "commands")
        self.replies = self.commands + ".replies"
        open(self.commands, "w").close()
        self.sent = 0
        self.xvfb, self.display = self._start_xvfb()
        env = dict(os.environ, DISPLAY=self.display, K40T_PANEL_TEST_COMMANDS=self.commands)
        self.log = open(os.path.join(self.dir, "rviz.log"), "w")
        self.rviz = subprocess.Popen(["rviz", "-d", config, "__name:=panel_test_rviz"], env=env,
                                     stdout=self.log, stderr=subprocess.STDOUT)
        try:
            self._wait_until_shown(startup_timeout)
        except BaseException:
            self.close()  # a panel that never came up must not leave rviz and Xvfb running
            raise

    def _wait_until_shown(self, timeout):
        """The hook answers as soon as the panel exists, which on a loaded machine can be before
        rviz has shown its window ("... is not visible"): ask again until the panel is shown."""
        deadline = time.time() + timeout
        while True:
            try:
                self.text("message", timeout=max(1.0, deadline - time.time()))
                return
            except PanelError as error:
                if "not visible" not in str(error) or time.time() >= deadline:
                    raise
                time.sleep(0.2)

    @staticmethod
    def _start_xvfb():
        """Xvfb on a display number it picks itself (-displayfd): no clash with other runs."""
        read_end, write_end = os.pipe()
        xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(write_end), "-screen", "0", "1600x1000x24",
                                 "-nolisten", "tcp"], pass_fds=(write_end,),
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(write_end)
        number = b""
        with os.fdopen(read_end, "rb") as pipe:
            while not number.endswith(b"\n"):
                chunk = pipe.read(1)
                if not chunk:
                    raise PanelError("Xvfb did not start")
                number += chunk
        return xvfb, ":" + number.decode().strip()

    def alive(self):
        return self.rviz.poll() is None

    def do(self, line, timeout=30.0):
        """Sends one command, returns the reply's text; raises on an error reply or no reply."""
        return self.do_together([line], timeout)[0]

    def do_together(self, lines, timeout=30.0):
        """Sends the commands in one write: the hook carries them out one after the other in the
        same pass, with no event processed in between. Returns their replies' texts."""
        first = self.sent + 1
        self.sent += len(lines)
        with open(self.commands, "a") as f:
            f.write("".join(line + "\n" for line in lines))
        return [self._reply(first + i, line, timeout) for i, line in enumerate(lines)]

    def _reply(self, n, line, timeout):
        deadline = time.time() + timeout
        while time.time() < deadline:
            if not self.alive():
                raise PanelError("rviz exited (%s) during '%s'; log: %s" % (self.rviz.returncode, line, self.log.name))
            for reply in self._replies():
                number, _, rest = reply.partition(" ")
                if number == str(n):
                    verdict, _, text = rest.partition(" ")
                    if verdict != "ok":
                        raise PanelError("panel refused '%s': %s" % (line, text))
                    return text
            time.sleep(0.05)
        raise PanelError("no reply to '%s' within %.0f s" % (line, timeout))

    def _replies(self):
        try:
            with open(self.replies) as f:
                return [l.strip() for l in f if l.strip()]
        except FileNotFoundError:
            return []

    def text(self, label, timeout=30.0):
        return self.do("text " + label, timeout)

    def close(self):
        """Stops rviz (SIGINT, as Ctrl-C) and the X server; returns rviz's exit code."""
        if self.xvfb.poll() is not None:
            return self.rviz.returncode  # closed before
        code = self.rviz.returncode
        if self.alive():
            self.rviz.send_signal(signal.SIGINT)
            try:
                code = self.rviz.wait(20)
            except subprocess.TimeoutExpired:
                self.rviz.kill()
                code = self.rviz.wait()
        self.xvfb.terminate()
        self.xvfb.wait(10)
        self.log.close()
        if code == 0:
            shutil.rmtree(self.dir, ignore_errors=True)  # kept when rviz failed: its log is there
        return code
