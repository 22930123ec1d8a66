/*
 * test_cso.c - unit tests of the state objects (raster/r_state.h, the
 * cache raster/r_cso.c, their validation in state.c):
 *  - the cache returns one shared copy per content: equal bytes give the
 *    same pointer, different bytes another, and the copy does not change
 *    when the object it was made from does;
 *  - it keeps at most R_CSO_CACHE_MAX objects nobody holds, evicting the
 *    least recently used, and never an object that is held;
 *  - through the GL: a scene that switches between two states reuses the
 *    same objects (the cache does not grow, the r_state points to the same
 *    object for the same state), a group that is not dirty keeps its
 *    object, and glBitmap's cache keeps the state it was validated with
 *    alive across any number of later states.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <GL/osmesa.h>

#include "context.h"
#include "raster/r_state.h"

#include "check.h"

struct obj {
   uint32_t id;
   float v[7];
};

static struct obj make(uint32_t id)
{
   struct obj o;
   memset(&o, 0, sizeof o);
   o.id = id;
   for (int i = 0; i < 7; i++)
      o.v[i] = (float)id * 0.5f + (float)i;
   return o;
}

static void test_cache(void)
{
   struct r_cso_cache c;
   memset(&c, 0, sizeof c);

   struct obj a = make(1), b = make(2);
   const struct obj *pa = r_cso_lookup(&c, &a, sizeof a);
   const struct obj *pb = r_cso_lookup(&c, &b, sizeof b);
   CHECK(pa && pb && pa != pb, "two contents, two objects (%p %p)", (const void *)pa,
         (const void *)pb);
   CHECK(pa != &a, "the cache returns its own copy");
   struct obj a2 = make(1);
   CHECK(r_cso_lookup(&c, &a2, sizeof a2) == pa, "equal bytes give the same object");
   a.v[3] = 99.0f;
   CHECK(pa->v[3] == 3.5f, "the copy does not follow its source (%g)", (double)pa->v[3]);
   CHECK(r_cso_lookup(&c, &a, sizeof a) != pa, "changed bytes give another object");
   /* the same bytes with another size are another object */
   CHECK(r_cso_lookup(&c, &a2, sizeof a2 - 4) != pa, "the size is part of the key");

   /* eviction: hold pa, then look up many objects nobody holds */
   r_cso_hold(pa);
   for (uint32_t i = 100; i < 100 + 3 * R_CSO_CACHE_MAX; i++) {
      struct obj o = make(i);
      const struct obj *p = r_cso_lookup(&c, &o, sizeof o);
      CHECK(p && p->id == i, "object %u", i);
      CHECK(c.count <= R_CSO_CACHE_MAX + 1, "the cache holds %u objects", c.count);
   }
   CHECK(r_cso_lookup(&c, &a2, sizeof a2) == pa && pa->id == 1 && pa->v[6] == 6.5f,
         "a held object is never evicted");
   /* the most recent ones are still there, the oldest unheld ones not */
   struct obj last = make(100 + 3 * R_CSO_CACHE_MAX - 1);
   const unsigned before = c.count;
   const struct obj *pl = r_cso_lookup(&c, &last, sizeof last);
   CHECK(pl && c.count == before, "the last object is still cached (%u -> %u)", before, c.count);
   r_cso_release(pa);
   r_cso_cache_fini(&c);
   CHECK(c.count == 0 && c.entry == NULL, "fini empties the cache");
}

static uint8_t buf[64 * 64 * 4];

static void draw_tri(void)
{
   glBegin(GL_TRIANGLES);
   glVertex2f(-1, -1);
   glVertex2f(1, -1);
   glVertex2f(0, 1);
   glEnd();
   glFlush();
}

static void test_gl(void)
{
   OSMesaContext osm = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
   if (!osm) {
      FAIL("no context");
      return;
   }
   OSMesaMakeCurrent(osm, buf, GL_UNSIGNED_BYTE, 64, 64);
   struct fgl_context *ctx = fgl_get_current();
   glEnable(GL_DEPTH_TEST);
   glColor4f(0.2f, 0.4f, 0.6f, 0.5f);
   glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

   /* two states, many times */
   const struct r_blend_state *blend[2] = { NULL, NULL };
   const struct r_dsa_state *dsa = NULL;
   unsigned count_after_first = 0;
   for (int i = 0; i < 50; i++) {
      if (i & 1)
         glEnable(GL_BLEND);
      else
         glDisable(GL_BLEND);
      draw_tri();
      const struct r_state *rs = &ctx->_Raster;
      CHECK(rs->blend->enable == (i & 1), "draw %d: blend object %d", i, rs->blend->enable);
      if (i < 2) {
         blend[i] = rs->blend;
         dsa = rs->dsa;
      } else {
         CHECK(rs->blend == blend[i & 1], "draw %d: the same blend object for the same state", i);
         CHECK(rs->dsa == dsa, "draw %d: the same depth-stencil-alpha object", i);
      }
      if (i == 1)
         count_after_first = ctx->_StateCache.count;
      else if (i > 1)
         CHECK(ctx->_StateCache.count == count_after_first,
               "draw %d: the cache grew from %u to %u objects", i, count_after_first,
               ctx->_StateCache.count);
   }
   CHECK(blend[0] != blend[1], "two blend states, two objects");

   /* a group that is not dirty keeps its object, even through a
    * validation of other groups */
   const struct r_rast_state *rast = ctx->_Raster.rast;
   const struct r_fs_state *fs = ctx->_Raster.fs;
   glDepthFunc(GL_LEQUAL);
   draw_tri();
   CHECK(ctx->_Raster.rast == rast && ctx->_Raster.fs == fs,
         "a depth change keeps the rasterizer and fragment program objects");
   CHECK(ctx->_Raster.dsa != dsa && ctx->_Raster.dsa->depth_func == R_LEQUAL,
         "a depth change makes a new depth-stencil-alpha object");
   glEnable(GL_FOG);
   draw_tri();
   CHECK(ctx->_Raster.fs != fs && ctx->_Raster.fs->fog_mode != R_FOG_NONE,
         "fog makes a new fragment program object");
   glDisable(GL_FOG);
   draw_tri();
   CHECK(ctx->_Raster.fs == fs, "fog off again: the first fragment program object");

   /* glBitmap's cache keeps its state while many other states come and go */
   static const GLubyte bits[8] = { 0xff, 0x81, 0x81, 0x81, 0x81, 0x81, 0x81, 0xff };
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);   /* rows of one byte */
   glRasterPos2f(0.0f, 0.0f);
   glBitmap(8, 8, 0, 0, 0, 0, bits);
   const struct r_blend_state *bitmap_blend = ctx->BitmapCache.Raster.blend;
   const struct r_blend_state saved = *bitmap_blend;
   CHECK(ctx->BitmapCache.Pending, "the bitmap is cached, not drawn");
   for (int i = 0; i < 3 * R_CSO_CACHE_MAX; i++) {
      /* states that are validated (glRasterPos validates) without a draw,
       * which would flush the bitmap cache */
      glBlendColor((float)i / 1000.0f, 0.0f, 0.0f, 0.0f);
      glRasterPos2f(0.0f, 0.0f);
   }
   CHECK(ctx->_StateCache.count <= R_CSO_CACHE_MAX + 16, "the cache is bounded (%u)",
         ctx->_StateCache.count);
   CHECK(memcmp(bitmap_blend, &saved, sizeof saved) == 0,
         "the bitmap cache's blend object is intact");
   glFinish();
   CHECK(glGetError() == GL_NO_ERROR, "no GL error");
   OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
   OSMesaDestroyContext(osm);
}

int main(void)
{
   test_cache();
   test_gl();
   return check_report("cso");
}
