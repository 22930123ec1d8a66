#!/usr/bin/env python3
"""run_glx.py - the glx suite: unmodified GLX programs on fixgl's libGL.so.1
against the same programs on Mesa's libGL (llvmpipe), under Xvfb.

    run_glx.py compare LIBGL_DIR OUT_DIR NAME PROGRAM [ARGS...]
        PROGRAM (one of ours, glx_frames.h) runs twice on a fresh Xvfb:
        with Debian's libGL (LIBGL_ALWAYS_SOFTWARE=1: llvmpipe, the oracle)
        and with LD_LIBRARY_PATH=LIBGL_DIR; each reads its window back and
        writes OUT_DIR/NAME-{mesa,fixgl}.ppm and prints its renderer.  The
        renderers must be llvmpipe and fixgl, the two images identical.
    run_glx.py glxgears LIBGL_DIR OUT_DIR FROZEN_CLOCK_SO GRAB
        /usr/bin/glxgears with its clock stopped (FROZEN_CLOCK_SO, every
        frame is its first) on both libraries: GRAB reads its window after
        it has drawn; the images are identical and show the three gears.
        Then glxgears -info on fixgl with the clock running: it reports
        fixgl and its frames move.
    run_glx.py oracle PROGRAM [ARGS...]
        PROGRAM runs on Mesa's libGL alone (a fresh Xvfb): a probe that
        checks the oracle against rules of ORACLE-NOTES.md that fixgl does
        not model yet (linrules.c); its renderer must be llvmpipe and it
        must exit 0.
    run_glx.py glxinfo LIBGL_DIR
        glxinfo on fixgl prints fixgl's renderer, version and extensions.
    run_glx.py configs LIBGL_DIR OUT_DIR PROGRAM
        PROGRAM (configs.c) lists the FBConfigs, the visuals and the
        answers of glXChooseFBConfig/glXChooseVisual on Mesa's libGL and on
        fixgl's (each on a fresh Xvfb): the configs fixgl cannot render
        (lines of Mesa's marked "-": multisampled, not 8-8-8 RGBA) are
        left out of Mesa's list, fixgl must list none of them and answer
        "no GL" for their visuals; every other line must be equal.

Xvfb, glxgears or glxinfo missing is a failure (exit 1), not a skip.
"""
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

SCREEN = "640x480x24"


class Fail(Exception):
    pass


def start_xvfb():
    xvfb = shutil.which("Xvfb")
    if not xvfb:
        raise Fail("Xvfb is not installed (Debian package xvfb)")
    rfd, wfd = os.pipe()
    # the server with the system's libraries (meson points LD_LIBRARY_PATH
    # at build/libfixgl/libgl, and Xvfb's GLX loads libGL.so.1)
    env = {k: v for k, v in os.environ.items() if k not in ("LD_LIBRARY_PATH", "LD_PRELOAD")}
    proc = subprocess.Popen([xvfb, "-displayfd", str(wfd), "-screen", "0", SCREEN,
                             "-nolisten", "tcp", "-noreset"], env=env,
                            pass_fds=(wfd,), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    os.close(wfd)
    data = b""
    deadline = time.time() + 20
    while not data.endswith(b"\n") and time.time() < deadline:
        chunk = os.read(rfd, 64)
        if not chunk:
            break
        data += chunk
    os.close(rfd)
    if not data.strip().isdigit():
        proc.kill()
        raise Fail("Xvfb did not start: " + proc.stderr.read().decode(errors="replace")[-500:])
    return proc, ":" + data.decode().strip()


def stop(proc):
    if proc.poll() is None:
        proc.send_signal(signal.SIGTERM)
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


def sanitizer_runtime(libgl_dir):
    """The AddressSanitizer runtime fixgl's libGL.so.1 needs, or None: in a
    sanitized build (CI's build-asan) the library is instrumented while the
    programs are not (they are built without sanitizers, as unmodified
    binaries are), so the runtime must be loaded first (LD_PRELOAD)."""
    r = subprocess.run(["ldd", os.path.join(libgl_dir, "libGL.so.1")], capture_output=True, text=True)
    for line in r.stdout.splitlines():
        parts = line.split()
        if parts and parts[0].startswith("libasan.so") and len(parts) >= 3 and parts[2].startswith("/"):
            return parts[2]
    return None


def env_for(which, display, libgl_dir, preload=None):
    env = dict(os.environ, DISPLAY=display)
    env.pop("LD_LIBRARY_PATH", None)
    env.pop("LD_PRELOAD", None)
    preloads = [os.path.abspath(preload)] if preload else []
    if which == "mesa":
        env["LIBGL_ALWAYS_SOFTWARE"] = "1"
        env["GALLIUM_DRIVER"] = "llvmpipe"
    else:
        env["LD_LIBRARY_PATH"] = os.path.abspath(libgl_dir)
        asan = sanitizer_runtime(libgl_dir)
        if asan:
            preloads.insert(0, asan)
            # the programs (freeglut, Xlib) leak at exit: leaks are not
            # checked here, every access fixgl makes still is
            env["ASAN_OPTIONS"] = ":".join(filter(None, [env.get("ASAN_OPTIONS"), "detect_leaks=0"]))
    if preloads:
        env["LD_PRELOAD"] = " ".join(preloads)
    return env


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    images = []
    pos = 0
    while pos < len(data):
        fields = []
        while len(fields) < 4:
            while data[pos:pos + 1].isspace():
                pos += 1
            end = pos
            while not data[end:end + 1].isspace():
                end += 1
            fields.append(data[pos:end])
            pos = end
        pos += 1
        w, h = int(fields[1]), int(fields[2])
        images.append((w, h, data[pos:pos + 3 * w * h]))
        pos += 3 * w * h
    return images


def compare_images(name, mesa_path, fixgl_path):
    a, b = read_ppm(mesa_path), read_ppm(fixgl_path)
    if len(a) != len(b):
        raise Fail(f"{name}: {len(a)} images from Mesa, {len(b)} from fixgl")
    for i, ((wa, ha, pa), (wb, hb, pb)) in enumerate(zip(a, b)):
        if (wa, ha) != (wb, hb):
            raise Fail(f"{name} image {i}: Mesa's is {wa}x{ha}, fixgl's {wb}x{hb}")
        if pa == pb:
            print(f"{name} image {i}: {wa}x{ha}, identical")
            continue
        diff = [(j // 3) for j in range(0, len(pa), 3) if pa[j:j + 3] != pb[j:j + 3]]
        xs = [p % wa for p in diff]
        ys = [p // wa for p in diff]
        worst = max(abs(pa[j] - pb[j]) for j in range(len(pa)))
        raise Fail(f"{name} image {i}: {len(diff)} of {wa * ha} pixels differ (largest channel "
                   f"difference {worst}; x {min(xs)}..{max(xs)}, y {min(ys)}..{max(ys)}); "
                   f"see {mesa_path} and {fixgl_path}")
    # (over every image: a program may write several, the first small)
    distinct = len(set(img[2][j:j + 3] for img in a for j in range(0, len(img[2]), 3)))
    if distinct < 8:
        raise Fail(f"{name}: the images have {distinct} colours: nothing was drawn")


def run(cmd, env, timeout=60):
    r = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=timeout)
    if r.returncode != 0:
        raise Fail(f"{' '.join(cmd)} exited with {r.returncode}:\n{r.stdout[-1500:]}{r.stderr[-1500:]}")
    return r.stdout


def check_renderer(out, which, what):
    line = next((l for l in out.splitlines() if l.startswith("renderer: ")), "")
    want = "llvmpipe" if which == "mesa" else "fixgl"
    if want not in line:
        raise Fail(f"{what} on {which}: expected a {want} renderer, got {line!r}")


def cmd_compare(libgl_dir, out_dir, name, program):
    if not os.path.exists(program[0]):
        raise Fail(f"{program[0]} is missing")
    os.makedirs(out_dir, exist_ok=True)
    paths = {}
    said = {}
    for which in ("mesa", "fixgl"):
        xvfb, display = start_xvfb()
        try:
            paths[which] = os.path.join(out_dir, f"{name}-{which}.ppm")
            if os.path.exists(paths[which]):
                os.remove(paths[which])
            out = run(program + ["--out", paths[which]], env_for(which, display, libgl_dir))
            check_renderer(out, which, name)
            # lines starting "= " (GL state, errors, counts) must be equal too
            said[which] = [l for l in out.splitlines() if l.startswith("= ")]
        finally:
            stop(xvfb)
    if said["mesa"] != said["fixgl"]:
        raise Fail(f"{name}: Mesa printed {said['mesa']}, fixgl {said['fixgl']}")
    compare_images(name, paths["mesa"], paths["fixgl"])


def cmd_oracle(program):
    if not os.path.exists(program[0]):
        raise Fail(f"{program[0]} is missing")
    xvfb, display = start_xvfb()
    try:
        out = run(program, env_for("mesa", display, None), timeout=180)
    finally:
        stop(xvfb)
    check_renderer(out, "mesa", os.path.basename(program[0]))
    print(out, end="")


def grab_stable(grab, env, path, deadline):
    """GRAB's image of the window once two reads 0.3 s apart agree."""
    last = None
    while time.time() < deadline:
        time.sleep(0.3)
        r = subprocess.run([grab, path], env=env, capture_output=True, text=True)
        if r.returncode != 0:
            continue
        with open(path, "rb") as f:
            data = f.read()
        if data == last and len(set(data[20:])) > 4:
            return
        last = data
    raise Fail(f"no stable image of the window by {grab}")


def colour_counts(path):
    w, h, px = read_ppm(path)[0]
    red = green = blue = 0
    for j in range(0, len(px), 3):
        r, g, b = px[j], px[j + 1], px[j + 2]
        if r > 60 and r > 2 * g and r > 2 * b:
            red += 1
        elif g > 60 and g > 2 * r and g > 2 * b:
            green += 1
        elif b > 60 and b > 2 * r and b > 2 * g:
            blue += 1
    return red, green, blue


def cmd_glxgears(libgl_dir, out_dir, frozen, grab):
    gears = shutil.which("glxgears")
    if not gears:
        raise Fail("glxgears is not installed (Debian package mesa-utils)")
    os.makedirs(out_dir, exist_ok=True)
    paths = {}
    said = {}
    for which in ("mesa", "fixgl"):
        xvfb, display = start_xvfb()
        env = env_for(which, display, libgl_dir)
        genv = env_for(which, display, libgl_dir, preload=frozen)
        proc = subprocess.Popen([gears, "-geometry", "300x300+0+0"], env=genv,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        try:
            paths[which] = os.path.join(out_dir, f"glxgears-{which}.ppm")
            grab_stable(grab, env, paths[which], time.time() + 30)
            if proc.poll() is not None:
                raise Fail(f"glxgears on {which} exited with {proc.returncode}: "
                           + proc.stdout.read().decode(errors="replace")[-1500:])
        finally:
            stop(proc)
            stop(xvfb)
    compare_images("glxgears", paths["mesa"], paths["fixgl"])
    red, green, blue = colour_counts(paths["fixgl"])
    print(f"glxgears on fixgl: {red} red, {green} green, {blue} blue gear pixels")
    if min(red, green, blue) < 500:
        raise Fail("glxgears on fixgl: the three gears are not all there")

    # with the clock running: fixgl's renderer, frames that move
    xvfb, display = start_xvfb()
    env = env_for("fixgl", display, libgl_dir)
    # stdbuf: glxgears's stdout is a pipe, buffered, and it ends by SIGTERM
    proc = subprocess.Popen(["stdbuf", "-oL", gears, "-info", "-geometry", "300x300+0+0"], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    try:
        one, two = os.path.join(out_dir, "glxgears-run-1.ppm"), os.path.join(out_dir, "glxgears-run-2.ppm")
        deadline = time.time() + 20
        while time.time() < deadline:
            time.sleep(0.5)
            if subprocess.run([grab, one], env=env, capture_output=True).returncode == 0:
                break
        time.sleep(0.5)
        run([grab, two], env)
        if proc.poll() is not None:
            raise Fail(f"glxgears -info on fixgl exited with {proc.returncode}")
        if read_ppm(one) == read_ppm(two):
            raise Fail("glxgears on fixgl: two frames 0.5 s apart are the same (no animation)")
    finally:
        stop(proc)
        stop(xvfb)
    out = proc.stdout.read().decode(errors="replace")
    if "GL_RENDERER   = fixgl" not in out:
        raise Fail("glxgears -info on fixgl does not report fixgl:\n" + out[-1500:])
    print("glxgears -info on fixgl: " + next(l for l in out.splitlines() if "GL_RENDERER" in l))


def cmd_glxinfo(libgl_dir):
    glxinfo = shutil.which("glxinfo")
    if not glxinfo:
        raise Fail("glxinfo is not installed (Debian package mesa-utils)")
    xvfb, display = start_xvfb()
    try:
        out = run([glxinfo], env_for("fixgl", display, libgl_dir))
    finally:
        stop(xvfb)
    want = [
        "direct rendering: Yes",
        "server glx vendor string: fixgl",
        "client glx vendor string: fixgl",
        "GLX version: 1.4",
        "GLX_ARB_get_proc_address",
        "GLX_EXT_swap_control",
        "GLX_MESA_swap_control",
        "OpenGL vendor string: fixgl",
        "OpenGL renderer string: fixgl CPU rasterizer",
        "OpenGL version string: 1.5 fixgl",
        "GL_ARB_multitexture",
        "GL_ARB_vertex_buffer_object",
        "GL_EXT_blend_color",
    ]
    missing = [w for w in want if w not in out]
    if missing:
        raise Fail("glxinfo on fixgl lacks " + ", ".join(repr(m) for m in missing) + ":\n" + out[-3000:])
    if "llvmpipe" in out or "Mesa" in out.split("OpenGL vendor string")[1][:200]:
        raise Fail("glxinfo on fixgl names Mesa's renderer:\n" + out[-3000:])
    for line in out.splitlines():
        if line.startswith(("OpenGL renderer", "OpenGL version", "GLX version")):
            print(line)


def cmd_configs(libgl_dir, out_dir, program):
    if not os.path.exists(program):
        raise Fail(f"{program} is missing")
    os.makedirs(out_dir, exist_ok=True)
    lines = {}
    for which in ("mesa", "fixgl"):
        xvfb, display = start_xvfb()
        try:
            path = os.path.join(out_dir, f"configs-{which}.txt")
            if os.path.exists(path):
                os.remove(path)
            out = run([program, "--out", path], env_for(which, display, libgl_dir))
            vendor = next((l for l in out.splitlines() if l.startswith("vendor: ")), "")
            want = "Mesa" if which == "mesa" else "fixgl"
            if want not in vendor:
                raise Fail(f"configs on {which}: expected {want}'s GLX, got {vendor!r}")
            print(f"{which}: " + " ".join(out.splitlines()[1:]))
            with open(path) as f:
                lines[which] = f.read().splitlines()
        finally:
            stop(xvfb)
    skipped_visuals = {l.split()[1] for l in lines["mesa"] if l.startswith("-visual ")}
    mesa = [l for l in lines["mesa"] if not l.startswith("-")]
    fixgl = []
    for l in lines["fixgl"]:
        if l.startswith("-"):
            raise Fail(f"fixgl offers a config it cannot render: {l}")
        f = l.split()
        if f[0] == "visual" and f[1] in skipped_visuals:
            if "use_gl=0" not in f:
                raise Fail(f"fixgl offers GL on a visual of Mesa's it cannot render: {l}")
            continue
        fixgl.append(l)
    if not any(l.startswith("fbconfig ") for l in mesa):
        raise Fail("Mesa lists no FBConfig fixgl could render")
    for i, (a, b) in enumerate(zip(mesa, fixgl)):
        if a != b:
            raise Fail(f"line {i + 1} differs:\n  Mesa:  {a}\n  fixgl: {b}")
    if len(mesa) != len(fixgl):
        raise Fail(f"Mesa has {len(mesa)} lines, fixgl {len(fixgl)}")
    counts = {k: sum(1 for l in mesa if l.startswith(k)) for k in ("fbconfig", "visual", "choose")}
    print(f"configs: {counts['fbconfig']} FBConfigs, {counts['visual']} visuals and "
          f"{counts['choose']} choices equal ({len(skipped_visuals)} multisampled visuals without GL on fixgl)")


def main(argv):
    try:
        if len(argv) >= 5 and argv[1] == "compare":
            cmd_compare(argv[2], argv[3], argv[4], argv[5:])
        elif len(argv) == 6 and argv[1] == "glxgears":
            cmd_glxgears(*argv[2:])
        elif len(argv) >= 3 and argv[1] == "oracle":
            cmd_oracle(argv[2:])
        elif len(argv) == 3 and argv[1] == "glxinfo":
            cmd_glxinfo(argv[2])
        elif len(argv) == 5 and argv[1] == "configs":
            cmd_configs(*argv[2:])
        else:
            print(__doc__)
            return 2
    except Fail as e:
        print("FAIL: " + str(e))
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
