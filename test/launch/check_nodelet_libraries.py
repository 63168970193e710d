#!/usr/bin/python3
"""Checks the nodelet plugin files against the libraries a ROS build made (issue 14, item 4).
  - nodelet_plugins.xml declares the three product libraries and nothing else: no library or
    class of bench/bench_nodelet_plugins.xml, no library with "bench" in its name;
  - package.xml exports the bench plugin file only if the ROS build made every library it names;
  - each product library loads only what it uses. What it loads is its ELF DT_NEEDED entries
    (readelf -d), followed through the project's own libraries in the devel space, so a library
    that needs libk40t_pod_nodelet.so also loads what that one needs: the pod driver no OpenCV
    (its lens distortion is opened on first use), GStreamer or OpenSSL, the video nodelet no
    OpenSSL, the SKYPORT bridge no OpenCV or GStreamer; none Qt;
  - the standalone k40t_node loads no nodelet library (nodelet's roslib brings rospack and
    libpython: ~3 MB resident for nothing; issue 24, item 6) and no OpenCV at its start (lens
    distortion is in libk40t_opencv_lens.so, opened on the first pixel located: ~4.8 MB).
    System libraries' own dependencies are not followed: they are not the project's to choose
    (PROJ's libcurl brings libcrypto through libssh2, OpenCV's FFmpeg brings libssl).
Exits 1 naming each failure; --junit writes one test case. Needs no ROS master; run after a ROS
build (scripts/run_tests.sh's launch tier does)."""
import argparse
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PACKAGE = os.path.join(ROOT, "package.xml")
PLUGINS = os.path.join(ROOT, "nodelet_plugins.xml")
BENCH_PLUGINS = os.path.join(ROOT, "bench", "bench_nodelet_plugins.xml")

OPENCV, GSTREAMER, OPENSSL, QT = ("libopencv_",), ("libgst",), ("libssl.", "libcrypto."), ("libQt",)
# Product library (as nodelet_plugins.xml names it) -> prefixes of libraries it must not load.
FORBIDDEN = {
    "lib/libk40t_pod_nodelet": OPENCV + GSTREAMER + OPENSSL + QT,
    "lib/libk40t_video_nodelet": OPENSSL + QT,
    "lib/libk40t_skyport_nodelet": OPENCV + GSTREAMER + QT,
}
# Standalone node (path in the devel space) -> prefixes of libraries it must not load.
NODELET = ("libnodeletlib.", "libclass_loader.", "libroslib.", "librospack.", "libpython")
NODE_FORBIDDEN = {"lib/k40t_driver/k40t_node": NODELET + OPENCV}


def libraries(plugin_file):
    """(library path as written, e.g. lib/libk40t_pod_nodelet; its class names) per <library>."""
    root = ET.parse(plugin_file).getroot()
    return [(lib.get("path"), [c.get("name") for c in lib.findall("class")])
            for lib in root.iter("library")]


def exported_plugin_files():
    """The nodelet plugin files package.xml exports, relative to the package."""
    root = ET.parse(PACKAGE).getroot()
    return [n.get("plugin").replace("${prefix}/", "") for n in root.iter("nodelet")]


def needed(so_path):
    out = subprocess.run(["readelf", "-d", so_path], capture_output=True, text=True,
                         check=True).stdout
    return [line.split("[", 1)[1].rstrip("]") for line in out.splitlines() if "(NEEDED)" in line]


def loaded(so_path, lib_dir):
    """{library name: the chain that loads it}: the NEEDED entries of so_path, and recursively
    those of each needed library that is in lib_dir (the project's own)."""
    chains, todo = {}, [(so_path, os.path.basename(so_path))]
    while todo:
        path, chain = todo.pop()
        for dep in needed(path):
            if dep in chains:
                continue
            chains[dep] = chain + " -> " + dep
            own = os.path.join(lib_dir, dep)
            if os.path.exists(own):
                todo.append((own, chains[dep]))
    return chains


def check_declarations(devel):
    failures = []
    bench = libraries(BENCH_PLUGINS)
    bench_paths = {path for path, _ in bench}
    bench_classes = {name for _, names in bench for name in names}
    declared = libraries(PLUGINS)
    for path, names in declared:
        if path in bench_paths or "bench" in path:
            failures.append("nodelet_plugins.xml declares the benchmark library %s" % path)
        elif path not in FORBIDDEN:
            failures.append("nodelet_plugins.xml declares %s, not a product library (%s)"
                            % (path, ", ".join(sorted(FORBIDDEN))))
        failures += ["nodelet_plugins.xml declares the benchmark class %s" % n
                     for n in names if n in bench_classes]
    missing = sorted(set(FORBIDDEN) - {path for path, _ in declared})
    failures += ["nodelet_plugins.xml does not declare %s" % path for path in missing]
    for path, _ in declared:
        if not os.path.exists(os.path.join(devel, path + ".so")):
            failures.append("%s.so is declared but not built in %s" % (path, devel))
    exported = exported_plugin_files()
    if "nodelet_plugins.xml" not in exported:
        failures.append("package.xml does not export nodelet_plugins.xml")
    if os.path.relpath(BENCH_PLUGINS, ROOT) in exported:
        failures += ["package.xml exports %s but %s.so is not built in %s"
                     % (os.path.relpath(BENCH_PLUGINS, ROOT), path, devel)
                     for path in sorted(bench_paths)
                     if not os.path.exists(os.path.join(devel, path + ".so"))]
    return failures


def forbidden_loads(path, lib_dir, prefixes):
    """Failures for each library the ELF file `path` loads whose name starts with one of prefixes."""
    if not os.path.exists(path):
        return ["%s not built" % path]
    return ["%s loads %s (%s)" % (os.path.basename(path), dep, chain)
            for dep, chain in sorted(loaded(path, lib_dir).items()) if dep.startswith(prefixes)]


def check_links(devel):
    failures = []
    for path, prefixes in sorted(FORBIDDEN.items()):
        so = os.path.join(devel, path + ".so")
        failures += forbidden_loads(so, os.path.dirname(so), prefixes)
    for path, prefixes in sorted(NODE_FORBIDDEN.items()):
        failures += forbidden_loads(os.path.join(devel, path), os.path.join(devel, "lib"), prefixes)
    return failures


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--devel", default=os.environ.get("K40T_DEVEL", os.path.join(ROOT, "devel")),
                    help="the catkin devel space (default: $K40T_DEVEL or devel/)")
    ap.add_argument("--junit", help="JUnit XML output path (one test case)")
    options = ap.parse_args()
    failures = check_declarations(options.devel) + check_links(options.devel)
    for failure in failures:
        print("FAIL " + failure)
    if options.junit:
        suite = ET.Element("testsuite", name="nodelet_libraries", tests="1",
                           failures=str(min(1, len(failures))), errors="0")
        case = ET.SubElement(suite, "testcase", classname="launch_files", name="nodelet libraries")
        if failures:
            ET.SubElement(case, "failure", message="nodelet libraries").text = "\n".join(failures)
        os.makedirs(os.path.dirname(os.path.abspath(options.junit)), exist_ok=True)
        ET.ElementTree(suite).write(options.junit, encoding="utf-8", xml_declaration=True)
    print("nodelet libraries: %s" % ("%d failures" % len(failures) if failures else "ok"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
