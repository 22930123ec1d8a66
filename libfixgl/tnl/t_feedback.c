/*
 * The selection and feedback stages: in GL_SELECT and GL_FEEDBACK the
 * state tracker draws with its own draw context whose last stage, instead
 * of rasterization, records primitives (st_cb_feedback.c,
 * st_draw_feedback.c).  That draw context always runs the pipeline (it
 * has no vbuf backend: draw_pt.c PT_PIPELINE), clips exactly against the
 * view volume and the user planes (no guard band), and has no line
 * stipple, wide line/point, aaline, aapoint or pstipple stages
 * (st_draw.c:st_get_draw_context); state.c derives its stage choice.
 * The primitives arrive here after clipping, culling, two-sided colours,
 * polygon offset, flat shading (only with unfilled polygons) and the
 * unfilled stage, with window coordinates in the y-down buffer.
 */
#include "tnl/t_pipeline.h"

#include "context.h"

/* [S: feedback.c:_mesa_update_hitflag] */
void t_update_hitflag(struct fgl_context *ctx, float z)
{
   struct fgl_selection *s = &ctx->Select;
   s->HitFlag = true;
   if (z < s->HitMinZ)
      s->HitMinZ = z;
   if (z > s->HitMaxZ)
      s->HitMaxZ = z;
}

/* [S: st_cb_feedback.c:feedback_vertex, feedback.c:_mesa_feedback_vertex]
 * x; y flipped back to y-up as Height - y (float); z; w = 1 / (1/w); the
 * vertex program's colour output (COL0, which it always writes in
 * GL_FEEDBACK: ffvertex_prog.c make_state_key); its texture coordinate
 * (TEX0). */
static void feedback_vertex(struct fgl_context *ctx, const struct r_vertex *v)
{
   const unsigned mask = ctx->Feedback.Mask;
   const GLuint height = ctx->DrawBuffer ? (GLuint)ctx->DrawBuffer->Height : 0u;

   fgl_feedback_token(ctx, v->pos[0]);
   fgl_feedback_token(ctx, (float)height - v->pos[1]);
   if (mask & FGL_FB_3D)
      fgl_feedback_token(ctx, v->pos[2]);
   if (mask & FGL_FB_4D)
      fgl_feedback_token(ctx, 1.0f / v->pos[3]);
   if (mask & FGL_FB_COLOR)
      for (int c = 0; c < 4; c++)
         fgl_feedback_token(ctx, v->attr[R_ATTR_COLOR0][c]);
   if (mask & FGL_FB_TEXTURE)
      for (int c = 0; c < 4; c++)
         fgl_feedback_token(ctx, v->attr[R_ATTR_TEX0][c]);
}

void t_feedback_tri(struct fgl_context *ctx, const struct r_vertex *v0,
                    const struct r_vertex *v1, const struct r_vertex *v2)
{
   if (ctx->RenderMode == GL_SELECT) {
      /* [S: st_cb_feedback.c:select_tri] */
      t_update_hitflag(ctx, v0->pos[2]);
      t_update_hitflag(ctx, v1->pos[2]);
      t_update_hitflag(ctx, v2->pos[2]);
      return;
   }
   /* [S: st_cb_feedback.c:feedback_tri] every triangle is a polygon of
    * three vertices */
   fgl_feedback_token(ctx, (GLfloat)GL_POLYGON_TOKEN);
   fgl_feedback_token(ctx, 3.0f);
   feedback_vertex(ctx, v0);
   feedback_vertex(ctx, v1);
   feedback_vertex(ctx, v2);
}

void t_feedback_line(struct fgl_context *ctx, const struct r_vertex *v0,
                     const struct r_vertex *v1)
{
   if (ctx->RenderMode == GL_SELECT) {
      /* [S: st_cb_feedback.c:select_line] */
      t_update_hitflag(ctx, v0->pos[2]);
      t_update_hitflag(ctx, v1->pos[2]);
      return;
   }
   /* [S: st_cb_feedback.c:feedback_line] a reset token after the stage's
    * reset_stipple_counter, which only the unfilled stage calls (at a
    * primitive's first triangle): lines drawn as lines never reset it */
   if (ctx->Feedback.ResetStipple) {
      fgl_feedback_token(ctx, (GLfloat)GL_LINE_RESET_TOKEN);
      ctx->Feedback.ResetStipple = false;
   } else {
      fgl_feedback_token(ctx, (GLfloat)GL_LINE_TOKEN);
   }
   feedback_vertex(ctx, v0);
   feedback_vertex(ctx, v1);
}

void t_feedback_point(struct fgl_context *ctx, const struct r_vertex *v)
{
   if (ctx->RenderMode == GL_SELECT) {
      /* [S: st_cb_feedback.c:select_point] */
      t_update_hitflag(ctx, v->pos[2]);
      return;
   }
   /* [S: st_cb_feedback.c:feedback_point] */
   fgl_feedback_token(ctx, (GLfloat)GL_POINT_TOKEN);
   feedback_vertex(ctx, v);
}

void t_feedback_reset_stipple(struct fgl_context *ctx)
{
   /* [S: st_cb_feedback.c:feedback_reset_stipple_counter; the selection
    * stage's is a no-op] */
   if (ctx->RenderMode == GL_FEEDBACK)
      ctx->Feedback.ResetStipple = true;
}
