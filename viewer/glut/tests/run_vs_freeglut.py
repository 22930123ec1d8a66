#!/usr/bin/env python3
"""run_vs_freeglut.py - freeglut's cylinders against libfixglut's.

    run_vs_freeglut.py XVFB FREEGLUT_EXE FIXGLUT_EXE OUTDIR

Starts a private Xvfb (freeglut's glutInit opens the display), runs
FREEGLUT_EXE (cylinder_vs_freeglut.c on Debian's libglut) there and
FIXGLUT_EXE (the same source on libfixglut, headless); both render with
fixgl.  Fails unless both outputs exist, are non-empty and identical, and
the frames are not all background.
"""
import os
import subprocess
import sys


def main():
    if len(sys.argv) != 5:
        print(__doc__)
        return 2
    xvfb, freeglut_exe, fixglut_exe, outdir = sys.argv[1:]
    os.makedirs(outdir, exist_ok=True)
    r, w = os.pipe()
    server = subprocess.Popen([xvfb, "-displayfd", str(w), "-screen", "0", "320x240x24",
                               "-nolisten", "tcp"], pass_fds=(w,),
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(w)
    try:
        with os.fdopen(r) as f:
            display = f.readline().strip()
        if not display:
            print("FAIL: Xvfb gave no display")
            return 1
        a = os.path.join(outdir, "freeglut.out")
        b = os.path.join(outdir, "fixglut.out")
        env = dict(os.environ, DISPLAY=":" + display)
        # under AddressSanitizer: freeglut's and Xlib's leaks are not ours
        env["ASAN_OPTIONS"] = env.get("ASAN_OPTIONS", "") + ":detect_leaks=0"
        ra = subprocess.run([freeglut_exe, a], env=env, timeout=60)
        env = dict(os.environ, FIXGLUT_HEADLESS="1")
        env.pop("DISPLAY", None)
        rb = subprocess.run([fixglut_exe, b], env=env, timeout=60)
    finally:
        server.terminate()
        server.wait()
    if ra.returncode or rb.returncode:
        print(f"FAIL: exit status freeglut {ra.returncode}, libfixglut {rb.returncode}")
        return 1
    da, db = open(a, "rb").read(), open(b, "rb").read()
    frame = 96 * 96 * 8 + 4
    if len(da) != 6 * frame or len(db) != 6 * frame:
        print(f"FAIL: output sizes {len(da)}, {len(db)}")
        return 1
    status = 0
    for i in range(6):
        fa, fb = da[i * frame:(i + 1) * frame], db[i * frame:(i + 1) * frame]
        rgba = fa[:96 * 96 * 4]
        drawn = sum(1 for k in range(0, len(rgba), 4) if rgba[k:k + 4] != rgba[0:4])
        diff = sum(1 for k in range(0, 96 * 96 * 8, 4) if fa[k:k + 4] != fb[k:k + 4])
        print(f"case {i}: {drawn} pixels drawn, {diff} colour/depth words differ")
        if diff or drawn < 50:
            status = 1
    print("identical" if status == 0 else "FAIL: libfixglut's cylinders differ from freeglut's")
    return status


if __name__ == "__main__":
    sys.exit(main())
