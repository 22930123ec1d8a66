/* fc_record.h - binary record stream written by the renderers, read by the runner.
 *
 * A renderer output file is a sequence of records.  Every record is
 *   u32 kind, u32 label_len, u64 payload_len, label bytes, payload bytes
 * in host byte order (writer and reader always run on the same machine).
 * A case starts with FC_REC_CASE (label = case name) and ends with
 * FC_REC_END; a case without FC_REC_END crashed or timed out.  The file
 * starts with FC_REC_INFO records (label "renderer"/"version").
 * This header is GL-free: the runner includes it without any GL headers. */
#ifndef FC_RECORD_H
#define FC_RECORD_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

enum fc_rec_kind {
    FC_REC_INFO = 1,  /* payload: text */
    FC_REC_CASE,      /* label: case name, payload: empty */
    FC_REC_VALUE,     /* payload: int64 (OSMesa return values, etc.) */
    FC_REC_ERROR,     /* payload: uint32 glGetError() value */
    FC_REC_QUERY,     /* payload: u32 type, u32 count, count values */
    FC_REC_BLOB,      /* payload: raw bytes */
    FC_REC_FRAME,     /* payload: struct fc_frame_hdr fields, colour, depth */
    FC_REC_END,       /* payload: int32 status, then a text message */
    FC_REC_DOCUMENTED, /* label: a record label, payload: the reason text
                        * (fc_documented_difference) */
    FC_REC_DRAWS_NOTHING /* right after FC_REC_CASE, label: "draws nothing",
                          * payload: int32 the case's draws_nothing
                          * (fc_case.h), when not 0 */
};

/* Fill byte of fresh colour buffers and of glGet output arrays (values a
 * query did not write keep it). */
#define FC_FILL_BYTE 0xCD

/* FC_REC_QUERY value types (element sizes 4, 4, 8, 1). */
enum fc_query_type { FC_Q_INT = 1, FC_Q_FLOAT, FC_Q_DOUBLE, FC_Q_BOOL };

/* fc_case.draws_nothing values (fc_case.h), the payload of
 * FC_REC_DRAWS_NOTHING. */
enum fc_draws_nothing { FC_DRAWS_NOTHING = 1, FC_MAY_DRAW_NOTHING = 2 };

/* FC_REC_END statuses. */
enum fc_end_status { FC_END_OK = 0, FC_END_HARNESS = 1 };

/* Frame header, serialised as FC_FRAME_HDR_FIELDS int32 values. */
struct fc_frame_hdr {
    int32_t width, height;      /* framebuffer size in pixels */
    int32_t row_length;         /* buffer row length in pixels (>= width) */
    int32_t format;             /* OSMESA_RGBA, ... */
    int32_t bpp;                /* bytes per colour pixel */
    int32_t y_up;               /* 1: row 0 is the bottom row */
    int32_t depth_ok;           /* OSMesaGetDepthBuffer return value */
    int32_t depth_w, depth_h, depth_bpv;
};
#define FC_FRAME_HDR_FIELDS 10

/* One parsed record; pointers point into the buffer given to fc_rec_next. */
struct fc_rec {
    uint32_t kind;
    const char *label;          /* not NUL-terminated */
    uint32_t label_len;
    const unsigned char *payload;
    uint64_t payload_len;
};

/* Writer.  Each call writes one complete record and flushes the stream,
 * so a crash loses at most the record being written. */
int fc_rec_write(FILE *f, uint32_t kind, const char *label,
                 const void *p1, uint64_t n1, const void *p2, uint64_t n2,
                 const void *p3, uint64_t n3);

/* Reader: parses the record at *pos in buf[0..len) and advances *pos.
 * Returns 1 on success, 0 at the end or on a truncated record. */
int fc_rec_next(const unsigned char *buf, size_t len, size_t *pos, struct fc_rec *out);

/* Decodes a frame payload.  Returns 0 when the payload is malformed. */
int fc_frame_parse(const struct fc_rec *r, struct fc_frame_hdr *hdr,
                   const unsigned char **color, uint64_t *color_len,
                   const unsigned char **depth, uint64_t *depth_len);

/* Compares a record label with a C string. */
int fc_rec_label_is(const struct fc_rec *r, const char *s);

#endif
