# tables.awk - the benchmark's two tables from bench.tsv (run-bench.sh),
# as text (-v format=text) or as HTML tables (-v format=html).
#
# Frames per second: fixgl (default threads) and fixgl-1 (one thread),
# OSMesa (llvmpipe, default threads) and OSMesa-1 (LP_NUM_THREADS=1), the
# ratios like for like, and whether the check frames are the same.
#
# Scaling: fixgl's frames per second with 1, 2 and 4 threads
# (FIXGL_NUM_THREADS) and the speed-ups over one thread.
#
# Where fixgl spends a frame on one thread, from fixgl's counters
# (fixglStats) over the stats frames (bench.c stats_frames), per frame:
#   ms/frame     their wall-clock time (frame_ns / frames)
#   frags/frame  fragments the raster core shaded (fragments / frames)
#   ns/frag      raster_ns / fragments: the raster core's time after
#                primitive setup (coverage and the fragment stage: texture,
#                fog, per-fragment tests, blending, store) per shaded
#                fragment; setup time is not in it
#   vertex       vertex_ns / frame_ns: the vertex stage (everything in a
#                vertex batch outside the raster core)
#   setup        setup_ns / frame_ns: primitive setup
#   frags        raster_ns / frame_ns: coverage and fragments
#   other        the rest of the frame time: glClear, glFinish's copy,
#                state changes outside vertex batches
# n/a: nothing to divide by, or the raster core's counters read 0 (a
# libfixgl that does not count them): the vertex time then includes the
# raster core's, so only "other" is shown.

function pct(v, t) { return t > 0 ? sprintf("%.1f%%", 100 * v / t) : "n/a" }

function row(cells, header,   c, i, x) {
  c = split(cells, cell, "\t")
  if (format == "html") {
    x = "<tr>"
    for (i = 1; i <= c; i++)
      x = x (header ? "<th>" : "<td>") cell[i] (header ? "</th>" : "</td>")
    print x "</tr>"
  } else {
    x = sprintf("%-9s", cell[1])
    for (i = 2; i <= c; i++)
      x = x sprintf(" %" width[i] "s", cell[i])
    print x
  }
}

function widths(s,   i, c, w) {
  c = split(s, w, " ")
  for (i = 1; i <= c; i++)
    width[i + 1] = w[i]
}

BEGIN { FS = "\t" }
/^#/ || $1 == "scene" { next }
{ line[++n] = $0 }

END {
  T = "\t"
  if (format == "html")
    print "<h2>Frames per second</h2>\n<table>"
  widths("10 10 10 12 10 13 5")
  row("scene" T "fixgl fps" T "fixgl-1 fps" T "OSMesa fps" T "OSMesa-1 fps" T "fixgl/OSM" T \
      "fixgl-1/OSM-1" T "same", 1)
  for (i = 1; i <= n; i++) {
    split(line[i], v, "\t")
    f = v[2]; o = v[3]; o1 = v[4]; f1 = v[13]
    row(v[1] T sprintf("%.1f", f) T sprintf("%.1f", f1) T sprintf("%.1f", o) T sprintf("%.1f", o1) T \
        (o > 0 ? sprintf("%.2fx", f / o) : "n/a") T (o1 > 0 ? sprintf("%.2fx", f1 / o1) : "n/a") T v[5])
  }
  if (format == "html")
    print "</table>\n<h2>Scaling: fixgl with 1, 2 and 4 threads</h2>\n<table>"
  else
    print ""
  widths("9 9 9 7 7")
  row("scaling" T "1 thread" T "2 threads" T "4 threads" T "2/1" T "4/1", 1)
  for (i = 1; i <= n; i++) {
    split(line[i], v, "\t")
    t1 = v[13]; t2 = v[14]; t4 = v[15]
    row(v[1] T sprintf("%.1f", t1) T sprintf("%.1f", t2) T sprintf("%.1f", t4) T \
        (t1 > 0 ? sprintf("%.2fx", t2 / t1) : "n/a") T (t1 > 0 ? sprintf("%.2fx", t4 / t1) : "n/a"))
  }
  if (format == "html")
    print "</table>\n<h2>Where fixgl spends a frame (one thread)</h2>\n<table>"
  else
    print ""
  widths("9 12 8 7 7 7 7")
  row("fixgl-1" T "ms/frame" T "frags/frame" T "ns/frag" T "vertex" T "setup" T "frags" T "other", 1)
  for (i = 1; i <= n; i++) {
    split(line[i], v, "\t")
    frames = v[6]; t = v[7]; frags = v[8]; setup = v[9]; raster = v[10]; vert = v[11]
    if (!(frames > 0 && t > 0)) {
      row(v[1] T "n/a" T "n/a" T "n/a" T "n/a" T "n/a" T "n/a" T "n/a")
      continue
    }
    counted = frags > 0 || setup + raster > 0
    row(v[1] T sprintf("%.2f", t / frames / 1e6) T \
        (counted ? sprintf("%.0f", frags / frames) : "n/a") T \
        (frags > 0 ? sprintf("%.2f", raster / frags) : "n/a") T \
        (counted ? pct(vert, t) : "n/a") T (counted ? pct(setup, t) : "n/a") T \
        (counted ? pct(raster, t) : "n/a") T pct(t - vert - setup - raster, t))
  }
  if (format == "html")
    print "</table>"
}
