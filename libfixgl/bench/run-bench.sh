#!/usr/bin/env bash
# run-bench.sh BENCH_BUILD_DIR [SECONDS_PER_SCENE]
#
# Runs the benchmark in one go: fixgl, OSMesa (llvmpipe with its default
# number of threads) and OSMesa with LP_NUM_THREADS=1, then prints frames per
# second per scene and the ratio fixgl/OSMesa for both OSMesa modes.
# The "same image" column compares the checksums of the last frames.
# The shading scenes (phong, ctphong, ctsmooth) use fixgl's extensions; the
# OSMesa build binds the conformance suite's GLSL reference for them.
set -euo pipefail

if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "usage: $0 BENCH_BUILD_DIR [SECONDS_PER_SCENE]" >&2
  exit 2
fi
dir=$1
seconds=${2:-2}
fixgl_bin=$dir/fixgl-bench-fixgl
osmesa_bin=$dir/fixgl-bench-osmesa

[[ -x $fixgl_bin ]] || { echo "bench: $fixgl_bin is not built" >&2; exit 1; }
[[ -x $osmesa_bin ]] || {
  echo "bench: $osmesa_bin is not built (needs the system OSMesa: libosmesa6-dev)" >&2
  exit 1
}

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

echo "bench: 1024x768, ${seconds}s per scene after warm-up, $(nproc) CPU(s)"
echo "bench: running fixgl..."
"$fixgl_bin" "$seconds" >"$out/fixgl"
echo "bench: running OSMesa (llvmpipe, default threads)..."
env -u LP_NUM_THREADS "$osmesa_bin" "$seconds" >"$out/osmesa"
echo "bench: running OSMesa (llvmpipe, LP_NUM_THREADS=1)..."
LP_NUM_THREADS=1 "$osmesa_bin" "$seconds" >"$out/osmesa1"
echo

# Each file has lines "scene NAME fps X frames N checksum C".
awk '
  FNR == 1 { run = FILENAME; sub(/.*\//, "", run) }
  $1 == "scene" {
    if (!($2 in seen)) { seen[$2] = 1; order[++n] = $2 }
    fps[run, $2] = $4; sum[run, $2] = $8
  }
  END {
    printf "%-8s %12s %12s %12s %11s %11s %6s\n", "scene", "fixgl fps", "OSMesa fps",
           "OSMesa-1 fps", "fixgl/OSM", "fixgl/OSM-1", "same"
    for (i = 1; i <= n; i++) {
      s = order[i]
      f = fps["fixgl", s]; o = fps["osmesa", s]; o1 = fps["osmesa1", s]
      printf "%-8s %12.1f %12.1f %12.1f %10.2fx %10.2fx %6s\n", s, f, o, o1,
             (o > 0 ? f / o : 0), (o1 > 0 ? f / o1 : 0),
             (sum["fixgl", s] == sum["osmesa", s] ? "yes" : "no")
    }
  }' "$out/fixgl" "$out/osmesa" "$out/osmesa1"
echo
echo "OSMesa = llvmpipe with its default threads; OSMesa-1 = LP_NUM_THREADS=1;"
echo "same = last frame of fixgl identical to OSMesa's (lit200, lit20k and gears"
echo "are lit).  phong, ctphong, ctsmooth: fixgl's GL_PHONG_WIN and"
echo "GL_FIXGL_cook_torrance (per fragment, per vertex) against llvmpipe running the"
echo "same equations as GLSL (conformance/reference/fcr_shading.c); 786,432 lit"
echo "fragments a frame."
