/* p_shadow.c - depth textures and the shadow comparison (ORACLE-NOTES.md
 * "Depth textures and shadow comparison"): the pipe format of each depth
 * internal format and client type (GL_TEXTURE_DEPTH_SIZE, the stored
 * values read back), the value the sampler compares (r equal to it
 * passes GL_EQUAL, the next float does not), r clamped to [0, 1], the
 * LINEAR filter of the comparisons (the weight of the passing texel),
 * and glCopyTexImage from the depth buffer as the depth blit writes it. */
#include "probe.h"
#include <stdint.h>

#define W 16
#define H 16

static unsigned char buf[W * H * 4];

/* the sampler's value of a stored depth (lp_build_unsigned_norm_to_float) */
static float sampled(uint32_t z, int bits)
{
   if (bits == 32) {
      const uint32_t u = (z >> 9) | 0x3f800000u;
      float f;
      memcpy(&f, &u, 4);
      return (f - 1.0f) * (float)(8388608.0 / 8388607.0);
   }
   return (float)z * (bits == 16 ? (float)(1.0 / 65535.0) : (float)(1.0 / 16777215.0));
}

/* a quad over the buffer with constant (s, t, r) */
static void quad(float s, float t, float r)
{
   glBegin(GL_QUADS);
   glTexCoord3f(s, t, r);
   glVertex2f(0, 0);
   glVertex2f(W, 0);
   glVertex2f(W, H);
   glVertex2f(0, H);
   glEnd();
   glFinish();
}

static void compare_setup(GLenum func, GLenum filter)
{
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)filter);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)filter);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, (GLint)func);
}

int main(void)
{
   g_buf = buf;
   probe_init_ub(W, H);
   glEnable(GL_TEXTURE_2D);
   glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
   char what[96];

   /* pipe formats: unsized by type, sized by size */
   static const struct { GLenum internal, type; int bits; } fmt[] = {
      { GL_DEPTH_COMPONENT, GL_FLOAT, 24 }, { GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, 24 },
      { GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, 16 }, { GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, 32 },
      { GL_DEPTH_COMPONENT16, GL_UNSIGNED_INT, 16 }, { GL_DEPTH_COMPONENT24, GL_UNSIGNED_SHORT, 24 },
      { GL_DEPTH_COMPONENT32, GL_FLOAT, 32 },
   };
   const uint32_t uv[4] = { 0x12345678u, 0xfedcba98u, 0x80000000u, 0x00000fffu };
   const uint16_t sv[4] = { 0x1234, 0xfedc, 0x8000, 0x0001 };
   const float fv[4] = { 0.3f, 0.7f, 1.5f, -0.2f };
   for (size_t k = 0; k < sizeof(fmt) / sizeof(fmt[0]); k++) {
      const void *src = fmt[k].type == GL_FLOAT ? (const void *)fv
                      : fmt[k].type == GL_UNSIGNED_INT ? (const void *)uv
                                                       : (const void *)sv;
      glTexImage2D(GL_TEXTURE_2D, 0, (GLint)fmt[k].internal, 2, 2, 0, GL_DEPTH_COMPONENT,
                   fmt[k].type, src);
      GLint bits = -1;
      glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &bits);
      snprintf(what, sizeof what, "format %zu: depth bits", k);
      probe_expect(what, bits, fmt[k].bits);
      if (fmt[k].type == GL_UNSIGNED_BYTE)
         continue;
      /* the stored value of texel 0 from its model (pack.c
       * _mesa_unpack_depth_span), the comparison at exactly the value the
       * sampler reads and at the next float above */
      uint32_t z;
      if (fmt[k].type == GL_FLOAT) {
         z = fmt[k].bits == 32 ? (uint32_t)((double)fv[0] * 4294967295.0)
                               : (uint32_t)(fv[0] * (float)((1u << fmt[k].bits) - 1u));
      } else if (fmt[k].type == GL_UNSIGNED_INT) {
         z = fmt[k].bits == 32 ? uv[0] : uv[0] >> 16;   /* the 16-bit shortcut */
      } else if (fmt[k].bits == 16) {
         z = sv[0];
      } else {
         const float d = (float)sv[0] * (1.0f / 65535.0f);
         z = (uint32_t)(d * (float)0xffffff);
      }
      const float v = sampled(z, fmt[k].bits);
      glTexImage2D(GL_TEXTURE_2D, 0, (GLint)fmt[k].internal, 1, 1, 0, GL_DEPTH_COMPONENT,
                   fmt[k].type, src);
      compare_setup(GL_EQUAL, GL_NEAREST);
      quad(0.5f, 0.5f, v);
      snprintf(what, sizeof what, "format %zu: r == sampled value passes EQUAL", k);
      probe_expect(what, px(3, 3)[0], 255);
      quad(0.5f, 0.5f, nextafterf(v, 2.0f));
      snprintf(what, sizeof what, "format %zu: the next float fails EQUAL", k);
      probe_expect(what, px(3, 3)[0], 0);
   }

   /* r clamped to [0, 1]: -0.5 equals a stored 0, 1.5 a stored 1 */
   const float zero_one[2] = { 0.0f, 1.0f };
   glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 2, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                zero_one);
   compare_setup(GL_EQUAL, GL_NEAREST);
   quad(0.25f, 0.5f, -0.5f);
   probe_expect("r -0.5 equals depth 0", px(3, 3)[0], 255);
   quad(0.75f, 0.5f, 1.5f);
   probe_expect("r 1.5 equals depth 1", px(3, 3)[0], 255);

   /* LINEAR: depths 0.25 and 0.75, r 0.5 under LEQUAL passes texel 1
    * only: the result is s's weight (s * 2 - 0.5's fraction) */
   const float two[2] = { 0.25f, 0.75f };
   glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 2, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                two);
   compare_setup(GL_LEQUAL, GL_LINEAR);
   for (int i = 1; i < 8; i++) {
      const float s = 0.25f + (float)i * 0.0625f;
      quad(s, 0.5f, 0.5f);
      const float c = s * 2.0f - 0.5f;
      const float w = c - floorf(c);
      snprintf(what, sizeof what, "LINEAR compare at s %g: the weight", (double)s);
      probe_expect(what, px(3, 3)[0], (long)nearbyintf(w * 255.0f));
   }

   /* glCopyTexImage2D from the 24-bit depth buffer into a 16-bit depth
    * texture: the depth blit's fragment depth, z24 * (float)(1/16777215)
    * converted to 16 bits with gallivm's rounding */
   glDisable(GL_TEXTURE_2D);
   glClearDepth(1.0);
   glClear(GL_DEPTH_BUFFER_BIT);
   glEnable(GL_DEPTH_TEST);
   glDepthFunc(GL_ALWAYS);
   glBegin(GL_TRIANGLES);
   glVertex3f(0, 0, -0.9f);
   glVertex3f(2 * W, 0, 0.3f);
   glVertex3f(0, 2 * H, 0.7f);
   glEnd();
   glFinish();
   uint32_t z32[W];
   glReadPixels(0, 5, W, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, z32);
   glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, 0, 5, W, 1, 0);
   uint16_t got[W];
   glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, got);
   int bad = 0;
   for (int i = 0; i < W; i++) {
      const float d = (float)(z32[i] >> 8) * (float)(1.0 / 16777215.0);
      const float m = d * (65535.0f / 65536.0f) + 128.0f;
      uint32_t u;
      memcpy(&u, &m, 4);
      bad += got[i] != (uint16_t)(u & 0xffffu);
   }
   probe_expect("copy Z24 -> Z16: texels off the blit model", bad, 0);
   return probe_result();
}
