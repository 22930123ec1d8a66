/* fz_table.h - the fuzzer's table of entry points (fz_table.c is generated
 * by gen_table.py from the symbols libfixgl exports) and the call streams
 * built from it.
 *
 * A stream is an array of fz_call: an entry index and its arguments, each
 * an integer, a double or, for pointer parameters, an offset into one of the
 * executor's arenas (fz_ptr).  The arenas are large and mapped at a fixed
 * address, so whatever a call may legitimately read or write through a
 * pointer stays inside them (the generator bounds the sizes that decide
 * how much, fz_gen.c): a crash is the library's fault.  The input arena is
 * mapped 4 GB before and 8 GB after its contents (zero pages, no memory
 * used): element offsets that wrap in 32 bits, as the oracle computes
 * them, land inside it. */
#ifndef FZ_TABLE_H
#define FZ_TABLE_H

#include <stddef.h>
#include <stdint.h>

#ifdef FZ_WITH_CALLS
#include <GL/gl.h>
#include <GL/osmesa.h>
#endif

enum fz_kind {
    FZ_ENUM = 1, FZ_BITFIELD, FZ_BOOL, FZ_I8, FZ_U8, FZ_I16, FZ_U16, FZ_I32, FZ_U32,
    FZ_SIZE, FZ_F32, FZ_F64, FZ_PTR_IN, FZ_PTR_OUT, FZ_CTX
};
enum fz_ret { FZ_RET_VOID, FZ_RET_INT, FZ_RET_PTR };

#define FZ_MAX_ARGS 12

typedef struct {
    uint8_t kind;        /* enum fz_kind */
    int16_t cls;         /* index into fz_enum_classes, -1: none */
    const char *name;    /* the parameter's name in the header */
} fz_param;

typedef struct {
    const char *name;
    uint8_t ret;         /* enum fz_ret */
    uint8_t nparams;
    fz_param params[FZ_MAX_ARGS];
} fz_entry;

typedef struct {
    const char *name;
    const uint32_t *values;
    size_t count;
} fz_enum_class;

typedef union {
    int64_t i;           /* integers, enums, arena offsets */
    double d;            /* floats and doubles */
} fz_arg;

typedef struct {
    uint32_t fn;         /* index into fz_table */
    fz_arg a[FZ_MAX_ARGS];
} fz_call;

extern const fz_entry fz_table[];
extern const size_t fz_table_count;
extern const fz_enum_class fz_enum_classes[];
extern const size_t fz_enum_class_count;
extern const uint32_t fz_all_enums[];
extern const size_t fz_all_enum_count;

/* Arenas (fz_exec.c): inputs read through const pointers, outputs written
 * through the others; the select and feedback buffers live in the second
 * half of the output arena, which per-call outputs never reach. */
#define FZ_IN_BASE     ((uintptr_t)0x3f0100000000ull)
#define FZ_IN_SIZE     (48u << 20)   /* filled; the mapping is larger: */
#define FZ_IN_BEFORE   (4ull << 30)  /* readable zeros before FZ_IN_BASE */
#define FZ_IN_AFTER    (8ull << 30)  /* and after it (32-bit offsets wrap) */
#define FZ_IN_WINDOW   (16u << 20)   /* pointers start in [16 MB, 32 MB) */
#define FZ_OUT_BASE    ((uintptr_t)0x3f4000000000ull)
#define FZ_OUT_SIZE    (48u << 20)
#define FZ_OUT_WINDOW  (8u << 20)    /* per-call outputs start below 8 MB */
#define FZ_OUT_PERSIST (24u << 20)   /* select/feedback buffers from here */
#define FZ_OUT_HASHED  4096u         /* bytes of each output compared */

#ifdef FZ_WITH_CALLS
typedef void (*fz_proc)(void);
extern fz_proc fz_fn[];
/* Calls entry i with arguments a; returns its result (pointers: non-NULL). */
uint64_t fz_call_entry(size_t i, const fz_arg *a);
/* The address an argument of kind k denotes. */
void *fz_ptr(int kind, int64_t off);
#endif

#endif
