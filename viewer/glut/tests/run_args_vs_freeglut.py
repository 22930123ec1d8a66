#!/usr/bin/env python3
"""run_args_vs_freeglut.py - glutInit's command line, freeglut's against
libfixglut's.

    run_args_vs_freeglut.py XVFB FREEGLUT_EXE FIXGLUT_EXE

FREEGLUT_EXE and FIXGLUT_EXE are glut_args.c built on Debian's libglut
(run on a private 1280x1024 Xvfb: freeglut's glutInit opens the display)
and on libfixglut (headless, whose screen is 1280x1024).  Each command
line below runs on both, as argv[0] "glut-args" (@DISPLAY@ is the
Xvfb's display, which freeglut opens); the output (stdout and
stderr) and the exit status must be the same, and each case's expected
effect is checked on the way so that two equally wrong runs fail too.
(A -geometry that XParseGeometry refuses is not among them: freeglut then
reports an uninitialised width.)
"""
import os
import subprocess
import sys

# (arguments, a line the output must contain)
CASES = [
    ([], "glutInit left 1 of 1 arguments:"),
    (["-f", "3", "-w", "scene.obj"], "demo: frames 3, wire 1"),
    (["--frames=5", "-geometry", "200x100+10+20", "--title", "t"],
     "init window: 10 20 200x100"),
    (["-geometry", "640x480", "-iconic", "-sync", "-gldebug", "a", "b"],
     "glutInit left 3 of 8 arguments: [a] [b]"),
    (["-display", "@DISPLAY@", "-w", "--wire"], "glutInit left 3 of 5 arguments: [-w] [--wire]"),
    (["-geometry", "100x50-10-20"], "init window: 1170 954 100x50"),
    (["-geometry", "=300x200+0+0", "-f", "2"], "init window: 0 0 300x200"),
    (["-geometry", "80x60+5", "x"], "init window: -1 -1 80x60"),
    (["-direct"], "direct rendering 3"),
    (["-indirect", "-f", "4"], "direct rendering 0"),
    (["-direct", "-indirect"], "parameters ambiguity"),
    (["-w", "-geometry"], "-geometry parameter must be followed by window geometry settings"),
    (["-display"], "-display parameter must be followed by display name"),
    (["--", "-geometry", "10x10", "-q"], "init window: -1 -1 10x10"),
    (["-x"], "the demo's parser refuses an option"),
]


def run(exe, args, env):
    r = subprocess.run(["glut-args"] + args, executable=exe, env=env, capture_output=True,
                       text=True, timeout=60)
    return r.returncode, r.stdout + r.stderr


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    xvfb, freeglut_exe, fixglut_exe = sys.argv[1:]
    r, w = os.pipe()
    server = subprocess.Popen([xvfb, "-displayfd", str(w), "-screen", "0", "1280x1024x24",
                               "-nolisten", "tcp"], pass_fds=(w,),
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(w)
    failures = 0
    try:
        with os.fdopen(r) as f:
            display = f.readline().strip()
        if not display:
            print("FAIL: Xvfb gave no display")
            return 1
        fg_env = dict(os.environ, DISPLAY=":" + display)
        fg_env["ASAN_OPTIONS"] = fg_env.get("ASAN_OPTIONS", "") + ":detect_leaks=0"
        fx_env = dict(os.environ, FIXGLUT_HEADLESS="1")
        fx_env.pop("DISPLAY", None)
        for args, want in CASES:
            args = [a.replace("@DISPLAY@", ":" + display) for a in args]
            a = run(freeglut_exe, args, fg_env)
            b = run(fixglut_exe, args, fx_env)
            line = "glut-args " + " ".join(args)
            if a != b:
                print(f"FAIL {line}:\n  freeglut (exit {a[0]}): {a[1]!r}\n"
                      f"  libfixglut (exit {b[0]}): {b[1]!r}")
                failures += 1
            elif want not in a[1]:
                print(f"FAIL {line}: both print {a[1]!r}, without {want!r}")
                failures += 1
            else:
                print(f"ok   {line}: exit {a[0]}, {len(a[1].splitlines())} lines alike")
    finally:
        server.terminate()
        server.wait()
    print(f"{len(CASES) - failures} of {len(CASES)} command lines alike")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
