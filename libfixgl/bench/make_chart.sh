#!/usr/bin/env bash
# Draws the benchmark's bar chart (chart.awk) from the data of a run
# (bench.tsv, written by run-bench.sh into build/bench/) into a PNG with
# oiiotool (OpenImageIO): the README's chart, the same drawing as the SVG
# in build/bench/report.html.  `ninja -C build bench-chart` runs it into
# libfixgl/bench/chart.png.
#
#   make_chart.sh BENCH.TSV OUT.png
set -euo pipefail
if [[ $# -ne 2 ]]; then
  echo "usage: $0 BENCH.TSV OUT.png" >&2
  exit 2
fi
data=$1 out=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
[[ -f $data ]] || { echo "make_chart.sh: no $data: run ./fixgl bench first" >&2; exit 1; }
command -v oiiotool >/dev/null || { echo "make_chart.sh: oiiotool not found (openimageio-tools)" >&2; exit 1; }

# DejaVu Sans when installed, else OpenImageIO's default font
fonts=/usr/share/fonts/truetype/dejavu
font= bold=
[[ -f $fonts/DejaVuSans.ttf ]] && font=$fonts/DejaVuSans.ttf
[[ -f $fonts/DejaVuSans-Bold.ttf ]] && bold=$fonts/DejaVuSans-Bold.ttf

# chart.awk: the size as "W H" on its first line, then oiiotool's
# arguments one a line
mapfile -t args < <(awk -v format=oiio -v font="$font" -v boldfont="$bold" -f "$here/chart.awk" "$data")
[[ ${#args[@]} -gt 1 ]] || { echo "make_chart.sh: no chart drawn from $data" >&2; exit 1; }
size=${args[0]}
w=${size% *} h=${size#* }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
oiiotool --create "${w}x${h}" 3 "${args[@]:1}" -d uint8 -o "$tmp/chart.png"
mv "$tmp/chart.png" "$out"
echo "wrote $out"
