#!/bin/sh
# check-frame.sh BENCH [BENCH...]: the benchmark's checksum of a scene does
# not depend on how many frames were drawn before it (bench.c, the check
# frame). The stipple scene drawn 8 and 9 times by each given build
# (fixgl-bench-fixgl, and fixgl-bench-osmesa when the oracle is built): the
# 9th frame's vertices wrap the vbo's 512 KiB buffer inside a line strip,
# whose stipple then restarts (on both libraries), so the last frames of
# the two runs differ; the check frames of all the runs must be one image.
set -eu
[ $# -ge 1 ] || { echo "usage: $0 BENCH [BENCH...]" >&2; exit 2; }
first=
for bench in "$@"; do
  for n in 8 9; do
    sum=$(FIXGL_NUM_THREADS=1 FIXGL_BENCH_FRAMES=$n "$bench" 1 stipple |
          awk '$1 == "scene" && $2 == "stipple" { print $8 }')
    [ -n "$sum" ] || { echo "FAIL: $bench drew no stipple scene" >&2; exit 1; }
    echo "$(basename "$bench") FIXGL_BENCH_FRAMES=$n stipple checksum $sum"
    first=${first:-$sum}
    [ "$sum" = "$first" ] || { echo "FAIL: checksum $sum, the first run's was $first" >&2; exit 1; }
  done
done
echo "PASS: one check frame over $# build(s) and 2 frame counts"
