/* p_vbo_frames.c - the oracle's immediate-mode vertex buffer runs on
 * across glFinish and frames (ORACLE-NOTES.md "Immediate mode: the vertex
 * buffer across frames"): a frame's picture depends on every vertex the
 * context received before it.  Each frame here is glClear, 954 points
 * outside the viewport, a stippled GL_LINE_STRIP of 16 segments of 4
 * pixels (pattern 0x00ff, factor 1) and glFinish, every vertex
 * glColor3f + glVertex2f (5 floats, 20 bytes).  Model (vbo_exec): the
 * 512 KiB buffer holds max = (524288 - used) / 20 - 1 vertices; storing
 * the max-th wraps it (the stored draw, the strip's last vertex copied to
 * a new buffer, used = 0, the strip goes on as a new draw whose stipple
 * counter restarts); glFinish adds the batch's bytes to used and starts a
 * new buffer when 1 KiB or less is left.  60 frames: each frame's row of
 * the strip must equal the first frame's exactly when the model puts no
 * wrap inside the strip (after its vertex 0, before its last); here the
 * buffer wraps twice, in the strip both times (frames 26 and 53).  (Which
 * phase the restarted pattern has is not modelled: the conformance cases
 * compare that, raster/lines_wrapped_vertex_buffer.) */
#include "probe.h"

#include <stdbool.h>

#define POINTS 954
#define STRIP 17
#define VSIZE 20u
#define BUFFER 524288u

static void frame(void)
{
   glClear(GL_COLOR_BUFFER_BIT);
   glBegin(GL_POINTS);
   for (int i = 0; i < POINTS; i++) {
      glColor3f(1.0f, 0.0f, 0.0f);
      glVertex2f(-10.0f, -10.0f);
   }
   glEnd();
   glBegin(GL_LINE_STRIP);
   for (int i = 0; i < STRIP; i++) {
      glColor3f(1.0f, 1.0f, 1.0f);
      glVertex2f(0.5f + 4.0f * (float)i, 4.5f);
   }
   glEnd();
   glFinish();
}

int main(void)
{
   probe_init_ub(72, 8);
   glEnable(GL_LINE_STIPPLE);
   glLineStipple(1, 0x00ff);
   unsigned char first[72 * 4];
   unsigned used = 0;
   int restarts = 0;
   for (int k = 0; k < 60; k++) {
      /* the model */
      const unsigned max = (BUFFER - used) / VSIZE - 1, n = POINTS + STRIP;
      bool visible = false;
      if (n >= max) {
         /* wrapped after storing vertex max - 1 */
         const int j = (int)max - 1 - POINTS;   /* the strip's vertex it restarts at */
         visible = j >= 1 && j <= STRIP - 2;
         used = (n - max + (j >= 0 ? 1u : 0u)) * VSIZE;
      } else {
         used += n * VSIZE;
      }
      if (!(BUFFER > used + 1024))
         used = 0;
      restarts += visible;
      /* the oracle */
      frame();
      const unsigned char *row = px(0, 4);
      if (k == 0) {
         memcpy(first, row, sizeof first);
         continue;
      }
      char what[96];
      snprintf(what, sizeof what, "frame %d is the first frame's image (0: a restart is predicted)", k);
      probe_expect(what, memcmp(row, first, sizeof first) == 0, !visible);
   }
   probe_expect("frames with a restart predicted", restarts, 2);
   return probe_result();
}
