/*
 * osmesa_api.c - behaviour of the OSMesa API itself, with no GL drawing focus.
 *
 * Built twice from this one source: linked with libfixgl (test `osmesa_api`)
 * and, when the system OSMesa is installed, linked with it (the oracle).
 *
 * Two kinds of evidence:
 *  - CHECK()s: behaviour the OSMesa API documents (GL_FALSE for a NULL buffer
 *    or a size below 1, release with OSMesaMakeCurrent(NULL, NULL, 0, 0, 0),
 *    zeros from OSMesaGetDepthBuffer without a depth buffer, ...).  They must
 *    hold for both libraries, which proves the checks themselves right.
 *  - A transcript on stdout of every value Mesa's behaviour defines but no
 *    document does (MAX_WIDTH, bytes per depth value, the current context
 *    after destroying it, ...).  Test `osmesa_api_vs_mesa` runs both builds
 *    and requires identical transcripts, instead of guessing the values here.
 *
 * Mesa 22.3 crashes on a few misuses (OSMesaPixelStore or
 * OSMesaGetIntegerv(OSMESA_FORMAT) with no current context,
 * OSMesaGetDepthBuffer on a context never made current,
 * OSMesaGetProcAddress(NULL)).  fixgl must survive them; those checks are
 * compiled only into the fixgl build (FIXGL_API_TEST_FIXGL).
 */
#include <GL/osmesa.h>
#include <GL/gl.h>

#include <stdio.h>
#include <string.h>

#include "check.h"

#define W 33 /* odd sizes catch width/height mix-ups */
#define H 17

static unsigned char color_buf[W * H * 4];

/* Prints one transcript line: a name and an integer. */
static void note(const char *what, long value)
{
  printf("%s = %ld\n", what, value);
}

/* Every OSMesaGetIntegerv pname, in transcript order. */
static const struct { GLint pname; const char *name; } int_pnames[] = {
  { OSMESA_WIDTH, "WIDTH" },       { OSMESA_HEIGHT, "HEIGHT" },
  { OSMESA_FORMAT, "FORMAT" },     { OSMESA_TYPE, "TYPE" },
  { OSMESA_ROW_LENGTH, "ROW_LENGTH" }, { OSMESA_Y_UP, "Y_UP" },
  { OSMESA_MAX_WIDTH, "MAX_WIDTH" }, { OSMESA_MAX_HEIGHT, "MAX_HEIGHT" },
};

/* Queries every pname and writes them to the transcript under `tag`. */
static void note_integers(const char *tag)
{
  for (size_t i = 0; i < sizeof int_pnames / sizeof int_pnames[0]; i++) {
    GLint v = -12345;
    char what[96];
    OSMesaGetIntegerv(int_pnames[i].pname, &v);
    snprintf(what, sizeof what, "%s: GetIntegerv(%s)", tag, int_pnames[i].name);
    note(what, v);
  }
}

static GLint get_integer(GLint pname)
{
  GLint v = -12345;
  OSMesaGetIntegerv(pname, &v);
  return v;
}

/* OSMesaMakeCurrent must refuse what it cannot bind, and keep the binding. */
static void test_make_current_rejects(void)
{
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  OSMesaContext c565 = OSMesaCreateContextExt(OSMESA_RGB_565, 16, 0, 0, NULL);
  CHECK(ctx != NULL, "OSMesaCreateContextExt(RGBA, 24, 8) failed");
  CHECK(c565 != NULL, "OSMesaCreateContextExt(RGB_565, 16, 0) failed");
  if (!ctx || !c565)
    return;

  CHECK(OSMesaMakeCurrent(ctx, NULL, GL_UNSIGNED_BYTE, W, H) == GL_FALSE,
        "NULL buffer accepted");
  CHECK(OSMesaMakeCurrent(ctx, color_buf, GL_UNSIGNED_BYTE, 0, H) == GL_FALSE,
        "width 0 accepted");
  CHECK(OSMesaMakeCurrent(ctx, color_buf, GL_UNSIGNED_BYTE, W, 0) == GL_FALSE,
        "height 0 accepted");
  CHECK(OSMesaMakeCurrent(ctx, color_buf, GL_UNSIGNED_BYTE, -W, H) == GL_FALSE,
        "negative width accepted");
  CHECK(OSMesaMakeCurrent(ctx, color_buf, GL_UNSIGNED_BYTE, W, -H) == GL_FALSE,
        "negative height accepted");
  CHECK(OSMesaMakeCurrent(NULL, color_buf, GL_UNSIGNED_BYTE, W, H) == GL_FALSE,
        "NULL context with a buffer accepted");
  CHECK(OSMesaMakeCurrent(ctx, color_buf, GL_INT, W, H) == GL_FALSE,
        "type GL_INT accepted for OSMESA_RGBA");
  CHECK(OSMesaMakeCurrent(c565, color_buf, GL_UNSIGNED_BYTE, W, H) == GL_FALSE,
        "OSMESA_RGB_565 accepted with GL_UNSIGNED_BYTE");
  CHECK(OSMesaGetCurrentContext() == NULL,
        "a refused OSMesaMakeCurrent made a context current");

  /* A refused bind leaves the current binding alone. */
  CHECK(OSMesaMakeCurrent(ctx, color_buf, GL_UNSIGNED_BYTE, W, H) == GL_TRUE,
        "valid OSMesaMakeCurrent refused");
  CHECK(OSMesaMakeCurrent(c565, NULL, GL_UNSIGNED_SHORT_5_6_5, W, H) == GL_FALSE,
        "NULL buffer accepted (565)");
  CHECK(OSMesaGetCurrentContext() == ctx, "refused bind changed the current context");
  CHECK(get_integer(OSMESA_WIDTH) == W, "refused bind changed the buffer width");

  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(c565);
  OSMesaDestroyContext(ctx);
}

/* Bad formats and NULL handles at creation and destruction. */
static void test_create_destroy(void)
{
  OSMesaContext bad = OSMesaCreateContextExt(0x1234, 24, 8, 0, NULL);
  note("CreateContextExt(format 0x1234) returned a context", bad != NULL);
  if (bad)
    OSMesaDestroyContext(bad);
  OSMesaDestroyContext(NULL); /* must be a no-op */
}

/* Creates a context from `attribs`; reports whether one came back and, if
 * it binds, that it draws (a cleared pixel reads back).  Destroys it. */
static int try_attribs(const int *attribs)
{
  OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, NULL);
  if (!ctx)
    return 0;
  static unsigned char px[4 * 4 * 4];
  int drew = 0;
  if (OSMesaMakeCurrent(ctx, px, GL_UNSIGNED_BYTE, 4, 4)) {
    glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    drew = px[1] == 255 && px[0] == 0 && glGetError() == GL_NO_ERROR;
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  }
  OSMesaDestroyContext(ctx);
  return drew ? 2 : 1;
}

#define ATTRIBS(...) ((const int[]){ __VA_ARGS__, 0 })

/* OSMesaCreateContextAttribs: the attributes both libraries refuse (each
 * value checked as it is read, so a bad one refuses even when a later one
 * is good), and the GL 1.x requests both honour; the last value of a
 * repeated attribute is the one that counts. */
static void test_create_attribs(void)
{
  const struct { const char *what; const int *attribs; int want; } cases[] = {
    { "empty list", ATTRIBS(0), 2 },
    { "compat profile", ATTRIBS(OSMESA_PROFILE, OSMESA_COMPAT_PROFILE), 2 },
    { "compat 1.0", ATTRIBS(OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 1, OSMESA_CONTEXT_MINOR_VERSION, 0), 2 },
    { "compat 1.3", ATTRIBS(OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 1, OSMESA_CONTEXT_MINOR_VERSION, 3), 2 },
    { "compat 1.5", ATTRIBS(OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 1, OSMESA_CONTEXT_MINOR_VERSION, 5), 2 },
    { "minor 5 alone", ATTRIBS(OSMESA_CONTEXT_MINOR_VERSION, 5), 2 },
    { "major 0", ATTRIBS(OSMESA_CONTEXT_MAJOR_VERSION, 0), 0 },
    { "major -1", ATTRIBS(OSMESA_CONTEXT_MAJOR_VERSION, -1), 0 },
    { "minor -1", ATTRIBS(OSMESA_CONTEXT_MINOR_VERSION, -1), 0 },
    { "major 0 then 1", ATTRIBS(OSMESA_CONTEXT_MAJOR_VERSION, 0, OSMESA_CONTEXT_MAJOR_VERSION, 1), 0 },
    { "compat 4.6", ATTRIBS(OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 6), 0 },
    { "1.100", ATTRIBS(OSMESA_CONTEXT_MAJOR_VERSION, 1, OSMESA_CONTEXT_MINOR_VERSION, 100), 0 },
    { "core 5.0", ATTRIBS(OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                          OSMESA_CONTEXT_MAJOR_VERSION, 5, OSMESA_CONTEXT_MINOR_VERSION, 0), 0 },
    { "profile 0x1234", ATTRIBS(OSMESA_PROFILE, 0x1234), 0 },
    { "core then compat", ATTRIBS(OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                  OSMESA_PROFILE, OSMESA_COMPAT_PROFILE), 2 },
    { "major 4 then 1", ATTRIBS(OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MAJOR_VERSION, 1), 2 },
    { "unknown attribute", ATTRIBS(0x9999, 1), 0 },
    { "OSMESA_ROW_LENGTH as an attribute", ATTRIBS(OSMESA_ROW_LENGTH, 5), 0 },
    { "format 0x1234", ATTRIBS(OSMESA_FORMAT, 0x1234), 0 },
    { "format BGRA", ATTRIBS(OSMESA_FORMAT, OSMESA_BGRA), 2 },
    { "depth -1", ATTRIBS(OSMESA_DEPTH_BITS, -1), 0 },
    { "stencil -1", ATTRIBS(OSMESA_STENCIL_BITS, -1), 0 },
    { "accum -1", ATTRIBS(OSMESA_ACCUM_BITS, -1), 0 },
    { "bits 100", ATTRIBS(OSMESA_DEPTH_BITS, 100, OSMESA_STENCIL_BITS, 100,
                          OSMESA_ACCUM_BITS, 100), 2 },
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    const int got = try_attribs(cases[i].attribs);
    char what[96];
    snprintf(what, sizeof what, "CreateContextAttribs(%s)", cases[i].what);
    note(what, got);
    CHECK(got == cases[i].want, "%s: %d, expected %d", what, got, cases[i].want);
  }
#ifdef FIXGL_API_TEST_FIXGL
  /* What fixgl cannot provide (the oracle, a GL 4.5 implementation, gives
   * a context): a core profile of any version, a compatibility profile
   * above 1.5; a compatibility context keeps its GL_VERSION. */
  const struct { const char *what; const int *attribs; } refused[] = {
    { "core", ATTRIBS(OSMESA_PROFILE, OSMESA_CORE_PROFILE) },
    { "core 1.0", ATTRIBS(OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                          OSMESA_CONTEXT_MAJOR_VERSION, 1, OSMESA_CONTEXT_MINOR_VERSION, 0) },
    { "core 3.3", ATTRIBS(OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                          OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3) },
    { "compat then core", ATTRIBS(OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                                  OSMESA_PROFILE, OSMESA_CORE_PROFILE) },
    { "compat 1.6", ATTRIBS(OSMESA_CONTEXT_MAJOR_VERSION, 1, OSMESA_CONTEXT_MINOR_VERSION, 6) },
    { "compat 2.0", ATTRIBS(OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 2) },
    { "compat 2.1", ATTRIBS(OSMESA_CONTEXT_MAJOR_VERSION, 2, OSMESA_CONTEXT_MINOR_VERSION, 1) },
    { "compat 3.3", ATTRIBS(OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3) },
    { "compat 4.5", ATTRIBS(OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5) },
    { "major 2147483647", ATTRIBS(OSMESA_CONTEXT_MAJOR_VERSION, 2147483647) },
    { "1.5 then 1.6", ATTRIBS(OSMESA_CONTEXT_MAJOR_VERSION, 1, OSMESA_CONTEXT_MINOR_VERSION, 5,
                              OSMESA_CONTEXT_MINOR_VERSION, 6) },
  };
  for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++)
    CHECK(try_attribs(refused[i].attribs) == 0, "CreateContextAttribs(%s) gave a context",
          refused[i].what);
  /* a NULL list is the empty list (Mesa reads through it) */
  CHECK(try_attribs(NULL) == 2, "CreateContextAttribs(NULL) gave no working context");
  OSMesaContext ctx = OSMesaCreateContextAttribs(
      ATTRIBS(OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 1,
              OSMESA_CONTEXT_MINOR_VERSION, 5), NULL);
  CHECK(ctx != NULL, "compat 1.5 refused");
  if (ctx) {
    CHECK(OSMesaMakeCurrent(ctx, color_buf, GL_UNSIGNED_BYTE, W, H) == GL_TRUE, "bind failed");
    const char *v = (const char *)glGetString(GL_VERSION);
    CHECK(v && strncmp(v, "1.5 ", 4) == 0, "compat 1.5 context: GL_VERSION %s", v ? v : "NULL");
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
  }
#endif
}

/* OSMesaGetIntegerv and OSMesaPixelStore on a bound RGBA context. */
static void test_integers(void)
{
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx != NULL, "OSMesaCreateContextExt failed");
  if (!ctx || !OSMesaMakeCurrent(ctx, color_buf, GL_UNSIGNED_BYTE, W, H)) {
    FAIL("cannot bind a %dx%d RGBA buffer", W, H);
    return;
  }

  CHECK(get_integer(OSMESA_WIDTH) == W, "OSMESA_WIDTH is %d", get_integer(OSMESA_WIDTH));
  CHECK(get_integer(OSMESA_HEIGHT) == H, "OSMESA_HEIGHT is %d", get_integer(OSMESA_HEIGHT));
  CHECK(get_integer(OSMESA_FORMAT) == OSMESA_RGBA, "OSMESA_FORMAT is %#x",
        get_integer(OSMESA_FORMAT));
  CHECK(get_integer(OSMESA_TYPE) == GL_UNSIGNED_BYTE, "OSMESA_TYPE is %#x",
        get_integer(OSMESA_TYPE));
  CHECK(get_integer(OSMESA_ROW_LENGTH) == 0, "default OSMESA_ROW_LENGTH is %d",
        get_integer(OSMESA_ROW_LENGTH));
  CHECK(get_integer(OSMESA_Y_UP) == 1, "default OSMESA_Y_UP is %d", get_integer(OSMESA_Y_UP));
  CHECK(get_integer(OSMESA_MAX_WIDTH) >= W, "OSMESA_MAX_WIDTH is %d",
        get_integer(OSMESA_MAX_WIDTH));
  CHECK(get_integer(OSMESA_MAX_HEIGHT) >= H, "OSMESA_MAX_HEIGHT is %d",
        get_integer(OSMESA_MAX_HEIGHT));
  note_integers("bound");

  OSMesaPixelStore(OSMESA_ROW_LENGTH, 40);
  OSMesaPixelStore(OSMESA_Y_UP, 0);
  CHECK(get_integer(OSMESA_ROW_LENGTH) == 40, "ROW_LENGTH 40 reads back as %d",
        get_integer(OSMESA_ROW_LENGTH));
  CHECK(get_integer(OSMESA_Y_UP) == 0, "Y_UP 0 reads back as %d", get_integer(OSMESA_Y_UP));
  note_integers("after PixelStore");

  OSMesaPixelStore(OSMESA_Y_UP, 5);
  note("Y_UP after PixelStore(Y_UP, 5)", get_integer(OSMESA_Y_UP));
  OSMesaPixelStore(OSMESA_ROW_LENGTH, -3);
  note("ROW_LENGTH after PixelStore(ROW_LENGTH, -3)", get_integer(OSMESA_ROW_LENGTH));
  note("glGetError after OSMesaPixelStore", (long)glGetError());
  OSMesaPixelStore(0x7777, 3); /* unknown pname: ignored */
  note("value left by GetIntegerv(unknown pname)", get_integer(0x7777));

  /* The colour buffer is the one handed over. */
  GLint w = -1, h = -1, format = -1;
  void *buffer = NULL;
  CHECK(OSMesaGetColorBuffer(ctx, &w, &h, &format, &buffer) == GL_TRUE,
        "OSMesaGetColorBuffer on a bound context failed");
  CHECK(w == W && h == H && format == OSMESA_RGBA && buffer == color_buf,
        "OSMesaGetColorBuffer gave %dx%d format %#x buffer %p", w, h, format, buffer);

  CHECK(OSMesaMakeCurrent(NULL, NULL, 0, 0, 0) == GL_TRUE, "release returned GL_FALSE");
  CHECK(OSMesaGetCurrentContext() == NULL, "context still current after release");
  note("WIDTH with no current context", get_integer(OSMESA_WIDTH));
  note("HEIGHT with no current context", get_integer(OSMESA_HEIGHT));
  note("MAX_WIDTH with no current context", get_integer(OSMESA_MAX_WIDTH));
  OSMesaDestroyContext(ctx);
}

/* OSMesaGetDepthBuffer / OSMesaGetColorBuffer with and without buffers. */
static void test_buffers(void)
{
  static const struct { GLint depth, stencil; } configs[] = {
    { 0, 0 }, { 16, 0 }, { 24, 0 }, { 24, 8 }, { 32, 0 },
  };
  for (size_t i = 0; i < sizeof configs / sizeof configs[0]; i++) {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, configs[i].depth,
                                               configs[i].stencil, 0, NULL);
    CHECK(ctx != NULL, "OSMesaCreateContextExt(depth %d, stencil %d) failed",
          configs[i].depth, configs[i].stencil);
    if (!ctx)
      continue;

    GLint w = -1, h = -1, format = -1, bpv = -1;
    void *buffer = color_buf;
    if (i == 0) {
      /* A context never bound has no colour buffer. */
      CHECK(OSMesaGetColorBuffer(ctx, &w, &h, &format, &buffer) == GL_FALSE,
            "colour buffer reported before OSMesaMakeCurrent");
      CHECK(w == 0 && h == 0 && format == 0 && buffer == NULL,
            "unbound colour buffer gave %d %d %d %p", w, h, format, buffer);
    }

    CHECK(OSMesaMakeCurrent(ctx, color_buf, GL_UNSIGNED_BYTE, W, H) == GL_TRUE,
          "bind failed");
    buffer = color_buf;
    GLboolean ok = OSMesaGetDepthBuffer(ctx, &w, &h, &bpv, &buffer);
    char what[96];
    snprintf(what, sizeof what, "depth %d stencil %d: GetDepthBuffer", configs[i].depth,
             configs[i].stencil);
    printf("%s = %d, %dx%d, %d bytes per value, buffer %s\n", what, ok, w, h, bpv,
           buffer ? "set" : "NULL");
    if (configs[i].depth == 0) {
      CHECK(ok == GL_FALSE, "depth buffer reported without one");
      CHECK(w == 0 && h == 0 && bpv == 0 && buffer == NULL,
            "no depth buffer gave %d %d %d %p", w, h, bpv, buffer);
    } else {
      CHECK(ok == GL_TRUE, "depth buffer not reported (depth %d)", configs[i].depth);
      CHECK(w == W && h == H && buffer != NULL, "depth buffer %dx%d %p", w, h, buffer);
    }
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
  }
}

/* Function pointers are compared and converted through void (*)(void), the
 * one type -Wcast-function-type accepts from and to any other. */
typedef void (*any_fn)(void);
typedef void (*clear_color_fn)(GLclampf, GLclampf, GLclampf, GLclampf);
typedef void (*clear_fn)(GLbitfield);
#define PROC(name) ((any_fn)OSMesaGetProcAddress(name))

/* OSMesaGetProcAddress: real functions for real names, NULL for others. */
static void test_proc_address(void)
{
  CHECK(PROC("OSMesaMakeCurrent") == (any_fn)OSMesaMakeCurrent,
        "OSMesaMakeCurrent resolves to another function");
  CHECK(PROC("OSMesaGetProcAddress") == (any_fn)OSMesaGetProcAddress,
        "OSMesaGetProcAddress resolves to another function");
  CHECK(PROC("OSMesaCreateContextExt") == (any_fn)OSMesaCreateContextExt,
        "OSMesaCreateContextExt resolves to another function");
#ifdef FIXGL_API_TEST_FIXGL
  /* Mesa hands out glapi dispatch stubs; fixgl returns the entry points. */
  CHECK(PROC("glClear") == (any_fn)glClear,
        "glClear resolves to another function");
  CHECK(PROC(NULL) == NULL, "OSMesaGetProcAddress(NULL) is not NULL");
  /* Mesa hands out a do-nothing dispatch stub for any unknown gl* name;
   * fixgl answers NULL for what it does not implement (no silent no-op) */
  CHECK(PROC("glFooBar") == NULL, "\"glFooBar\" resolves");
  CHECK(PROC("glCreateShader") == NULL, "glCreateShader resolves");
  CHECK(PROC("gl") == NULL, "\"gl\" resolves");
  /* the aliases of the advertised extensions */
  CHECK(PROC("glBlendColorEXT") == (any_fn)glBlendColor, "glBlendColorEXT is not glBlendColor");
  CHECK(PROC("glDrawRangeElementsEXT") == (any_fn)glDrawRangeElements,
        "glDrawRangeElementsEXT is not glDrawRangeElements");
#endif
  CHECK(PROC("nonsense") == NULL, "\"nonsense\" resolves");
  CHECK(PROC("") == NULL, "\"\" resolves");
  CHECK(PROC("OSMesaNoSuchFunction") == NULL,
        "\"OSMesaNoSuchFunction\" resolves");

  /* The glClear and glClearColor handed out must work. */
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
  clear_color_fn clear_color = (clear_color_fn)PROC("glClearColor");
  clear_fn clear = (clear_fn)PROC("glClear");
  CHECK(clear_color != NULL && clear != NULL, "glClearColor or glClear not found");
  if (!ctx || !OSMesaMakeCurrent(ctx, color_buf, GL_UNSIGNED_BYTE, W, H)) {
    FAIL("cannot create and bind a context without depth buffer");
    return;
  }
  if (!clear_color || !clear)
    return;
  memset(color_buf, 0, sizeof color_buf);
  clear_color(1.0f, 0.0f, 1.0f, 1.0f);
  clear(GL_COLOR_BUFFER_BIT);
  glFinish();
  const unsigned char *last = color_buf + sizeof color_buf - 4;
  CHECK(color_buf[0] == 255 && color_buf[1] == 0 && color_buf[2] == 255 && color_buf[3] == 255,
        "first pixel after clear is %d %d %d %d", color_buf[0], color_buf[1], color_buf[2],
        color_buf[3]);
  CHECK(last[0] == 255 && last[1] == 0 && last[2] == 255 && last[3] == 255,
        "last pixel after clear is %d %d %d %d", last[0], last[1], last[2], last[3]);
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(ctx);
}

/* Which context is current across binds, releases and destruction. */
static void test_current(void)
{
  OSMesaContext a = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
  OSMesaContext b = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
  CHECK(a && b && a != b, "two contexts not created");
  if (!a || !b)
    return;
  CHECK(OSMesaGetCurrentContext() == NULL, "a context is current at the start");
  OSMesaMakeCurrent(a, color_buf, GL_UNSIGNED_BYTE, W, H);
  CHECK(OSMesaGetCurrentContext() == a, "a is not current");
  OSMesaMakeCurrent(b, color_buf, GL_UNSIGNED_BYTE, W, H);
  CHECK(OSMesaGetCurrentContext() == b, "b is not current");
  CHECK(OSMesaMakeCurrent(NULL, NULL, 0, 0, 0) == GL_TRUE, "release returned GL_FALSE");
  CHECK(OSMesaGetCurrentContext() == NULL, "b still current after release");

  OSMesaMakeCurrent(a, color_buf, GL_UNSIGNED_BYTE, W, H);
  OSMesaDestroyContext(a);
  note("current context is NULL after destroying it", OSMesaGetCurrentContext() == NULL);
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(b);
}

#ifdef FIXGL_API_TEST_FIXGL
/* Misuse that crashes Mesa 22.3 and must not crash fixgl. */
static void test_no_current_context(void)
{
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaPixelStore(OSMESA_ROW_LENGTH, 8);
  OSMesaPixelStore(OSMESA_Y_UP, 0);
  for (size_t i = 0; i < sizeof int_pnames / sizeof int_pnames[0]; i++) {
    GLint v = -12345;
    OSMesaGetIntegerv(int_pnames[i].pname, &v); /* any value; must not crash */
  }
  CHECK(get_integer(OSMESA_WIDTH) == 0, "WIDTH without a context is not 0");
  CHECK(get_integer(OSMESA_HEIGHT) == 0, "HEIGHT without a context is not 0");

  /* A context that was never bound has no buffers at all. */
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx != NULL, "OSMesaCreateContextExt failed");
  if (!ctx)
    return;
  GLint w = -1, h = -1, bpv = -1;
  void *buffer = color_buf;
  CHECK(OSMesaGetDepthBuffer(ctx, &w, &h, &bpv, &buffer) == GL_FALSE,
        "depth buffer reported before OSMesaMakeCurrent");
  CHECK(w == 0 && h == 0 && bpv == 0 && buffer == NULL,
        "unbound depth buffer gave %d %d %d %p", w, h, bpv, buffer);
  OSMesaDestroyContext(ctx);
}
#endif

int main(void)
{
  test_make_current_rejects();
  test_create_destroy();
  test_create_attribs();
  test_integers();
  test_buffers();
  test_proc_address();
  test_current();
#ifdef FIXGL_API_TEST_FIXGL
  test_no_current_context();
#endif
  return check_report("osmesa_api");
}
