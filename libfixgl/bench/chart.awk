# chart.awk - the benchmark's bar chart, from the data file run-bench.sh
# writes (build/bench/bench.tsv), in one of two forms of the same drawing:
#
#   awk -v format=svg  -f chart.awk bench.tsv   an SVG document (report.html)
#   awk -v format=oiio [-v font=FONT.ttf] [-v boldfont=BOLD.ttf] \
#       -f chart.awk bench.tsv                  the size "W H" on the first
#                                               line, then oiiotool's
#                                               arguments one a line that
#                                               draw it into a new image of
#                                               that size (make_chart.sh ->
#                                               chart.png)
#
# Top: frames per second per scene, log scale: fixgl with its default
# threads (one per CPU), fixgl on one thread (FIXGL_NUM_THREADS=1), OSMesa
# (llvmpipe, default threads) and OSMesa-1 (LP_NUM_THREADS=1).  Bottom:
# fixgl's fps over OSMesa's, like for like: default threads over default
# threads, one thread over one thread (1 = as fast).
#
# The data file: "# key value" lines (date, seconds, cpus), a header line
# starting with "scene", then one tab-separated line per scene whose
# columns named fixgl_fps, fixgl1_fps, osmesa_fps, osmesa1_fps are read
# (by the header's names; a file without fixgl1_fps draws three series).

BEGIN {
  FS = "\t"
  W = 960; H = 620
  X0 = 70; X1 = W - 20
  FPS_TOP = 70; FPS_BOT = 330
  RAT_TOP = 420; RAT_BOT = 560
  split("0.122 0.467 0.706,0.553 0.745 0.894,1.000 0.498 0.055,0.173 0.627 0.173", colour, ",")
  split("fixgl,fixgl-1,OSMesa,OSMesa-1", series, ",")
  split("fixgl_fps,fixgl1_fps,osmesa_fps,osmesa1_fps", column, ",")
  NS = 4
  GRID = "0.85 0.85 0.85"; AXIS = "0.2 0.2 0.2"; INK = "0.1 0.1 0.1"; MUTED = "0.4 0.4 0.4"
}

/^# / { meta[$0 ~ /^# [a-z]+ / ? substr($0, 3, index(substr($0, 3), " ") - 1) : ""] = substr($0, 3 + index(substr($0, 3), " ")); next }
$1 == "scene" {
  for (c = 1; c <= NF; c++)
    col[$c] = c
  next
}
NF < 4 { next }
{
  n++
  name[n] = $1
  for (k = 1; k <= NS; k++)
    fps[n, k] = (column[k] in col) ? $(col[column[k]]) + 0 : 0
}

# ---- the two output forms ------------------------------------------------
function hex(c,   p, s, i) {
  split(c, p, " ")
  s = "#"
  for (i = 1; i <= 3; i++)
    s = s sprintf("%02x", int(p[i] * 255 + 0.5))
  return s
}
function oiio_colour(c) { gsub(/ /, ",", c); return c }
function esc(s) { gsub(/&/, "\\&amp;", s); gsub(/</, "\\&lt;", s); gsub(/>/, "\\&gt;", s); return s }

function rect(x, y, w, h, c) {
  x = int(x + 0.5); y = int(y + 0.5); w = int(w + 0.5); h = int(h + 0.5)
  if (w <= 0 || h <= 0)
    return
  if (format == "svg")
    printf "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"%s\"/>\n", x, y, w, h, hex(c)
  else
    printf "--fill:color=%s\n%dx%d+%d+%d\n", oiio_colour(c), w, h, x, y
}
function line(x1, y1, x2, y2, c) {
  x1 = int(x1 + 0.5); y1 = int(y1 + 0.5); x2 = int(x2 + 0.5); y2 = int(y2 + 0.5)
  if (format == "svg")
    printf "<line x1=\"%d.5\" y1=\"%d.5\" x2=\"%d.5\" y2=\"%d.5\" stroke=\"%s\"/>\n", x1, y1, x2, y2, hex(c)
  else
    printf "--line:color=%s\n%d,%d,%d,%d\n", oiio_colour(c), x1, y1, x2, y2
}
# anchor: start, middle or end; y is the baseline
function text(x, y, size, anchor, c, s, bold) {
  x = int(x + 0.5); y = int(y + 0.5)
  if (format == "svg")
    printf "<text x=\"%d\" y=\"%d\" font-size=\"%d\" text-anchor=\"%s\" fill=\"%s\"%s>%s</text>\n",
           x, y, size, anchor, hex(c), bold ? " font-weight=\"bold\"" : "", esc(s)
  else
    printf "--text:x=%d:y=%d:size=%d:color=%s:xalign=%s%s\n%s\n", x, y, size, oiio_colour(c),
           anchor == "middle" ? "center" : anchor == "end" ? "right" : "left",
           font != "" ? ":font=" (bold && boldfont != "" ? boldfont : font) : "", s
}

function log10(v) { return log(v) / log(10) }
function fmt_fps(v) { return v >= 100 ? sprintf("%.0f", v) : v >= 10 ? sprintf("%.1f", v) : sprintf("%.2f", v) }

function legend(x, y, k, label) {
  rect(x, y - 10, 12, 12, colour[k])
  text(x + 17, y, 13, "start", INK, label)
  return x + 17 + 7.3 * length(label) + 24
}

END {
  if (n == 0) {
    print "chart.awk: no scenes in the data file" > "/dev/stderr"
    exit 1
  }
  if (format != "svg")
    print W " " H
  if (format == "svg") {
    printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\" font-family=\"DejaVu Sans, Verdana, sans-serif\">\n", W, H, W, H
  }
  rect(0, 0, W, H, "1 1 1")
  gw = (X1 - X0) / n

  # ---- frames per second, log scale ----
  text(X0, 26, 17, "start", INK, "Frames per second at 1024x768 (log scale)", 1)
  x = X0
  for (k = 1; k <= NS; k++)
    x = legend(x, 50, k, series[k] (k == 1 ? " (" (meta["cpus"] != "" ? meta["cpus"] : "all") " threads)" : k == 2 ? " (1 thread)" : k == 3 ? " (llvmpipe)" : " (1 thread)"))
  lo = 1e30; hi = 0
  for (i = 1; i <= n; i++)
    for (k = 1; k <= NS; k++)
      if (fps[i, k] > 0) {
        if (fps[i, k] < lo) lo = fps[i, k]
        if (fps[i, k] > hi) hi = fps[i, k]
      }
  if (hi == 0) { lo = 1; hi = 10 }
  dlo = int(log10(lo)); if (10 ^ dlo > lo) dlo--
  dhi = int(log10(hi)); if (10 ^ dhi < hi) dhi++
  if (dhi == dlo) dhi++
  for (d = dlo; d <= dhi; d++) {
    y = FPS_BOT - (d - dlo) / (dhi - dlo) * (FPS_BOT - FPS_TOP)
    line(X0, y, X1, y, GRID)
    text(X0 - 8, y + 4, 12, "end", MUTED, 10 ^ d >= 1 ? sprintf("%d", 10 ^ d) : sprintf("%g", 10 ^ d))
  }
  bw = gw * 0.2
  for (i = 1; i <= n; i++) {
    gx = X0 + (i - 1) * gw + (gw - NS * bw) / 2
    for (k = 1; k <= NS; k++) {
      v = fps[i, k]
      if (v <= 0)
        continue
      top = FPS_BOT - (log10(v) - dlo) / (dhi - dlo) * (FPS_BOT - FPS_TOP)
      rect(gx + (k - 1) * bw, top, bw - 1, FPS_BOT - top, colour[k])
    }
    # fixgl's fps above its bar
    if (fps[i, 1] > 0)
      text(gx + bw / 2, FPS_BOT - (log10(fps[i, 1]) - dlo) / (dhi - dlo) * (FPS_BOT - FPS_TOP) - 4,
           10, "middle", INK, fmt_fps(fps[i, 1]))
    text(X0 + (i - 0.5) * gw, FPS_BOT + 18, 13, "middle", INK, name[i])
  }
  line(X0, FPS_BOT, X1, FPS_BOT, AXIS)
  line(X0, FPS_TOP, X0, FPS_BOT, AXIS)

  # ---- ratios ----
  # ratio j: fixgl series j over OSMesa series j + 2
  text(X0, 376, 17, "start", INK, "fixgl fps / OSMesa fps, like for like (1 = as fast)", 1)
  x = legend(X0, 400, 1, "fixgl / OSMesa (default threads)")
  legend(x, 400, 2, "fixgl-1 / OSMesa-1 (one thread)")
  rmax = 1
  for (i = 1; i <= n; i++)
    for (j = 1; j <= 2; j++)
      if (fps[i, j + 2] > 0 && fps[i, j] / fps[i, j + 2] > rmax)
        rmax = fps[i, j] / fps[i, j + 2]
  step = rmax <= 1.5 ? 0.25 : rmax <= 3 ? 0.5 : 1
  rtop = step * int(rmax * 1.12 / step + 0.999)
  for (r = 0; r <= rtop + 1e-9; r += step) {
    y = RAT_BOT - r / rtop * (RAT_BOT - RAT_TOP)
    line(X0, y, X1, y, r == 1 ? AXIS : GRID)
    text(X0 - 8, y + 4, 12, "end", MUTED, sprintf("%.3g", r))
  }
  rw = gw * 0.3
  for (i = 1; i <= n; i++) {
    gx = X0 + (i - 1) * gw + (gw - 2 * rw) / 2
    for (j = 1; j <= 2; j++) {
      if (!(fps[i, j + 2] > 0 && fps[i, j] > 0))
        continue
      r = fps[i, j] / fps[i, j + 2]
      top = RAT_BOT - r / rtop * (RAT_BOT - RAT_TOP)
      rect(gx + (j - 1) * rw, top, rw - 1, RAT_BOT - top, colour[j])
      text(gx + (j - 1) * rw + rw / 2, top - 4, 10, "middle", INK, sprintf("%.2f", r))
    }
    text(X0 + (i - 0.5) * gw, RAT_BOT + 18, 13, "middle", INK, name[i])
  }
  line(X0, RAT_BOT, X1, RAT_BOT, AXIS)
  line(X0, RAT_TOP, X0, RAT_BOT, AXIS)

  foot = "fixgl bench"
  if (meta["date"] != "") foot = foot ", " meta["date"]
  if (meta["cpus"] != "") foot = foot ", " meta["cpus"] " CPU(s)"
  if (meta["seconds"] != "") foot = foot ", " meta["seconds"] " s per scene"
  text(W - 20, H - 12, 11, "end", MUTED, foot)

  if (format == "svg")
    print "</svg>"
}
