#!/usr/bin/python3
"""Checks that the ROS-free layers include only the layers below them (docs/architecture.md#layers):

    codec/      Status/Result, byte I/O, field sinks, value checks, declarative layouts
    protocol/   the K40T pod protocol               -> codec/
    psdk/       the DJI PSDK, beside protocol/      -> codec/, transport/, geo/ (never protocol/)

A layer's files are include/k40t_driver/<layer>/** and src/<layer>/**. Every `#include` of a
k40t_driver header ("k40t_driver/x/..." or <k40t_driver/x/...>, or a relative path that lands in
another layer's directory) must name a layer the table below allows. Prints one line per
violation and exits 1 if there is any, 0 otherwise.

Usage: scripts/check_layers.py [--root DIR]   (default: this repository)"""
import argparse
import os
import re
import sys

# layer -> the layers its files may include (itself included).
ALLOWED = {
    "codec": {"codec"},
    "protocol": {"codec", "protocol"},
    "psdk": {"codec", "transport", "geo", "psdk"},
    "transport": {"codec", "transport"},
}

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
SOURCE_SUFFIXES = (".h", ".hpp", ".cpp", ".cc", ".in")


def layer_of_path(root, path):
    """The layer a file in the tree belongs to, or None."""
    rel = os.path.relpath(os.path.normpath(path), root).split(os.sep)
    if len(rel) >= 3 and rel[0] == "include" and rel[1] == "k40t_driver":
        return rel[2]
    if len(rel) >= 2 and rel[0] == "src":
        return rel[1]
    return None


def included_layer(root, source, quote, target):
    """The layer an include names, or None for a header outside the k40t_driver tree."""
    if target.startswith("k40t_driver/"):
        parts = target.split("/")
        return parts[1] if len(parts) > 2 else None
    if quote == '"':
        resolved = os.path.join(os.path.dirname(source), target)
        if os.path.exists(resolved):
            return layer_of_path(root, resolved)
    return None


def layer_files(root, layer):
    for top in (os.path.join(root, "include", "k40t_driver", layer), os.path.join(root, "src", layer)):
        for directory, _, names in os.walk(top):
            for name in sorted(names):
                if name.endswith(SOURCE_SUFFIXES):
                    yield os.path.join(directory, name)


def violations(root):
    found = []
    for layer, allowed in sorted(ALLOWED.items()):
        for path in layer_files(root, layer):
            with open(path, encoding="utf-8", errors="replace") as source:
                for number, line in enumerate(source, 1):
                    match = INCLUDE.match(line)
                    if not match:
                        continue
                    target_layer = included_layer(root, path, match.group(1), match.group(2))
                    if target_layer is None or target_layer in allowed:
                        continue
                    found.append("%s:%d: %s/ includes %s/ (%s); %s/ may include only %s" % (
                        os.path.relpath(path, root), number, layer, target_layer, match.group(2),
                        layer, ", ".join(l + "/" for l in sorted(allowed))))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    args = parser.parse_args()
    found = violations(os.path.abspath(args.root))
    for line in found:
        print(line)
    checked = sum(1 for layer in ALLOWED for _ in layer_files(os.path.abspath(args.root), layer))
    print("layers: %d files checked, %d includes pointing the wrong way" % (checked, len(found)))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
