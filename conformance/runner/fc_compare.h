/* fc_compare.h - comparison of the records one case produced on the oracle
 * and on fixgl: colour bytes and raw depth values of every frame, and the
 * error / query / blob / value sequences.  GL-free. */
#ifndef FC_COMPARE_H
#define FC_COMPARE_H

#include "fc_record.h"

#include <stddef.h>
#include <stdint.h>

/* One captured frame, pointing into a record buffer. */
struct fc_frame_view {
    struct fc_frame_hdr hdr;
    const unsigned char *color, *depth;
    uint64_t color_len, depth_len;
};

struct fc_frame_stats {
    uint64_t pixels;            /* colour pixels compared (row_length x height) */
    uint64_t mismatched;        /* pixels with any differing byte */
    int max_diff;               /* largest per-byte difference */
    uint64_t at_1;              /* pixels whose largest byte difference is 1 */
    uint64_t beyond;            /* pixels with a byte difference > the tolerance
                                 * (= mismatched when the tolerance is 0) */
    uint64_t depth_values, depth_mismatches;
    int layout_differs;         /* sizes / formats / depth presence differ */
    int blank;                  /* both frames show a cleared buffer: every
                                 * colour pixel alike, every depth value alike
                                 * (fc_frame_blank) */
};

#define FC_MAX_NOTES 24
#define FC_NOTE_LEN 320

/* A record that differed under a documented difference
 * (fc_documented_difference in fc_case.h). */
#define FC_DOC_LABEL_LEN 64
#define FC_DOC_REASON_LEN 240
#define FC_DOC_VALUE_LEN 96
struct fc_documented {
    char label[FC_DOC_LABEL_LEN];
    char reason[FC_DOC_REASON_LEN];
    char kind[24];                      /* "query", "value" or "blob" */
    char oracle[FC_DOC_VALUE_LEN], fixgl[FC_DOC_VALUE_LEN];
};

struct fc_case_result {
    int frames;
    uint64_t pixels, mismatched_pixels;
    int max_channel_diff;
    /* set by the caller before fc_compare_case: the colour tolerance of a
     * reference case in LSB (fc_case.h), 0 = exact */
    int tolerance;
    uint64_t pixels_at_1;       /* pixels whose largest channel difference is 1 */
    uint64_t pixels_beyond;     /* pixels beyond the tolerance */
    uint64_t depth_values, depth_mismatches;
    int error_mismatches, query_mismatches, blob_mismatches, value_mismatches;
    int structure_mismatches;   /* records of different kind/label/count */
    int crashed;                /* a side did not finish the case */
    int blank;                  /* the case captured frames, every one blank
                                 * on both sides, and does not declare
                                 * draws_nothing (fc_case.h): it compares no
                                 * drawing */
    int blank_allowed;          /* the same for a generated scene
                                 * (FC_MAY_DRAW_NOTHING): counted, not failed */
    int nnotes, dropped_notes;
    char notes[FC_MAX_NOTES][FC_NOTE_LEN];
    /* differing records allowed by a documented difference (malloc'd,
     * owned by whoever holds the result: fc_report_end_case takes it) */
    int ndocumented;
    struct fc_documented *documented;
    /* set by the caller: both sides ran the same renderer (the harness
     * self-test), so documented differences compare equal and are not
     * reported as stale */
    int self_compare;
};

/* Called for every frame pair, before the case result is final. */
typedef void (*fc_frame_cb)(void *ud, int index, const struct fc_frame_view *oracle,
                            const struct fc_frame_view *fixgl, const struct fc_frame_stats *st);

/* 1 when the frame shows a cleared or untouched buffer: the colour bytes
 * of every pixel (the first width of each row) equal those of the first
 * pixel and every depth value equals the first. */
int fc_frame_blank(const struct fc_frame_view *f);

void fc_compare_frame(const struct fc_frame_view *a, const struct fc_frame_view *b,
                      struct fc_frame_stats *st);
/* Same with a colour tolerance in LSB (st->beyond counts the pixels past it). */
void fc_compare_frame_tol(const struct fc_frame_view *a, const struct fc_frame_view *b,
                          int tolerance, struct fc_frame_stats *st);

/* Compares two record sequences (the records between CASE and END; other
 * kinds are ignored).  res must be zeroed by the caller, who may have added
 * notes (e.g. about crashes) already. */
void fc_compare_case(const unsigned char *a, size_t alen, const unsigned char *b, size_t blen,
                     struct fc_case_result *res, fc_frame_cb cb, void *ud);

/* Appends a printf-style note to res (bounded). */
void fc_result_note(struct fc_case_result *res, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Frees res->documented. */
void fc_result_free(struct fc_case_result *res);

/* "exact", "agrees" (a reference case: colours differ, none by more than
 * its tolerance, everything else exact), "differs", "blank" (exact, but
 * every frame shows a cleared buffer: res->blank) or "error". */
const char *fc_result_status(const struct fc_case_result *res);

/* 1 for the statuses that pass: "exact" and "agrees". */
int fc_status_passes(const char *status);

#endif
