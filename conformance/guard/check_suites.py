#!/usr/bin/env python3
"""check_suites.py - the guard of issue 18 section 5: tests that cannot vanish.

    check_suites.py MESON SOURCE_DIR BUILD_DIR

1. The build's feature options (meson_options.txt) are each `enabled` or
   `disabled`: `auto` would drop a suite silently when a package is
   missing, so it is refused (a build without a suite is asked for with
   -DOPTION=disabled).
2. Every test a build with those options must hold is registered (meson
   introspect --tests): the suites and the tests that need OSMesa,
   OpenImageIO, GLFW, assimp or Xvfb; and no test is a stand-in that can
   only fail (`false`, which an `auto` build registers for a window test
   when Xvfb is missing).
3. A fresh configuration of the source tree in which pkg-config finds no
   package (so OSMesa, OpenImageIO, GLFW, X11 and assimp are all missing)
   fails, naming the missing dependency; with -Dconformance=disabled
   -Dviewer=disabled it succeeds and registers none of their suites.

Exit status 0 when all hold, 1 otherwise (each failure is printed).
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

FEATURES = ("conformance", "viewer", "glx")

# What each option, when enabled, must put into `meson test`.
REQUIRED = {
    None: {"suites": {"unit", "api", "threads", "guard", "robust", "packaging"},
           "tests": {"exports", "osmesa_api", "alloc-fail", "alloc-routing", "huge-draws",
                     "cli-options", "packaging-subproject"}},
    "conformance": {
        "suites": {"conformance", "conformance-reference", "conformance-threads", "probes", "oracle",
                   "fuzz", "glu"},
        "tests": {"conformance-core", "conformance-random", "conformance-random-lit",
                  "conformance-random-raster", "conformance-random-tex",
                  "conformance-random-shading", "conform-harness-selftest",
                  "dropin", "osmesa_api_vs_mesa", "threads (oracle)",
                  "fuzz-differential-short", "glu-quadric-textured", "glu-mipmap2d-rgb",
                  "glu-scale-image", "glu-tess-winding", "glu-nurbs-trim", "glu-gl-errors",
                  "glu-scene-list", "conform-report", "driver-stdout"},
    },
    "viewer": {
        "suites": {"glut", "viewer"},
        "tests": {"glut-lit", "glut-menus", "glut-text", "glut-api", "glut-window",
                  "glut-freeglut", "glut-freeglut-demo", "glut-glu", "glut-light",
                  "glut-cylinder-vs-freeglut",
                  "view-window", "view-window-split", "view-window-keys", "view-sphere-ply-flat",
                  "view-window-textured", "view-globe-obj-flat-normals-file",
                  "view-colors-ply-smooth-normals-file", "view-bad-models", "view-progress",
                  "packaging-consumers"},
    },
    "glx": {
        "suites": {"glx"},
        "tests": {"glx-gears", "glx-texcube", "glx-quadrics", "glx-glxapi", "glx-glxgears",
                  "glx-glxinfo", "glx-exports"},
    },
}

failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL: " + msg)


def introspect(meson, build, what):
    out = subprocess.run([meson, "introspect", build, "--" + what], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)


def options_of(meson, build):
    return {o["name"]: o["value"] for o in introspect(meson, build, "buildoptions")}


def suites_of(tests):
    # meson names a suite "project:suite"
    return {s.split(":", 1)[-1] for t in tests for s in t["suite"]}


def check_build(meson, build):
    opts = options_of(meson, build)
    tests = introspect(meson, build, "tests")
    names = {t["name"] for t in tests}
    suites = suites_of(tests)
    for opt in FEATURES:
        value = opts.get(opt)
        if value not in ("enabled", "disabled"):
            fail(f"option {opt} is {value!r}: a suite must be enabled, or disabled on purpose "
                 f"(-D{opt}=disabled), never dropped by `auto`")
    for opt, req in REQUIRED.items():
        if opt is not None and opts.get(opt) != "enabled":
            print(f"note: {opt} is {opts.get(opt)}: its suites are not required")
            continue
        for s in sorted(req["suites"] - suites):
            fail(f"suite {s} is missing from {build}" + (f" (option {opt} is enabled)" if opt else ""))
        for n in sorted(req["tests"] - names):
            fail(f"test {n!r} is missing from {build}" + (f" (option {opt} is enabled)" if opt else ""))
    for t in tests:
        prog = os.path.basename(t["cmd"][0]) if t["cmd"] else ""
        if prog in ("false", "true"):
            fail(f"test {t['name']!r} runs {t['cmd'][0]}: a stand-in for a missing program")
    print(f"{build}: {len(tests)} tests in {len(suites)} suites: {', '.join(sorted(suites))}")
    return opts


def check_missing_packages(meson, source):
    scratch = tempfile.mkdtemp(prefix="fixgl-guard-")
    empty = os.path.join(scratch, "no-pkgconfig")
    os.mkdir(empty)
    env = dict(os.environ, PKG_CONFIG_LIBDIR=empty, PKG_CONFIG_PATH="",
               CMAKE_PREFIX_PATH=empty)
    try:
        # required by default: the configuration fails and says what is missing
        r = subprocess.run([meson, "setup", os.path.join(scratch, "b1"), source], env=env,
                           capture_output=True, text=True)
        log = r.stdout + r.stderr
        if r.returncode == 0:
            fail("meson setup succeeded although pkg-config finds no package: "
                 "a dependency of a suite is not required")
        elif "osmesa" not in log.lower():
            fail("meson setup failed without naming the missing OSMesa:\n" + log[-2000:])
        else:
            line = next((l for l in log.splitlines() if "ERROR" in l), "")
            print(f"without packages, meson setup fails as it must: {line.strip()}")
        # asked for explicitly: a build without the oracle and the viewer
        b2 = os.path.join(scratch, "b2")
        r = subprocess.run([meson, "setup", b2, source, "-Dconformance=disabled", "-Dviewer=disabled",
                            "-Dglx=disabled"],
                           env=env, capture_output=True, text=True)
        if r.returncode != 0:
            fail("meson setup -Dconformance=disabled -Dviewer=disabled -Dglx=disabled failed without packages:\n"
                 + (r.stdout + r.stderr)[-2000:])
        else:
            suites = suites_of(introspect(meson, b2, "tests"))
            for s in sorted(suites & (REQUIRED["conformance"]["suites"] | REQUIRED["viewer"]["suites"]
                                      | REQUIRED["glx"]["suites"])):
                fail(f"suite {s} registered although its option is disabled")
            for s in sorted(REQUIRED[None]["suites"] - suites):
                fail(f"suite {s} is missing from a build without the oracle and the viewer")
            print(f"-Dconformance=disabled -Dviewer=disabled -Dglx=disabled: configures; suites {', '.join(sorted(suites))}")
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    meson, source, build = sys.argv[1:]
    check_build(meson, build)
    check_missing_packages(meson, source)
    if failures:
        print(f"{len(failures)} failure(s)")
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
