#!/usr/bin/python3
"""`rosbag play ARGS` for launch/replay.launch, which then stops the launch the way Ctrl-C does.

roslaunch ends a launch when a process marked required="true" exits, but it then prints the red
"REQUIRED process [...] has died!" banner even for a clean exit: a replay that simply reached the
end of its bag looked like a crash. This wrapper plays the bag as a plain (not required) node and,
once `rosbag play` has ended, sends SIGINT to the roslaunch that started it, so the launch shuts
down as on Ctrl-C, quietly. Its exit code is rosbag play's (non-zero still shows as an error).

Usage (replay.launch does this): k40t_replay_play.py [rosbag play options] --bags=FILE
Run from anything but roslaunch (e.g. rosrun), it only plays the bag."""
import os
import signal
import subprocess
import sys


def parent_is_roslaunch():
    """True when the parent process is roslaunch: only then is the SIGINT ours to send."""
    try:
        with open("/proc/%d/cmdline" % os.getppid(), "rb") as f:
            argv = f.read().split(b"\0")
    except OSError:
        return False
    return any(os.path.basename(arg) == b"roslaunch" for arg in argv[:2])


def main(args):
    # roslaunch appends __name:=... and __log:=... remappings: rosbag play needs none of them.
    play_args = [a for a in args if ":=" not in a]
    player = subprocess.Popen(["rosbag", "play"] + play_args)

    stopped = []

    def forward(signum, _frame):  # the launch is shutting down first: stop the player with it
        stopped.append(signum)
        if player.poll() is None:
            player.send_signal(signum)

    signal.signal(signal.SIGINT, forward)
    signal.signal(signal.SIGTERM, forward)
    code = player.wait()
    if not stopped and parent_is_roslaunch():
        print("k40t_replay_play: the bag has ended, stopping the replay", flush=True)
        os.kill(os.getppid(), signal.SIGINT)
    return code


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
