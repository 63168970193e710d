#!/usr/bin/python3
"""The package's conventions, checked from the source tree (no build, no ROS master):

  layers          scripts/check_layers.py passes: codec/ includes only codec/, protocol/ only
                  codec/ and itself, psdk/ never protocol/ (docs/architecture.md#layers);
  layers_can_fail the same script fails, naming file and line, on a tree where codec/ includes
                  protocol/ and psdk/ includes protocol/;
  catkin_lint     `catkin_lint .` reports 0 errors (and the warnings it reports are listed);
  catkin_lint_can_fail  catkin_lint reports the error for a package.xml that declares a build
                  dependency the CMake files never configure;
  readme_size     README.md is at most 10 KB (it is the front door; the rest is in docs/);
  readme_links_every_doc  every docs/**/*.md is linked from README.md.

Writes one JUnit test case per check to --junit; exits 1 on any failure.
Run by the launch tier of scripts/run_tests.sh."""
import argparse
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

from checks_report import run_checks

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
README_LIMIT_BYTES = 10 * 1024


def run(command, cwd=ROOT):
    done = subprocess.run(command, cwd=cwd, capture_output=True, text=True, check=False)
    return done.returncode, done.stdout + done.stderr


def check_layers():
    rc, out = run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "check_layers.py")])
    return None if rc == 0 else "scripts/check_layers.py failed:\n" + out


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as out:
        out.write(text)


def check_layers_can_fail():
    with tempfile.TemporaryDirectory(prefix="k40t_layers_") as tree:
        write(os.path.join(tree, "include/k40t_driver/codec/wire.h"),
              '#pragma once\n#include <cstdint>\n#include "k40t_driver/protocol/message.h"\n')
        write(os.path.join(tree, "src/psdk/frame.cpp"),
              '#include "k40t_driver/psdk/frame.h"\n#include <k40t_driver/protocol/result.h>\n')
        write(os.path.join(tree, "src/codec/layout.cpp"), '#include "../protocol/crc.h"\n')
        write(os.path.join(tree, "src/protocol/crc.h"), "#pragma once\n")
        rc, out = run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "check_layers.py"),
                       "--root", tree])
    expected = ["include/k40t_driver/codec/wire.h:3: codec/ includes protocol/",
                "src/psdk/frame.cpp:2: psdk/ includes protocol/",
                "src/codec/layout.cpp:1: codec/ includes protocol/"]
    missing = [line for line in expected if line not in out]
    if rc != 1 or missing:
        return "check_layers.py on a tree with wrong-way includes: exit %d, missing %s:\n%s" % (
            rc, missing, out)
    return None


def catkin_lint(path):
    """(errors, warnings) lines of catkin_lint on the package at `path`."""
    _, out = run(["catkin_lint", path])
    errors = [l for l in out.splitlines() if ": error: " in l]
    warnings = [l for l in out.splitlines() if ": warning: " in l]
    return errors, warnings, out


def check_catkin_lint():
    if shutil.which("catkin_lint") is None:
        return "catkin_lint is not installed (Debian package catkin-lint, scripts/install_deps.sh)"
    errors, warnings, out = catkin_lint(ROOT)
    for line in warnings:
        print("  catkin_lint " + line)
    if errors:
        return "catkin_lint reports %d errors:\n%s" % (len(errors), out)
    if "checked 1 packages" not in out:
        return "catkin_lint checked no package:\n" + out
    return None


def check_catkin_lint_can_fail():
    if shutil.which("catkin_lint") is None:
        return "catkin_lint is not installed"
    with tempfile.TemporaryDirectory(prefix="k40t_lint_") as copy:
        package = os.path.join(copy, "k40t_driver")
        os.mkdir(package)
        for name in os.listdir(ROOT):
            if name not in ("package.xml", ".git", "build", "devel"):
                os.symlink(os.path.join(ROOT, name), os.path.join(package, name))
        with open(os.path.join(ROOT, "package.xml")) as source:
            manifest = source.read()
        write(os.path.join(package, "package.xml"),
              manifest.replace("<depend>roscpp</depend>",
                               "<depend>roscpp</depend>\n  <depend>cv_bridge</depend>", 1))
        errors, _, out = catkin_lint(package)
    if not any("unconfigured build_depend on 'cv_bridge'" in line for line in errors):
        return "catkin_lint did not report the unconfigured cv_bridge dependency:\n" + out
    return None


def check_readme_size():
    size = os.path.getsize(os.path.join(ROOT, "README.md"))
    if size > README_LIMIT_BYTES:
        return "README.md is %d bytes, more than %d: move details to docs/" % (
            size, README_LIMIT_BYTES)
    return None


def check_readme_links_every_doc():
    with open(os.path.join(ROOT, "README.md")) as source:
        readme = source.read()
    linked = set(re.findall(r"\]\((docs/[^)#\s]+\.md)(?:#[^)]*)?\)", readme))
    docs = sorted(os.path.relpath(p, ROOT)
                  for p in glob.glob(os.path.join(ROOT, "docs", "**", "*.md"), recursive=True))
    missing = [d for d in docs if d not in linked]
    if missing:
        return "README.md's documentation table does not link: " + ", ".join(missing)
    if not docs:
        return "no docs/*.md found: the scan is broken"
    return None


CHECKS = [
    ("layers", check_layers),
    ("layers_can_fail", check_layers_can_fail),
    ("catkin_lint", check_catkin_lint),
    ("catkin_lint_can_fail", check_catkin_lint_can_fail),
    ("readme_size", check_readme_size),
    ("readme_links_every_doc", check_readme_links_every_doc),
]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--junit", help="write JUnit XML here")
    args = parser.parse_args()
    return 1 if run_checks("package", CHECKS, args.junit) else 0


if __name__ == "__main__":
    sys.exit(main())
