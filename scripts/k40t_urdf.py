#!/usr/bin/python3
"""Prints urdf/k40t.urdf with another frame and joint prefix, optionally mounted on a parent frame.

Debian ships no xacro, so launch files get a prefixed copy of the one URDF from this script:
  <param name="robot_description"
         command="$(find k40t_driver)/scripts/k40t_urdf.py --prefix pod_a_"/>
The prefix replaces the file's own "k40t_" at the start of every link and joint name (and of
every joint's parent and child link), so it must equal the driver's frame_prefix and
joint_prefix. --mount-parent FRAME adds a fixed joint FRAME -> <prefix>base_link (--mount-xyz,
--mount-rpy: its origin), which puts several pods in one TF tree under a vehicle frame.
Exit status 2, with the reason on stderr, on a bad prefix, frame or number."""
import argparse
import math
import os
import re
import sys
import xml.etree.ElementTree as ET

URDF = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "urdf", "k40t.urdf")
FILE_PREFIX = "k40t_"
# A frame id or joint name: what tf2 and urdfdom accept without surprises (no '/', no spaces).
NAME = re.compile(r"^[A-Za-z0-9_.-]*$")


def three_numbers(text):
    """'x y z' -> the same three numbers as text (for an origin attribute), or ValueError."""
    try:
        numbers = [float(p) for p in text.split()]
    except ValueError:
        numbers = []
    if len(numbers) != 3 or not all(math.isfinite(n) for n in numbers):
        raise ValueError("expected three numbers, got '%s'" % text)
    return " ".join(repr(n) for n in numbers)


def renamed(name, prefix):
    if not name.startswith(FILE_PREFIX):
        raise ValueError("'%s' in %s does not start with '%s'" % (name, URDF, FILE_PREFIX))
    return prefix + name[len(FILE_PREFIX):]


def prefixed(root, prefix):
    """Renames, in place, every link and joint of `root` and each joint's parent and child."""
    for element in root:
        if element.tag in ("link", "joint"):
            element.set("name", renamed(element.get("name", ""), prefix))
        if element.tag == "joint":
            for end in list(element.iter("parent")) + list(element.iter("child")):
                end.set("link", renamed(end.get("link", ""), prefix))
    return root


def mount(root, prefix, parent, xyz, rpy):
    """Adds the fixed joint parent -> <prefix>base_link (and the parent link itself)."""
    ET.SubElement(root, "link", name=parent)
    joint = ET.SubElement(root, "joint", name=prefix + "mount_joint", type="fixed")
    ET.SubElement(joint, "parent", link=parent)
    ET.SubElement(joint, "child", link=prefix + "base_link")
    ET.SubElement(joint, "origin", xyz=xyz, rpy=rpy)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--prefix", default=FILE_PREFIX, help="frame and joint prefix (default k40t_)")
    ap.add_argument("--mount-parent", default="", help="frame the pod's base_link is fixed to")
    ap.add_argument("--mount-xyz", default="0 0 0", help="'x y z' of the mount, metres")
    ap.add_argument("--mount-rpy", default="0 0 0", help="'roll pitch yaw' of the mount, radians")
    options = ap.parse_args()
    try:
        if not NAME.match(options.prefix) or not NAME.match(options.mount_parent):
            raise ValueError("prefix and mount parent may hold only letters, digits, '_', '.', '-'")
        xyz = three_numbers(options.mount_xyz)
        rpy = three_numbers(options.mount_rpy)
        root = prefixed(ET.parse(URDF).getroot(), options.prefix)
        if options.mount_parent:
            if options.mount_parent.startswith(options.prefix) and options.prefix:
                raise ValueError("the mount parent '%s' carries the pod's own prefix" % options.mount_parent)
            mount(root, options.prefix, options.mount_parent, xyz, rpy)
    except (ValueError, OSError, ET.ParseError) as e:
        sys.stderr.write("k40t_urdf: %s\n" % e)
        return 2
    sys.stdout.write(ET.tostring(root, encoding="unicode") + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
