#!/usr/bin/env python3
"""run_glu.py - one scene of glu_scenes.c on the oracle and on fixgl.

    run_glu.py SCENE ORACLE_EXE FIXGL_EXE OUTDIR
    run_glu.py --check-list FIXGL_EXE MESON_BUILD

Runs SCENE with both programs under the dynamic linker's binding trace
(LD_BIND_NOW=1 LD_DEBUG=bindings), then
  1. checks the bindings: every gl* symbol libGLU.so.1 uses must bind to
     the program's GL (libfixgl.so.0 for FIXGL_EXE, libOSMesa.so.8 for the
     oracle), never to libGLU's NEEDED libOpenGL.so.0 or libGLdispatch;
     fewer than 20 such bindings fails too (the trace must show them);
  2. compares the two outputs record by record (colour, depth, GL errors,
     GLU's results): they must be identical byte for byte.  For an image
     record it prints how many pixels differ and the first one.
--check-list fails unless every scene FIXGL_EXE lists has a test in
MESON_BUILD.
"""
import os
import re
import subprocess
import sys

BIND = re.compile(r"binding file (\S+) \[\d+\] to (\S+) \[\d+\]: normal symbol `([^']+)'")


def run(exe, scene, out, trace):
    env = dict(os.environ, LD_BIND_NOW="1", LD_DEBUG="bindings", LD_DEBUG_OUTPUT=trace)
    env["ASAN_OPTIONS"] = env.get("ASAN_OPTIONS", "") + ":detect_leaks=0"
    r = subprocess.run([exe, scene, out], env=env, capture_output=True, text=True, timeout=100)
    if r.returncode != 0:
        print(f"FAIL: {exe} {scene} exited {r.returncode}\n{r.stderr}")
    return r.returncode == 0


def check_bindings(trace_prefix, want):
    """want: the basename prefix of the library gl* must bind to"""
    bad, good = [], 0
    traces = [f for f in os.listdir(os.path.dirname(trace_prefix))
              if f.startswith(os.path.basename(trace_prefix) + ".")]
    for t in traces:
        with open(os.path.join(os.path.dirname(trace_prefix), t), errors="replace") as f:
            for line in f:
                m = BIND.search(line)
                if not m:
                    continue
                src, dst, sym = m.groups()
                if "libGLU.so" not in os.path.basename(src):
                    continue
                if not sym.startswith("gl") or sym.startswith("glu"):
                    continue
                if os.path.basename(dst).startswith(want):
                    good += 1
                else:
                    bad.append(f"{sym} -> {dst}")
    return good, bad


def records(path):
    data = open(path, "rb").read()
    i, out = 0, []
    while i < len(data):
        j = data.index(b"\n", i)
        _, name, n = data[i:j].decode().split(" ")
        n = int(n)
        out.append((name, data[j + 1:j + 1 + n]))
        i = j + 1 + n
    return out


def describe(name, a, b):
    if name.endswith(".rgba") or name.endswith(".depth"):
        size = 4
        diff = [k for k in range(0, min(len(a), len(b)), size) if a[k:k + size] != b[k:k + size]]
        if diff:
            k = diff[0] // size
            return (f"{len(diff)} pixels differ; first at x={k % 128} y={k // 128}: "
                    f"oracle {a[diff[0]:diff[0] + size].hex()} fixgl {b[diff[0]:diff[0] + size].hex()}")
    if len(a) != len(b):
        return f"{len(a)} bytes on the oracle, {len(b)} on fixgl"
    k = next(i for i in range(len(a)) if a[i] != b[i])
    return f"first difference at byte {k}: oracle {a[k:k + 16]!r} fixgl {b[k:k + 16]!r}"


def check_list(exe, meson_build):
    scenes = subprocess.run([exe, "--list"], check=True, capture_output=True, text=True).stdout.split()
    text = open(meson_build).read()
    missing = [s for s in scenes if f"'{s}'" not in text]
    for s in missing:
        print(f"FAIL: scene {s} has no test in {meson_build}")
    print(f"{len(scenes)} scenes, {len(scenes) - len(missing)} with a test")
    return 1 if missing or not scenes else 0


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "--check-list":
        return check_list(sys.argv[2], sys.argv[3])
    if len(sys.argv) != 5:
        print(__doc__)
        return 2
    scene, oracle, fixgl, outdir = sys.argv[1:]
    work = os.path.join(outdir, scene)
    os.makedirs(work, exist_ok=True)
    for f in os.listdir(work):
        os.unlink(os.path.join(work, f))
    status = 0
    for side, exe, want in (("oracle", oracle, "libOSMesa.so"), ("fixgl", fixgl, "libfixgl.so")):
        trace = os.path.join(work, side + ".bindings")
        ran = run(exe, scene, os.path.join(work, side + ".out"), trace)
        good, bad = check_bindings(trace, want)
        print(f"{side}: {good} gl* bindings of libGLU.so.1 to {want}, {len(bad)} elsewhere")
        for b in bad[:10]:
            print(f"FAIL: {side}: libGLU's {b}")
        if bad or good < 20:
            if good < 20:
                print(f"FAIL: {side}: the binding trace shows only {good} of libGLU's gl* calls")
            status = 1
        if not ran:
            return 1
    a = records(os.path.join(work, "oracle.out"))
    b = records(os.path.join(work, "fixgl.out"))
    if [n for n, _ in a] != [n for n, _ in b]:
        print(f"FAIL: the records differ: oracle {[n for n, _ in a]} fixgl {[n for n, _ in b]}")
        return 1
    same = 0
    for (name, da), (_, db) in zip(a, b):
        if da == db:
            same += 1
        else:
            print(f"FAIL: {name}: {describe(name, da, db)}")
            status = 1
    print(f"{scene}: {same} of {len(a)} records identical")
    return status


if __name__ == "__main__":
    sys.exit(main())
