/*
 * test_frag.c - unit tests of the per-fragment operations
 * (raster/r_frag.c r_fragment_ops) on a one-pixel target, against
 * hand-written models of the oracle's rules (libfixgl/ORACLE-NOTES.md
 * "Blending, alpha test, dithering", "Per-fragment operations"):
 *
 *   blend terms     (t + (t >> 8) + 128) >> 8 with t = a * f, for every a, f
 *                   (lp_build_mul_norm; 24 pairs differ from round(t / 255)),
 *                   saturating add/subtract, min/max
 *   alpha test      clamped alpha RNE(*255) compared with the u8 reference
 *   stencil         (ref & vm) func (s & vm); op; merged under the write mask
 *   logic ops       the sixteen bitwise functions
 *   colour mask     per channel
 *   zeroed r_state  a plain store (the path other primitives rely on)
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "raster/r_state.h"

#include "check.h"

static uint8_t pixel[4];
static uint32_t zs32;
static uint8_t zs8;

/* The state objects of the tests' r_state, which each test edits. */
static struct r_fb_state t_fb;
static struct r_rast_state t_rast;
static struct r_dsa_state t_dsa;
static struct r_blend_state t_blend;
static struct r_fs_state t_fs;

/* A 1x1 target with a Z24S8 buffer and every op off. */
static struct r_state target(void)
{
   struct r_state rs;
   memset(&rs, 0, sizeof rs);
   memset(&t_fb, 0, sizeof t_fb);
   memset(&t_rast, 0, sizeof t_rast);
   memset(&t_dsa, 0, sizeof t_dsa);
   memset(&t_blend, 0, sizeof t_blend);
   memset(&t_fs, 0, sizeof t_fs);
   rs.fb = &t_fb;
   rs.rast = &t_rast;
   rs.dsa = &t_dsa;
   rs.blend = &t_blend;
   rs.fs = &t_fs;
   t_fb.color = pixel;
   t_fb.zs = &zs32;
   t_fb.zs_format = R_ZS_Z24S8;
   t_fb.width = t_fb.height = 1;
   rs.x1 = rs.y1 = 1;
   t_blend.color_mask = 0xf;
   rs.full_ops = true;
   return rs;
}

/* The fragment colour that converts to u8 value v. */
static float unorm(unsigned v)
{
   return (float)v / 255.0f;
}

static void test_plain_store(void)
{
   struct r_state rs = target();
   rs.full_ops = false;
   t_blend.color_mask = 0;            /* ignored on the plain path */
   const float c[4] = { 1.0f, 0.5f, 0.0f, unorm(77) };
   r_fragment_ops(&rs, 0, 0, 0.5f, c);
   CHECK(pixel[0] == 255 && pixel[1] == 128 && pixel[2] == 0 && pixel[3] == 77,
         "plain store gave %u %u %u %u", pixel[0], pixel[1], pixel[2], pixel[3]);
}

/* Every source value times every source-alpha factor (dst ZERO): gallivm's
 * normalized multiply, which is round(a * f / 255) except for 24 pairs
 * such as 152 * 229 (136, not 137). */
static void test_blend_mul(void)
{
   struct r_state rs = target();
   t_blend.enable = true;
   t_blend.blend_eq = R_BLEND_ADD;
   t_blend.blend_src = R_BF_SRC_ALPHA;
   t_blend.blend_dst = R_BF_ZERO;
   int bad = 0;
   for (unsigned a = 0; a < 256; a++) {
      for (unsigned f = 0; f < 256; f++) {
         const float c[4] = { unorm(a), 0, 0, unorm(f) };
         r_fragment_ops(&rs, 0, 0, 0, c);
         const unsigned t = a * f;
         const unsigned want = (t + (t >> 8) + 128) >> 8;
         if (pixel[0] != want && bad++ < 5)
            FAIL("blend %u * %u / 255 = %u, expected %u", a, f, pixel[0], want);
      }
   }
   const float c[4] = { unorm(152), 0, 0, unorm(229) };
   r_fragment_ops(&rs, 0, 0, 0, c);
   CHECK(pixel[0] == 136, "152 * 229 gave %u, expected 136 (not the rounded 137)", pixel[0]);
}

/* Equations on one pair of terms: ONE/ONE gives s + d saturated, s - d and
 * d - s clamped at 0, min and max. */
static void test_blend_equations(void)
{
   static const unsigned vals[] = { 0, 1, 100, 128, 200, 254, 255 };
   struct r_state rs = target();
   t_blend.enable = true;
   t_blend.blend_src = t_blend.blend_dst = R_BF_ONE;
   for (int e = R_BLEND_ADD; e <= R_BLEND_MAX; e++) {
      t_blend.blend_eq = (enum r_blend_eq)e;
      for (unsigned i = 0; i < sizeof vals / sizeof vals[0]; i++) {
         for (unsigned j = 0; j < sizeof vals / sizeof vals[0]; j++) {
            const unsigned s = vals[i], d = vals[j];
            unsigned want;
            switch (e) {
            case R_BLEND_ADD:      want = s + d > 255 ? 255 : s + d; break;
            case R_BLEND_SUBTRACT: want = s > d ? s - d : 0; break;
            case R_BLEND_REVERSE_SUBTRACT: want = d > s ? d - s : 0; break;
            case R_BLEND_MIN:      want = s < d ? s : d; break;
            default:               want = s > d ? s : d; break;
            }
            pixel[1] = (uint8_t)d;
            const float c[4] = { 0, unorm(s), 0, 1 };
            r_fragment_ops(&rs, 0, 0, 0, c);
            CHECK(pixel[1] == want, "equation %d on s %u d %u gave %u, expected %u",
                  e, s, d, pixel[1], want);
         }
      }
   }
}

/* SRC_ALPHA_SATURATE: min(src.a, 1 - dst.a) for rgb, one for alpha; a
 * buffer without alpha reads the destination alpha as one. */
static void test_saturate(void)
{
   struct r_state rs = target();
   t_blend.enable = true;
   t_blend.blend_eq = R_BLEND_ADD;
   t_blend.blend_src = R_BF_SRC_ALPHA_SATURATE;
   t_blend.blend_dst = R_BF_ZERO;
   pixel[3] = 200;                       /* 1 - dst.a = 55 */
   const float c[4] = { 1, 1, 1, unorm(100) };
   r_fragment_ops(&rs, 0, 0, 0, c);
   CHECK(pixel[0] == 55 && pixel[3] == 100, "saturate gave rgb %u alpha %u", pixel[0], pixel[3]);
   t_blend.dst_alpha_one = true;
   pixel[3] = 0;
   r_fragment_ops(&rs, 0, 0, 0, c);
   CHECK(pixel[0] == 0, "saturate without dst alpha gave %u", pixel[0]);
}

static bool func_model(enum r_func f, unsigned a, unsigned b)
{
   switch (f) {
   case R_NEVER:    return false;
   case R_LESS:     return a < b;
   case R_EQUAL:    return a == b;
   case R_LEQUAL:   return a <= b;
   case R_GREATER:  return a > b;
   case R_NOTEQUAL: return a != b;
   case R_GEQUAL:   return a >= b;
   default:         return true;
   }
}

static void test_alpha(void)
{
   struct r_state rs = target();
   t_dsa.alpha_test = true;
   t_dsa.alpha_ref = 128;
   for (int f = R_NEVER; f <= R_ALWAYS; f++) {
      t_dsa.alpha_func = (enum r_func)f;
      for (unsigned a = 120; a < 136; a++) {
         memset(pixel, 0, sizeof pixel);
         const float c[4] = { 1, 0, 0, unorm(a) };
         r_fragment_ops(&rs, 0, 0, 0, c);
         CHECK((pixel[0] == 255) == func_model((enum r_func)f, a, 128),
               "alpha func %d alpha %u ref 128: drawn %d", f, a, pixel[0] == 255);
      }
   }
   /* alpha above 1 clamps to 1 (255) */
   t_dsa.alpha_func = R_EQUAL;
   t_dsa.alpha_ref = 255;
   const float hi[4] = { 0, 1, 0, 7.0f };
   memset(pixel, 0, sizeof pixel);
   r_fragment_ops(&rs, 0, 0, 0, hi);
   CHECK(pixel[1] == 255, "alpha 7 does not equal 255");

   /* buffers without alpha (OSMESA_RGB): float compare with the unclamped
    * reference, unordered (NaN passes) */
   static const struct { enum r_func f; float alpha, ref; bool pass; } fl[] = {
      { R_EQUAL, 0.5f, 0.501f, false },       /* both 128 in u8 */
      { R_EQUAL, 0.5f, 0.5f, true },
      { R_LESS, 1.0f, 2.0f, true },           /* the reference is not clamped */
      { R_GEQUAL, 0.0f, -1.0f, true },
      { R_GREATER, 0.25f, NAN, true },
      { R_NEVER, 0.25f, NAN, false },
      { R_LEQUAL, 3.0f, 1.0f, true },         /* alpha clamped to 1 */
   };
   t_dsa.alpha_test_float = true;
   for (unsigned i = 0; i < sizeof fl / sizeof fl[0]; i++) {
      t_dsa.alpha_func = fl[i].f;
      t_dsa.alpha_ref_float = fl[i].ref;
      memset(pixel, 0, sizeof pixel);
      const float c[4] = { 1, 0, 0, fl[i].alpha };
      r_fragment_ops(&rs, 0, 0, 0, c);
      CHECK((pixel[0] == 255) == fl[i].pass, "float alpha test %u: drawn %d", i, pixel[0] == 255);
   }
}

static uint8_t stencil_model(enum r_stencil_op op, uint8_t s, uint8_t ref)
{
   switch (op) {
   case R_STENCIL_ZERO:      return 0;
   case R_STENCIL_REPLACE:   return ref;
   case R_STENCIL_INCR:      return s < 255 ? (uint8_t)(s + 1) : 255;
   case R_STENCIL_DECR:      return s > 0 ? (uint8_t)(s - 1) : 0;
   case R_STENCIL_INCR_WRAP: return (uint8_t)(s + 1);
   case R_STENCIL_DECR_WRAP: return (uint8_t)(s - 1);
   case R_STENCIL_INVERT:    return (uint8_t)~s;
   default:                  return s;
   }
}

/* Each op as fail, zfail and zpass, from several values, under masks, in a
 * Z24S8 word (depth bits kept) and in an S8 buffer. */
static void test_stencil(void)
{
   static const uint8_t starts[] = { 0, 1, 0x7f, 0xfe, 0xff };
   static const uint8_t wmasks[] = { 0xff, 0x0f, 0x00 };
   for (int fmt = 0; fmt < 2; fmt++) {
      struct r_state rs = target();
      if (fmt) {
         t_fb.zs = &zs8;
         t_fb.zs_format = R_ZS_S8;
      }
      t_dsa.stencil_test = true;
      t_dsa.stencil_ref = 0x5a;
      t_dsa.stencil_valuemask = 0xff;
      t_dsa.depth_test = fmt == 0;
      t_dsa.depth_func = R_LESS;
      for (int op = R_STENCIL_KEEP; op <= R_STENCIL_INVERT; op++) {
         for (int which = 0; which < 3; which++) {      /* fail, zfail, zpass */
            if (fmt == 1 && which == 1)
               continue;                                /* no depth buffer */
            t_dsa.stencil_fail = which == 0 ? (enum r_stencil_op)op : R_STENCIL_KEEP;
            t_dsa.stencil_zfail = which == 1 ? (enum r_stencil_op)op : R_STENCIL_KEEP;
            t_dsa.stencil_zpass = which == 2 ? (enum r_stencil_op)op : R_STENCIL_KEEP;
            t_dsa.stencil_func = which == 0 ? R_NEVER : R_ALWAYS;
            for (unsigned k = 0; k < sizeof starts; k++) {
               for (unsigned m = 0; m < sizeof wmasks; m++) {
                  t_dsa.stencil_writemask = wmasks[m];
                  /* depth 0x800000 in the word; z 0.75 fails LESS, 0.25 passes */
                  zs32 = (uint32_t)starts[k] << 24 | 0x800000u;
                  zs8 = starts[k];
                  const float c[4] = { 1, 1, 1, 1 };
                  r_fragment_ops(&rs, 0, 0, which == 1 ? 0.75f : 0.25f, c);
                  const uint8_t want_op = stencil_model((enum r_stencil_op)op, starts[k], 0x5a);
                  const uint8_t want = (uint8_t)((want_op & wmasks[m]) | (starts[k] & ~wmasks[m]));
                  const uint8_t got = fmt ? zs8 : (uint8_t)(zs32 >> 24);
                  CHECK(got == want, "fmt %d op %d as %d from %u mask %02x: %u, expected %u",
                        fmt, op, which, starts[k], wmasks[m], got, want);
                  if (fmt == 0 && which != 2)
                     CHECK((zs32 & 0xffffffu) == 0x800000u, "depth changed to %06x",
                           (unsigned)(zs32 & 0xffffffu));
               }
            }
         }
      }
   }
   /* the test: (ref & vm) func (s & vm) */
   struct r_state rs = target();
   t_dsa.stencil_test = true;
   t_dsa.stencil_writemask = 0xff;
   t_dsa.stencil_ref = 0x4f;
   t_dsa.stencil_valuemask = 0x70;
   for (int f = R_NEVER; f <= R_ALWAYS; f++) {
      t_dsa.stencil_func = (enum r_func)f;
      for (unsigned s = 0x30; s <= 0x50; s += 0x08) {
         zs32 = (uint32_t)s << 24;
         memset(pixel, 0, sizeof pixel);
         const float c[4] = { 1, 0, 0, 1 };
         r_fragment_ops(&rs, 0, 0, 0, c);
         CHECK((pixel[0] == 255) == func_model((enum r_func)f, 0x40, s & 0x70),
               "stencil func %d stencil %02x: drawn %d", f, s, pixel[0] == 255);
      }
   }
}

static void test_logic_ops(void)
{
   struct r_state rs = target();
   t_blend.logic_op = true;
   t_blend.enable = true;                      /* the logic op wins */
   t_blend.blend_src = R_BF_ZERO;
   t_blend.blend_dst = R_BF_ZERO;
   const unsigned s = 0xcc, d = 0xaa;
   for (unsigned op = 0; op < 16; op++) {
      t_blend.logic_op_mode = op;
      pixel[0] = (uint8_t)d;
      const float c[4] = { unorm(s), 0, 0, 1 };
      r_fragment_ops(&rs, 0, 0, 0, c);
      /* GL's encoding is the truth table: bits 0..3 of op - GL_CLEAR give
       * the result for (s, d) = (1, 1), (1, 0), (0, 1), (0, 0) */
      const unsigned want = ((op & 1) ? (s & d) : 0) | ((op & 2) ? (s & ~d) : 0) |
                            ((op & 4) ? (~s & d) : 0) | ((op & 8) ? (~s & ~d) : 0);
      CHECK(pixel[0] == (want & 0xff), "logic op %u gave %02x, expected %02x",
            op, pixel[0], want & 0xff);
   }
}

static void test_color_mask(void)
{
   struct r_state rs = target();
   for (unsigned m = 0; m < 16; m++) {
      t_blend.color_mask = m;
      memset(pixel, 9, sizeof pixel);
      const float c[4] = { 1, 1, 1, 1 };
      r_fragment_ops(&rs, 0, 0, 0, c);
      for (int ch = 0; ch < 4; ch++)
         CHECK(pixel[ch] == ((m >> ch) & 1 ? 255 : 9), "mask %x channel %d = %u", m, ch, pixel[ch]);
   }
}

int main(void)
{
   test_plain_store();
   test_blend_mul();
   test_blend_equations();
   test_saturate();
   test_alpha();
   test_stencil();
   test_logic_ops();
   test_color_mask();
   return check_report("unit-frag");
}
