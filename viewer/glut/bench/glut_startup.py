#!/usr/bin/env python3
"""glut_startup.py - what a headless GLUT program costs to start.

    glut_startup.py [--runs N] [--check LIBFIXGLUT] GLUT_PROGRAM OSMESA_PROGRAM

Runs the two start-up programs of this directory (startup_glut.c on
libfixglut, FIXGLUT_HEADLESS=1, one frame, no image; startup_osmesa.c on
Mesa's OSMesa) N times each (default 5) and prints, for each, the median
time from exec to the first frame's drawing and the peak resident size
(VmHWM).  Prints numbers only: timings are not asserted anywhere.

--check LIBFIXGLUT (the test glut-light; --needed-only skips the size): also fails (exit 1) when the
GLUT program's resident size exceeds twice the OSMesa program's, or when
LIBFIXGLUT's NEEDED entries (readelf -d) name OpenImageIO, libpng or GLFW,
which the layer may only load when it writes a frame or opens a window.
"""
import argparse
import os
import statistics
import subprocess
import sys
import time

FORBIDDEN_NEEDED = ("OpenImageIO", "libpng", "libglfw")


def run_once(prog):
    env = dict(os.environ, FIXGLUT_HEADLESS="1", FIXGLUT_FRAMES="1", FIXGLUT_OUT="")
    env.pop("FIXGLUT_EVENTS", None)
    env["STARTUP_T0_NS"] = str(time.clock_gettime_ns(time.CLOCK_REALTIME))
    out = subprocess.run([prog], env=env, capture_output=True, text=True, timeout=60)
    if out.returncode != 0:
        raise SystemExit(f"{prog} failed ({out.returncode}):\n{out.stderr}")
    vals = dict(line.split() for line in out.stdout.splitlines() if line.strip())
    return float(vals["startup_ms"]), int(vals["vmhwm_kb"])


def measure(prog, runs):
    samples = [run_once(prog) for _ in range(runs)]
    return statistics.median(s[0] for s in samples), max(s[1] for s in samples)


def needed(lib):
    out = subprocess.run(["readelf", "-d", lib], check=True, capture_output=True, text=True).stdout
    return [l.split("[", 1)[1].rstrip("]") for l in out.splitlines() if "(NEEDED)" in l]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--check", metavar="LIBFIXGLUT")
    ap.add_argument("--needed-only", action="store_true",
                    help="with --check: the NEEDED list only (sanitized builds)")
    ap.add_argument("glut_program")
    ap.add_argument("osmesa_program")
    a = ap.parse_args()
    g_ms, g_kb = measure(a.glut_program, a.runs)
    o_ms, o_kb = measure(a.osmesa_program, a.runs)
    print(f"libfixglut headless frame: start {g_ms:7.2f} ms, resident {g_kb / 1024:7.1f} MB")
    print(f"bare OSMesa (Mesa) frame:  start {o_ms:7.2f} ms, resident {o_kb / 1024:7.1f} MB")
    print(f"ratio: start {g_ms / o_ms:.2f}x, resident {g_kb / o_kb:.2f}x")
    if not a.check:
        return 0
    bad = []
    if a.needed_only:
        print("resident size not checked (--needed-only)")
    elif g_kb > 2 * o_kb:
        bad.append(f"resident size {g_kb} kB is more than twice the OSMesa program's {o_kb} kB")
    libs = needed(a.check)
    print("libfixglut NEEDED: " + " ".join(libs))
    for lib in libs:
        if any(f in lib for f in FORBIDDEN_NEEDED):
            bad.append(f"{a.check} has NEEDED {lib}: it must be loaded only when used")
    for b in bad:
        print("FAIL: " + b)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
