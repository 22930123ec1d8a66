/* fc_report.h - the conformance report: <dir>/index.html with the oracle
 * image, the fixgl image and amplified heat maps of every differing frame,
 * <dir>/summary.json with per-case numbers, and the per-tag summary table
 * printed by the runner.  GL-free. */
#ifndef FC_REPORT_H
#define FC_REPORT_H

#include "fc_compare.h"

#include <stdio.h>

struct fc_report;
struct fc_report_entry;

/* Creates dir and dir/img (removing PNGs of an earlier run).  NULL on error. */
struct fc_report *fc_report_open(const char *dir);

/* Renderer identification strings (GL_RENDERER, GL_VERSION) of each side. */
void fc_report_set_renderers(struct fc_report *r, const char *oracle_renderer,
                             const char *oracle_version, const char *fixgl_renderer,
                             const char *fixgl_version);

/* Starts a case; replay is the command-line fragment that re-runs it alone
 * (NULL for fixed cases, which re-run with --case NAME). */
struct fc_report_entry *fc_report_begin_case(struct fc_report *r, const char *name,
                                             const char *tags, const char *replay);

/* The list of known differences the run was given (its path, shown in the
 * report); without one, every differing case is "unlisted". */
void fc_report_set_known_file(struct fc_report *r, const char *path);

/* The case's entry in that list: its reason (the text after the name, ""
 * when the line has none), or NULL when it is not listed. */
void fc_report_set_known(struct fc_report_entry *e, const char *reason);

/* fc_frame_cb for fc_compare_case (ud = the entry): writes the PNGs of a
 * differing frame. */
void fc_report_frame(void *entry, int index, const struct fc_frame_view *oracle,
                     const struct fc_frame_view *fixgl, const struct fc_frame_stats *st);

/* Completes the case with its comparison result (copied; the entry takes
 * over res->documented); returns its status. */
const char *fc_report_end_case(struct fc_report_entry *e, const struct fc_case_result *res);

/* A random family compares too little when more than its bound of its
 * scenes (counted when it has at least FC_BLANK_MIN_SCENES) draw nothing:
 * FC_BLANK_MAX_PERCENT %, FC_BLANK_MAX_PERCENT_TEX % for random-tex.  The
 * plain, raster and texture generators place a witness in every scene
 * (fc_random.c fcr_witness), so only a few state combinations stay blank
 * (about 1%, 4-5% and 1-2%: random-tex 2, 6 and 3 of 300 on seeds 1-3,
 * 30, 19 and 25 before its witness), the lit and shading families none
 * blank. */
#define FC_BLANK_MAX_PERCENT 8
#define FC_BLANK_MAX_PERCENT_TEX 4
#define FC_BLANK_MIN_SCENES 50

/* Prints the per-tag table and totals; returns the number of random
 * families over the blank bound (FC_BLANK_MAX_PERCENT), which fail the run. */
int fc_report_print_summary(const struct fc_report *r, FILE *out);

/* Writes index.html and summary.json; returns the number of cases that do
 * not pass (neither exact nor, for a reference case, "agrees"),
 * or -1 if the files could not be written.  Frees r. */
int fc_report_finish(struct fc_report *r);

#endif
