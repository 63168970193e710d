#!/usr/bin/python3
"""Checks, offline, that scripts/install_deps.sh installs everything the package's Python code and
launch files need, on a machine that has only the base image plus that list.

It derives the needs from the source itself:
  - every module imported by a .py file under scripts/, test/, bench/ and tools/ (standard library
    and the package's own modules left out);
  - every node and test type the launch files start (launch/, test/ros/, bench/), every package
    they include files from, and every nodelet class they load from another package;
  - every external command the shell scripts run (scripts/, bench/, test/, .ci/run); commands of
    Essential or required packages count as present.
For each need it finds the Debian package that provides it (`dpkg -S` on the module's or the
executable's file) and fails, naming the need and the package, when that package is neither
listed in install_deps.sh nor pulled in by a package that is (`apt-cache depends --recurse`, the
same Depends/Pre-Depends closure that `apt-get install --no-install-recommends` installs). A need
that is not installed at all fails with the Debian package that would provide it.
It also checks that every ROS package among the needs is declared in package.xml.

  check_deps.py [--junit FILE] [--without PKG ...]

--without PKG drops PKG from install_deps.sh's list for this run: `--without python3-sensor-msgs`
must fail (scripts/run_tests.sh runs that too, so the checker itself is shown to be able to fail).
Exit status 1 when a need is not covered."""
import argparse
import ast
import glob
import importlib.util
import os
import re
import shutil
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PACKAGE = "k40t_driver"
PYTHON_DIRS = ["scripts", "test", "bench", "tools"]
SHELL_GLOBS = ["scripts/*.sh", "bench/**/*.sh", "test/**/*.sh", ".ci/run"]
SHELL_WORDS = set("""if then else elif fi for while until do done case esac in function select time
  local export source . echo printf read cd pwd set shift exit return trap wait kill true false test
  [ [[ eval exec declare typeset shopt unset command type break continue let builtin getopts hash
  ulimit umask alias mapfile readarray pushd popd dirs jobs fg bg disown suspend""".split())
LAUNCH_GLOBS = ["launch/*.launch", "test/ros/*.test", "bench/**/*.launch"]


def listed_packages(without):
    """The `packages=( ... )` array of scripts/install_deps.sh."""
    text = open(os.path.join(ROOT, "scripts", "install_deps.sh")).read()
    match = re.search(r"^packages=\((.*?)^\)", text, re.S | re.M)
    if not match:
        sys.exit("check_deps: no packages=( ... ) list in scripts/install_deps.sh")
    body = "\n".join(line.split("#", 1)[0] for line in match.group(1).splitlines())
    return [p for p in body.split() if p not in without]


def dependency_closure(packages):
    """Every package apt installs for `packages` without recommends (Depends and Pre-Depends)."""
    out = subprocess.run(
        ["apt-cache", "depends", "--recurse", "--no-recommends", "--no-suggests", "--no-conflicts",
         "--no-breaks", "--no-replaces", "--no-enhances"] + packages,
        capture_output=True, text=True, check=False).stdout
    closure = set(packages)
    for line in out.splitlines():
        if line and not line[0].isspace():
            closure.add(line.strip().strip("<>").split(":")[0])
        else:
            m = re.match(r"\s*\|?(?:Pre)?Depends:\s*<?([^>\s]+)>?", line)
            if m:
                closure.add(m.group(1).split(":")[0])
    return closure


def dpkg_owner(path):
    """The Debian package owning `path` (symlinks resolved), or None."""
    # usrmerge: /usr/bin/cat is the file dpkg knows as /bin/cat.
    unmerged = re.sub(r"^/usr/(s?bin|lib)/", r"/\1/", path)
    for candidate in (path, os.path.realpath(path), unmerged):
        out = subprocess.run(["dpkg", "-S", candidate], capture_output=True, text=True, check=False)
        if out.returncode == 0 and out.stdout:
            # "pkg1, pkg2:arch: /path" (diversions print more lines; take the owning line)
            for line in out.stdout.splitlines():
                if ": " in line and not line.startswith("diversion"):
                    return line.split(": ", 1)[0].split(",")[0].strip().split(":")[0]
    return None


def apt_has(package):
    out = subprocess.run(["apt-cache", "show", "--no-all-versions", package],
                         capture_output=True, text=True, check=False)
    return out.returncode == 0 and "Package:" in out.stdout


def guess_package(candidates):
    """The first candidate name Debian's archive has (for a need that is not installed)."""
    for name in candidates:
        if apt_has(name):
            return name
    return " or ".join(candidates) + " (none found in the apt cache)"


def local_python_modules():
    names = {PACKAGE}
    for d in PYTHON_DIRS:
        for path in glob.glob(os.path.join(ROOT, d, "**", "*.py"), recursive=True):
            names.add(os.path.splitext(os.path.basename(path))[0])
    return names


def python_imports():
    """{module: [file, ...]} for every top-level module imported by the package's Python files."""
    stdlib = set(sys.stdlib_module_names)
    local = local_python_modules()
    found = {}
    for d in PYTHON_DIRS:
        for path in sorted(glob.glob(os.path.join(ROOT, d, "**", "*.py"), recursive=True)):
            rel = os.path.relpath(path, ROOT)
            tree = ast.parse(open(path, encoding="utf-8").read(), rel)
            for node in ast.walk(tree):
                if isinstance(node, ast.Import):
                    names = [alias.name for alias in node.names]
                elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                    names = [node.module]
                else:
                    continue
                for name in names:
                    top = name.split(".")[0]
                    if top not in stdlib and top not in local:
                        found.setdefault(top, []).append(rel)
    return found


def module_file(name):
    spec = importlib.util.find_spec(name)
    if spec is None:
        return None
    if spec.origin and spec.origin not in ("built-in", "frozen", "namespace"):
        return spec.origin
    locations = list(spec.submodule_search_locations or [])
    return locations[0] if locations else None


def launch_needs():
    """{(kind, package, name): [file, ...]} for nodes, includes and nodelets of other packages."""
    found = {}
    files = []
    for pattern in LAUNCH_GLOBS:
        files += sorted(glob.glob(os.path.join(ROOT, pattern), recursive=True))
    for path in files:
        rel = os.path.relpath(path, ROOT)
        for element in ET.parse(path).getroot().iter():
            if element.tag in ("node", "test"):
                pkg, exe = element.get("pkg", ""), element.get("type", "")
                if pkg and pkg != PACKAGE:
                    found.setdefault(("node", pkg, exe), []).append(rel)
                load = re.match(r"\s*(?:standalone|load)\s+([\w]+)/(\w+)", element.get("args", ""))
                if pkg == "nodelet" and load and load.group(1) != PACKAGE:
                    found.setdefault(("nodelet", load.group(1), load.group(2)), []).append(rel)
            elif element.tag == "include":
                m = re.match(r"\$\(find (\w+)\)", element.get("file", ""))
                if m and m.group(1) != PACKAGE:
                    found.setdefault(("include", m.group(1), ""), []).append(rel)
    return found


def shell_commands():
    """{command: [file, ...]} for every external command a shell script of the package runs:
    the first word of each simple command, heredocs and the scripts' own functions left out."""
    found = {}
    files = []
    for pattern in SHELL_GLOBS:
        files += sorted(glob.glob(os.path.join(ROOT, pattern), recursive=True))
    starts = re.compile(r"(?:^|(?<![$(])[|;&({]|\$\((?!\()|\b(?:then|do|else|elif|if|while|until|time)\s)\s*"
                        r"((?:[A-Za-z_]\w*=\S*\s+)*)([A-Za-z][\w.+-]*)(?=\s|$|;|\))")
    for path in files:
        rel = os.path.relpath(path, ROOT)
        # Array bodies (install_deps.sh's package list) are words, not commands.
        text = re.sub(r"^\s*\w+=\((.*?)\)", "", open(path, encoding="utf-8").read(), flags=re.S | re.M)
        functions = set(re.findall(r"^\s*([A-Za-z_][\w-]*)\s*\(\)", text, re.M))
        heredoc_end = None
        for line in text.splitlines():
            if heredoc_end is not None:
                if line.strip() == heredoc_end:
                    heredoc_end = None
                continue
            heredoc = re.search(r"<<-?\s*['\"]?(\w+)['\"]?", line)
            code = re.sub(r"'[^']*'|\"[^\"]*\"", "''", line.split(" #", 1)[0])
            code = re.sub(r"\$\(\(.*?\)\)", "0", code)  # arithmetic, not a command
            if code.lstrip().startswith("#"):
                continue
            for _, word in starts.findall(code):
                if word not in SHELL_WORDS and word not in functions and "=" not in word:
                    found.setdefault(word, []).append(rel)
            if heredoc:
                heredoc_end = heredoc.group(1)
    return found


def essential(package):
    """Packages every Debian system has (Essential or Priority required), listed or not."""
    out = subprocess.run(["dpkg-query", "-W", "-f=${Essential} ${Priority}", package],
                         capture_output=True, text=True, check=False).stdout
    return out.startswith("yes") or "required" in out


def ros_package_share(pkg):
    path = os.path.join("/usr/share", pkg, "package.xml")
    return path if os.path.exists(path) else None


def node_file(pkg, exe):
    for base in ("/usr/lib", "/usr/libexec", "/usr/share"):
        path = os.path.join(base, pkg, exe)
        if os.path.exists(path):
            return path
    return None


def declared_ros_dependencies():
    root = ET.parse(os.path.join(ROOT, "package.xml")).getroot()
    tags = ("depend", "exec_depend", "test_depend", "build_depend", "run_depend")
    return {e.text.strip() for e in root if e.tag in tags and e.text}


class Report:
    def __init__(self):
        self.cases = []  # (name, failure or None)

    def check(self, name, failure):
        self.cases.append((name, failure))
        if failure:
            print("FAIL %s: %s" % (name, failure))

    def failures(self):
        return [c for c in self.cases if c[1]]

    def write_junit(self, path, seconds):
        suite = ET.Element("testsuite", name="dependencies", tests=str(len(self.cases)),
                           failures=str(len(self.failures())), time="%.1f" % seconds)
        for name, failure in self.cases:
            case = ET.SubElement(suite, "testcase", classname="dependencies", name=name)
            if failure:
                ET.SubElement(case, "failure", message=failure)
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
        ET.ElementTree(suite).write(path, encoding="unicode", xml_declaration=True)


def covered(report, name, package, closure, where):
    if package in closure:
        report.check(name, None)
    else:
        report.check(name, "%s (used by %s) comes from the Debian package %s, which "
                     "scripts/install_deps.sh neither lists nor pulls in" % (name, where, package))


def check_python(report, closure, declared):
    for module, files in sorted(python_imports().items()):
        where = ", ".join(sorted(set(files))[:3])
        name = "python module %s" % module
        path = module_file(module)
        if path is None:
            package = guess_package(["python3-" + module.replace("_", "-").lower()])
            report.check(name, "%s (used by %s) is not installed for /usr/bin/python3; Debian "
                         "package %s provides it: add it to scripts/install_deps.sh"
                         % (module, where, package))
            continue
        package = dpkg_owner(path)
        if package is None:
            report.check(name, "%s (%s, used by %s) belongs to no Debian package (installed by "
                         "hand?)" % (module, path, where))
            continue
        covered(report, name, package, closure, where)
        if ros_package_share(module) and module not in declared:
            report.check("package.xml declares %s" % module,
                         "ROS package %s (used by %s) is not a dependency in package.xml"
                         % (module, where))


def check_launch(report, closure, declared):
    for (kind, pkg, name), files in sorted(launch_needs().items()):
        where = ", ".join(sorted(set(files))[:3])
        label = "%s %s/%s" % (kind, pkg, name) if name else "%s %s" % (kind, pkg)
        path = node_file(pkg, name) if kind == "node" else ros_package_share(pkg)
        if path is None:
            package = guess_package(["ros-" + pkg.replace("_", "-"), pkg.replace("_", "-"),
                                     "lib%s-tools" % pkg.replace("_", "-"),
                                     "lib%s-dev" % pkg.replace("_", "-")])
            report.check(label, "%s (started by %s) is not installed; Debian package %s provides "
                         "it: add it to scripts/install_deps.sh" % (label, where, package))
            continue
        package = dpkg_owner(path)
        if package is None:
            report.check(label, "%s (%s) belongs to no Debian package" % (label, path))
            continue
        covered(report, label, package, closure, where)
        if pkg not in declared:
            report.check("package.xml declares %s" % pkg,
                         "ROS package %s (used by %s) is not a dependency in package.xml"
                         % (pkg, where))


def check_shell(report, closure):
    for command, files in sorted(shell_commands().items()):
        where = ", ".join(sorted(set(files))[:3])
        name = "command %s" % command
        if os.path.exists(os.path.join(ROOT, "scripts", command)):
            continue  # one of the package's own scripts
        path = shutil.which(command, path="/usr/local/bin:/usr/bin:/bin:/usr/sbin:/sbin")
        if path is None:
            report.check(name, "%s (run by %s) is not installed; add its Debian package to "
                         "scripts/install_deps.sh" % (command, where))
            continue
        package = dpkg_owner(path)
        if package is None:
            report.check(name, "%s (%s, run by %s) belongs to no Debian package" % (command, path,
                                                                                    where))
        elif essential(package):
            report.check(name, None)
        else:
            covered(report, name, package, closure, where)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--junit", help="JUnit XML output path")
    ap.add_argument("--without", action="append", default=[], metavar="PKG",
                    help="leave PKG out of install_deps.sh's list for this run")
    options = ap.parse_args()
    start = time.monotonic()

    packages = listed_packages(set(options.without))
    closure = dependency_closure(packages)
    declared = declared_ros_dependencies()
    report = Report()
    check_python(report, closure, declared)
    check_launch(report, closure, declared)
    check_shell(report, closure)

    seconds = time.monotonic() - start
    if options.junit:
        report.write_junit(options.junit, seconds)
    failed = len(report.failures())
    print("check_deps: %d needs checked against %d listed packages (%d with their dependencies): "
          "%d not covered (%.1f s)" % (len(report.cases), len(packages), len(closure), failed,
                                       seconds))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
