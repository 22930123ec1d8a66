#!/usr/bin/env bash
# run-bench.sh BENCH_BUILD_DIR [SECONDS_PER_SCENE [REPORT_DIR]]
#
# Runs the benchmark in one go: fixgl with its default threads (one per
# CPU) and with FIXGL_NUM_THREADS=1, OSMesa (llvmpipe with its default
# number of threads) and OSMesa with LP_NUM_THREADS=1, then prints frames
# per second per scene and the ratios like for like (default threads over
# default threads, one thread over one thread), and a scaling table: fixgl
# with 1, 2 and 4 threads.  The "same" column compares the checksums of the
# check frames (bench.c) of every fixgl run with OSMesa's.
# The shading scenes (phong, ctphong, ctsmooth) use fixgl's extensions; the
# OSMesa build binds the conformance suite's GLSL reference for them.
#
# Another table breaks fixgl's one-thread frames down with its own counters
# (fixglStats, on only for a few extra frames after the timed ones):
# nanoseconds per shaded fragment and the shares of the frame time in the
# vertex stage, primitive setup and fragments (tables.awk says what each
# column divides).
#
# REPORT_DIR (default BENCH_BUILD_DIR/../../bench, i.e. build/bench)
# receives bench.tsv, the data of the run, and report.html: both tables
# and the bar chart as inline SVG.  `ninja -C build bench-chart` draws the
# same chart from bench.tsv into libfixgl/bench/chart.png (make_chart.sh).
set -euo pipefail

if [[ $# -lt 1 || $# -gt 3 ]]; then
  echo "usage: $0 BENCH_BUILD_DIR [SECONDS_PER_SCENE [REPORT_DIR]]" >&2
  exit 2
fi
dir=$1
seconds=${2:-2}
report_dir=${3:-$(dirname "$(dirname "$dir")")/bench}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
fixgl_bin=$dir/fixgl-bench-fixgl
osmesa_bin=$dir/fixgl-bench-osmesa

[[ -x $fixgl_bin ]] || { echo "bench: $fixgl_bin is not built" >&2; exit 1; }
[[ -x $osmesa_bin ]] || {
  echo "bench: $osmesa_bin is not built (needs the system OSMesa: libosmesa6-dev)" >&2
  exit 1
}

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

date=$(date -u '+%Y-%m-%d %H:%M UTC')
echo "bench: 1024x768, ${seconds}s per scene after warm-up, $(nproc) CPU(s)"
echo "bench: running fixgl (default threads: $(nproc))..."
env -u FIXGL_NUM_THREADS "$fixgl_bin" "$seconds" >"$out/fixgl"
for t in 1 2 4; do
  echo "bench: running fixgl (FIXGL_NUM_THREADS=$t)..."
  FIXGL_NUM_THREADS=$t "$fixgl_bin" "$seconds" >"$out/fixgl$t"
done
echo "bench: running OSMesa (llvmpipe, default threads)..."
env -u LP_NUM_THREADS "$osmesa_bin" "$seconds" >"$out/osmesa"
echo "bench: running OSMesa (llvmpipe, LP_NUM_THREADS=1)..."
LP_NUM_THREADS=1 "$osmesa_bin" "$seconds" >"$out/osmesa1"
echo

# Each file has lines "scene NAME fps X frames N checksum C"; fixgl's also
# "stats NAME frames N frame_ns F fragments X setup_ns S raster_ns R
# vertex_ns V batch_ns B" (bench.c).  bench.tsv: "# key value" lines, a
# header, one tab-separated line per scene.
mkdir -p "$report_dir"
tsv=$report_dir/bench.tsv
{
  echo "# date $date"
  echo "# cpus $(nproc)"
  echo "# seconds $seconds"
  awk '
    FNR == 1 { run = FILENAME; sub(/.*\//, "", run) }
    $1 == "scene" {
      if (!($2 in seen)) { seen[$2] = 1; order[++n] = $2 }
      fps[run, $2] = $4; sum[run, $2] = $8
    }
    $1 == "stats" && run == "fixgl1" {
      for (k = 3; k < NF; k += 2)
        st[$2, $k] = $(k + 1)
    }
    END {
      OFS = "\t"
      print "scene", "fixgl_fps", "osmesa_fps", "osmesa1_fps", "same", "stats_frames",
            "frame_ns", "fragments", "setup_ns", "raster_ns", "vertex_ns", "batch_ns",
            "fixgl1_fps", "fixgl2_fps", "fixgl4_fps"
      for (i = 1; i <= n; i++) {
        s = order[i]
        same = sum["fixgl", s] == sum["osmesa", s] && sum["fixgl1", s] == sum["osmesa", s] &&
               sum["fixgl2", s] == sum["osmesa", s] && sum["fixgl4", s] == sum["osmesa", s]
        print s, fps["fixgl", s] + 0, fps["osmesa", s] + 0, fps["osmesa1", s] + 0,
              (same ? "yes" : "no"),
              st[s, "frames"] + 0, st[s, "frame_ns"] + 0, st[s, "fragments"] + 0,
              st[s, "setup_ns"] + 0, st[s, "raster_ns"] + 0, st[s, "vertex_ns"] + 0,
              st[s, "batch_ns"] + 0, fps["fixgl1", s] + 0, fps["fixgl2", s] + 0,
              fps["fixgl4", s] + 0
      }
    }' "$out/fixgl" "$out/fixgl1" "$out/fixgl2" "$out/fixgl4" "$out/osmesa" "$out/osmesa1"
} >"$tsv"

awk -v format=text -f "$here/tables.awk" "$tsv"
echo
echo "fixgl = FIXGL_NUM_THREADS unset (one thread per CPU); fixgl-1 = FIXGL_NUM_THREADS=1;"
echo "OSMesa = llvmpipe with its default threads; OSMesa-1 = LP_NUM_THREADS=1;"
echo "same = check frame of every fixgl run identical to OSMesa's (lit200, lit20k,"
echo "gears and manydraws are lit).  phong, ctphong, ctsmooth: fixgl's GL_PHONG_WIN and"
echo "GL_FIXGL_cook_torrance (per fragment, per vertex) against llvmpipe running the"
echo "same equations as GLSL (conformance/reference/fcr_shading.c); 786,432 lit"
echo "fragments a frame."
echo "Breakdown of fixgl-1's frames (fixgl's counters, fixglStats, on for a few extra"
echo "frames only):"
echo "ns/frag = raster core time after primitive setup / fragments shaded;"
echo "vertex, setup, frags, other = shares of the frame's wall-clock time (other:"
echo "glClear, glFinish, state outside vertex batches); n/a = nothing to divide"
echo "by, or the raster core's counters read 0 (a libfixgl that does not count them)."

# report.html: the chart (chart.awk: the drawing of chart.png too) and both
# tables
{
  cat <<EOF
<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>fixgl bench</title>
<style>
body { font-family: "DejaVu Sans", Verdana, sans-serif; margin: 2em; color: #1a1a1a; }
table { border-collapse: collapse; margin: 1em 0; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: right; }
th:first-child, td:first-child { text-align: left; }
th { background: #f0f0f0; }
p.note { color: #555; max-width: 60em; }
</style></head><body>
<h1>fixgl bench</h1>
<p>$date, $(nproc) CPU(s), 1024&times;768, $seconds s per scene after warm-up.
fixgl = one rasterizing thread per CPU (FIXGL_NUM_THREADS unset); fixgl-1 =
FIXGL_NUM_THREADS=1; OSMesa = llvmpipe with its default threads; OSMesa-1 =
LP_NUM_THREADS=1.</p>
EOF
  awk -v format=svg -f "$here/chart.awk" "$tsv"
  awk -v format=html -f "$here/tables.awk" "$tsv"
  cat <<'EOF'
<p class="note">same: the check frame of fixgl is identical to OSMesa's
(phong, ctphong, ctsmooth: OSMesa runs the GLSL reference of fixgl's shading
extensions, conformance/reference/fcr_shading.c).</p>
<p class="note">Breakdown: fixgl's own counters (fixglStats) in the
one-thread run, on only for a few extra frames after the timed ones, so the frames per second are measured
without them (the timers add a little to the frames they measure).
ms/frame: wall-clock time of those frames. frags/frame: fragments the raster
core shaded (covered pixels inside the draw region). ns/frag: the raster
core's time after primitive setup (coverage and the fragment stage) divided
by those fragments; setup is not in it. vertex, setup, frags: shares of the
frame time in the vertex stage (everything in a vertex batch outside the
raster core: state validation, transform, lighting, clipping, primitive
assembly), in primitive setup, and in coverage and fragments; other: the
rest (glClear, glFinish's copy, state changes outside vertex batches).
n/a: nothing to divide by, or the raster core's counters read 0 (a libfixgl
that does not count them), so the vertex stage cannot be told from the raster
core either.</p>
</body></html>
EOF
} >"$report_dir/report.html"

echo
echo "bench: report $report_dir/report.html (data: $tsv)"
echo "bench: \`ninja -C build bench-chart\` draws libfixgl/bench/chart.png from the data"
