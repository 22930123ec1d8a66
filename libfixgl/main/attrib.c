/*
 * The attribute stacks.
 *
 * Server: glPushAttrib, glPopAttrib [S: main/attrib.c:_mesa_PushAttrib,
 * _mesa_PopAttrib].  Push copies each group the mask names into the node;
 * pop puts it back in Mesa's order.  Mesa restores most groups through
 * its setters, each of which returns early when the value is unchanged,
 * and only the groups changed since the push (ctx->PopAttribState, see
 * changed_groups, which also loses the changes made under an inner push as
 * Mesa does): here a group whose stored copy differs from the current
 * state is copied back and its dirty bit set, which is the same state,
 * except for the lighting group, whose materials can change without
 * marking it (restore_light).
 * Stored values come back
 * as they were stored: light positions, spot directions and clip planes
 * stay in the eye space of their glLight/glClipPlane call (Mesa copies
 * them), whatever the modelview is at pop time.
 *
 * Client: glPushClientAttrib, glPopClientAttrib
 * [S: main/attrib.c:_mesa_PushClientAttrib, _mesa_PopClientAttrib] for
 * GL_CLIENT_PIXEL_STORE_BIT (ctx->Pack, ctx->Unpack) and
 * GL_CLIENT_VERTEX_ARRAY_BIT (ctx->Array).  Other mask bits are kept in
 * the node and ignored, as Mesa does.
 */
#include <stddef.h>
#include <string.h>

#include "main/groups.h"
#include "main/dlist.h"

/* GL_ENABLE_BIT: the capabilities pop_enable_group restores, in its
 * order [S: main/attrib.c:pop_enable_group].  _mesa_PushAttrib also saves
 * GL_LIGHT0..7 but pop_enable_group never restores them (Mesa 22.3): a
 * light enable comes back only with GL_LIGHTING_BIT.  The texture units'
 * enables follow them (save_enable, restore_enable). */
static const GLenum enable_caps[FGL_ENABLE_ATTRIB_CAPS] = {
   GL_ALPHA_TEST, GL_BLEND,
   GL_CLIP_PLANE0, GL_CLIP_PLANE0 + 1, GL_CLIP_PLANE0 + 2, GL_CLIP_PLANE0 + 3,
   GL_CLIP_PLANE0 + 4, GL_CLIP_PLANE0 + 5, GL_CLIP_PLANE0 + 6, GL_CLIP_PLANE0 + 7,
   GL_COLOR_MATERIAL, GL_CULL_FACE, GL_DEPTH_TEST, GL_DITHER, GL_FOG,
   GL_LIGHTING, GL_LINE_SMOOTH, GL_LINE_STIPPLE, GL_INDEX_LOGIC_OP,
   GL_COLOR_LOGIC_OP,
   GL_MAP1_COLOR_4, GL_MAP1_INDEX, GL_MAP1_NORMAL, GL_MAP1_TEXTURE_COORD_1,
   GL_MAP1_TEXTURE_COORD_2, GL_MAP1_TEXTURE_COORD_3, GL_MAP1_TEXTURE_COORD_4,
   GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_4,
   GL_MAP2_COLOR_4, GL_MAP2_INDEX, GL_MAP2_NORMAL, GL_MAP2_TEXTURE_COORD_1,
   GL_MAP2_TEXTURE_COORD_2, GL_MAP2_TEXTURE_COORD_3, GL_MAP2_TEXTURE_COORD_4,
   GL_MAP2_VERTEX_3, GL_MAP2_VERTEX_4,
   GL_AUTO_NORMAL, GL_NORMALIZE, GL_RESCALE_NORMAL, GL_POINT_SMOOTH,
   GL_POLYGON_OFFSET_POINT, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_FILL,
   GL_POLYGON_SMOOTH, GL_POLYGON_STIPPLE, GL_SCISSOR_TEST, GL_STENCIL_TEST,
   GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE,
   GL_SAMPLE_COVERAGE, GL_POINT_SPRITE,
};

static void save_enable(struct fgl_context *ctx, struct fgl_attrib_node *node)
{
   for (int i = 0; i < FGL_ENABLE_ATTRIB_CAPS; i++) {
      double v = 0.0;
      fgl_is_cap(ctx, enable_caps[i], &v);
      node->Enable[i] = v != 0.0;
   }
   for (int u = 0; u < FGL_MAX_TEXTURE_UNITS; u++) {
      node->TexEnabled[u] = ctx->Texture.Unit[u].Enabled;
      node->TexGenEnabled[u] = ctx->Texture.Unit[u].TexGenEnabled;
   }
}

static bool tex_enables_differ(const struct fgl_context *ctx, const struct fgl_attrib_node *node)
{
   for (int u = 0; u < FGL_MAX_TEXTURE_UNITS; u++)
      if (node->TexEnabled[u] != ctx->Texture.Unit[u].Enabled ||
          node->TexGenEnabled[u] != ctx->Texture.Unit[u].TexGenEnabled)
         return true;
   return false;
}

/* The enables GL_EVAL_BIT (memcpy of Mesa's gl_eval_attrib, which holds
 * them) restores besides GL_ENABLE_BIT; fixgl keeps them with the other
 * capabilities (enable.c).  GL_TEXTURE_BIT's unit enables are copied with
 * the units (ctx->Texture). */
static const GLenum eval_caps[FGL_EVAL_ATTRIB_CAPS] = {
   GL_MAP1_COLOR_4, GL_MAP1_INDEX, GL_MAP1_NORMAL, GL_MAP1_TEXTURE_COORD_1,
   GL_MAP1_TEXTURE_COORD_2, GL_MAP1_TEXTURE_COORD_3, GL_MAP1_TEXTURE_COORD_4,
   GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_4,
   GL_MAP2_COLOR_4, GL_MAP2_INDEX, GL_MAP2_NORMAL, GL_MAP2_TEXTURE_COORD_1,
   GL_MAP2_TEXTURE_COORD_2, GL_MAP2_TEXTURE_COORD_3, GL_MAP2_TEXTURE_COORD_4,
   GL_MAP2_VERTEX_3, GL_MAP2_VERTEX_4, GL_AUTO_NORMAL,
};

static void save_caps(struct fgl_context *ctx, const GLenum *caps, int n, bool *out)
{
   for (int i = 0; i < n; i++) {
      double v = 0.0;
      fgl_is_cap(ctx, caps[i], &v);
      out[i] = v != 0.0;
   }
}

static bool caps_differ(struct fgl_context *ctx, const GLenum *caps, int n, const bool *saved)
{
   bool now[FGL_ENABLE_ATTRIB_CAPS];
   save_caps(ctx, caps, n, now);
   return memcmp(now, saved, (size_t)n * sizeof(bool)) != 0;
}

static void save_eval(struct fgl_context *ctx, struct fgl_attrib_node *node)
{
   save_caps(ctx, eval_caps, FGL_EVAL_ATTRIB_CAPS, node->EvalEnable);
}

static void restore_eval(struct fgl_context *ctx, const struct fgl_attrib_node *node)
{
   for (int i = 0; i < FGL_EVAL_ATTRIB_CAPS; i++)
      fgl_set_enable(ctx, eval_caps[i], node->EvalEnable[i]);
}

static void save_texture(struct fgl_context *ctx, struct fgl_attrib_node *node)
{
   fgl_save_texobjs(ctx, node);
}

/* pop_texture_group: the units (copied by the group's entry), the
 * objects, then _mesa_ActiveTexture(saved unit), which points a
 * GL_TEXTURE matrix mode at that unit's stack. */
static void restore_texture(struct fgl_context *ctx, const struct fgl_attrib_node *node)
{
   fgl_restore_texobjs(ctx, node);
   if (ctx->Transform.MatrixMode == GL_TEXTURE)
      ctx->CurrentStack = fgl_texture_stack(ctx);
}

/* TEST_AND_UPDATE: _mesa_set_enable for each flag that differs, so that
 * re-enabling GL_COLOR_MATERIAL loads the current colour into the
 * tracked materials, as glEnable does. */
static void restore_enable(struct fgl_context *ctx, const struct fgl_attrib_node *node)
{
   for (int i = 0; i < FGL_ENABLE_ATTRIB_CAPS; i++)
      fgl_set_enable(ctx, enable_caps[i], node->Enable[i]);
   /* the texture unit enables, unit by unit (pop_enable_group) */
   for (int u = 0; u < FGL_MAX_TEXTURE_UNITS; u++) {
      struct fgl_texture_unit *t = &ctx->Texture.Unit[u];
      if (t->Enabled != node->TexEnabled[u] || t->TexGenEnabled != node->TexGenEnabled[u]) {
         FGL_FLUSH_VERTICES(ctx, FGL_NEW_TEXTURE);
         t->Enabled = node->TexEnabled[u];
         t->TexGenEnabled = node->TexGenEnabled[u];
      }
   }
}

/* GL_CURRENT_BIT and GL_LIGHTING_BIT take the vertex format's values
 * first (FLUSH_CURRENT). */
static void save_flush_current(struct fgl_context *ctx, struct fgl_attrib_node *node)
{
   (void)node;
   fgl_flush_current(ctx);
}

/* GL_CURRENT_BIT: memcpy to ctx->Current.  The vertex format is not reset
 * (the flush at the top of glPopAttrib draws only when vertices are
 * stored), so an attribute in the format keeps its value for the next
 * vertices while queries see the restored one. */
static void restore_current(struct fgl_context *ctx, const struct fgl_attrib_node *node)
{
   memcpy(ctx->Current.Attrib, node->Current, sizeof(node->Current));
}

/* GL_LIGHTING_BIT.  Mesa skips the group unless it was marked changed
 * since the push (PopAttribState): a glLight*, glLightModel*,
 * glColorMaterial, glShadeModel, lighting enable or material attribute
 * marks it, but the materials that GL_COLOR_MATERIAL makes follow the
 * colour do not, so those keep the tracked colour when nothing else of the
 * group changed.  A restore copies the lights (eye-space positions as
 * stored), the model, the colour material state and the materials; on
 * its way glColorMaterial and glEnable(GL_COLOR_MATERIAL) flush the
 * current values (FLUSH_CURRENT), so a colour still in the vertex format
 * goes into the tracked materials before the copy overwrites them and not
 * at a later flush. */
static void restore_light(struct fgl_context *ctx, const struct fgl_attrib_node *node)
{
   const struct fgl_light_attrib *l = &node->Light;
   /* every setter of the group marks it (FGL_FLUSH_VERTICES with
    * FGL_NEW_LIGHT, t_vbo.c for the materials); a change made under an
    * inner push no longer counts after its pop */
   if (!(ctx->PopAttribState & GL_LIGHTING_BIT))
      return;
   const bool cm_call = (ctx->Light.ColorMaterialFace != l->ColorMaterialFace ||
                         ctx->Light.ColorMaterialMode != l->ColorMaterialMode) &&
                        ctx->Light.ColorMaterialEnabled;
   if (cm_call || ctx->Light.ColorMaterialEnabled != l->ColorMaterialEnabled)
      fgl_flush_current(ctx);
   memcpy(&ctx->Light, l, sizeof(ctx->Light));   /* padding too: changed_groups */
   memcpy(ctx->Current.Attrib[FGL_ATTR_MAT_FIRST], node->Material, sizeof(node->Material));
   ctx->NewState |= FGL_NEW_LIGHT;
}

/* GL_COLOR_BUFFER_BIT: a copy, except the index clear value, which
 * _mesa_PopAttrib restores through glClearIndex((GLfloat)saved) when it
 * differs: a large GLuint comes back through a float (0xfffffffe -> 0) */
static void restore_color(struct fgl_context *ctx, const struct fgl_attrib_node *node)
{
   if (memcmp(&ctx->Color, &node->Color, sizeof(node->Color)) == 0)
      return;
   const bool clear_index = ctx->Color.ClearIndex != node->Color.ClearIndex;
   memcpy(&ctx->Color, &node->Color, sizeof(ctx->Color));   /* padding too: changed_groups */
   if (clear_index)
      ctx->Color.ClearIndex = fgl_clear_index_cast((float)node->Color.ClearIndex);
   ctx->NewState |= FGL_NEW_COLOR;
   fgl_select_color_buffer(ctx);   /* the draw buffer restored */
}

/* GL_FOG_BIT: the setters, _mesa_Fogfv(GL_FOG_COLOR) with the clamped
 * colour: the unclamped colour becomes the clamped one. */
static void restore_fog(struct fgl_context *ctx, const struct fgl_attrib_node *node)
{
   if (memcmp(&ctx->Fog, &node->Fog, sizeof(node->Fog)) == 0)
      return;
   /* _mesa_PopAttrib sets the enable, colour, density, start, end, index
    * and mode only: GL_FOG_COORDINATE_SOURCE, GL_FOG_DISTANCE_MODE_NV and
    * GL_COLOR_SUM (which GL_ENABLE_BIT does not restore either) keep their
    * current values (api/query_walk_popped, gl14/seccolor_attrib) */
   const GLenum source = ctx->Fog.CoordinateSource, distance = ctx->Fog.DistanceMode;
   const bool color_sum = ctx->Fog.ColorSumEnabled;
   memcpy(&ctx->Fog, &node->Fog, sizeof(ctx->Fog));   /* padding too: changed_groups */
   ctx->Fog.CoordinateSource = source;
   ctx->Fog.DistanceMode = distance;
   ctx->Fog.ColorSumEnabled = color_sum;
   memcpy(ctx->Fog.ColorUnclamped, node->Fog.Color, sizeof(node->Fog.Color));
   ctx->NewState |= FGL_NEW_FOG;
}

/* GL_HINT_BIT: _mesa_PopAttrib calls glHint for six targets only;
 * GL_GENERATE_MIPMAP_HINT keeps its current value. */
static void restore_hint(struct fgl_context *ctx, const struct fgl_attrib_node *node)
{
   struct fgl_hint_attrib *h = &ctx->Hint;
   h->PerspectiveCorrection = node->Hint.PerspectiveCorrection;
   h->PointSmooth = node->Hint.PointSmooth;
   h->LineSmooth = node->Hint.LineSmooth;
   h->PolygonSmooth = node->Hint.PolygonSmooth;
   h->Fog = node->Hint.Fog;
   h->TextureCompression = node->Hint.TextureCompression;
   /* fixgl's own GL_PHONG_HINT_WIN comes back too (shading.md) */
   h->PhongWin = node->Hint.PhongWin;
}

/* GL_TRANSFORM_BIT: glMatrixMode selects the stack; planes and enables are
 * copied (no re-transformation by the current modelview). */
static void restore_transform(struct fgl_context *ctx, const struct fgl_attrib_node *node)
{
   if (memcmp(&ctx->Transform, &node->Transform, sizeof(node->Transform)) == 0)
      return;
   memcpy(&ctx->Transform, &node->Transform, sizeof(ctx->Transform));   /* padding too */
   ctx->CurrentStack = fgl_matrix_stack_for_mode(ctx, ctx->Transform.MatrixMode);
   ctx->NewState |= FGL_NEW_CLIP;
}

/* A part that an earlier entry's hook restores */
static void restore_nothing(struct fgl_context *ctx, const struct fgl_attrib_node *node)
{
   (void)ctx;
   (void)node;
}

/* One group (or part of one) that a mask bit saves: ctx_offset/size bytes
 * of the context copied to node_offset of the node, or the hooks. */
struct attrib_group {
   GLbitfield bit;
   size_t ctx_offset, node_offset, size;
   unsigned dirty;          /* FGL_NEW_* set when the group changes on pop */
   void (*save)(struct fgl_context *ctx, struct fgl_attrib_node *node);     /* before the copy */
   void (*restore)(struct fgl_context *ctx, const struct fgl_attrib_node *node); /* instead of the copy */
};

#define GROUP(bit, ctxmember, nodemember, dirty, save, restore)                 \
   { bit, offsetof(struct fgl_context, ctxmember),                              \
     offsetof(struct fgl_attrib_node, nodemember),                              \
     sizeof(((struct fgl_attrib_node *)0)->nodemember), dirty, save, restore }

/* A group kept by its hooks alone (size 0: nothing copied) */
#define HOOKS(bit, save, restore) { bit, 0, 0, 0, 0, save, restore }

/* In _mesa_PopAttrib's order (the enable group's GL_COLOR_MATERIAL before
 * the lighting group's materials).  The raster position is in
 * Current.RasterPos and after. */
static const struct attrib_group groups[] = {
   /* copied back as Mesa does (_mesa_ClearAccum of the stored value,
    * memcpy of Eval and Pixel then _mesa_ReadBuffer, the texture bindings
    * and active unit) */
   GROUP(GL_ACCUM_BUFFER_BIT, Accum, Accum, 0, NULL, NULL),
   GROUP(GL_COLOR_BUFFER_BIT, Color, Color, FGL_NEW_COLOR, NULL, restore_color),
   GROUP(GL_CURRENT_BIT, Current.Attrib, Current, 0, save_flush_current, restore_current),
   /* the current values outside the vbo (raster position...) */
   GROUP(GL_CURRENT_BIT, Current.RasterPos, CurrentExtra, 0, NULL, NULL),
   GROUP(GL_DEPTH_BUFFER_BIT, Depth, Depth, FGL_NEW_DEPTH, NULL, NULL),
   HOOKS(GL_ENABLE_BIT, save_enable, restore_enable),
   GROUP(GL_EVAL_BIT, Eval, Eval, 0, NULL, NULL),
   HOOKS(GL_EVAL_BIT, save_eval, restore_eval),
   GROUP(GL_FOG_BIT, Fog, Fog, FGL_NEW_FOG, NULL, restore_fog),
   GROUP(GL_HINT_BIT, Hint, Hint, 0, NULL, restore_hint),
   GROUP(GL_LIGHTING_BIT, Light, Light, FGL_NEW_LIGHT, save_flush_current, restore_light),
   GROUP(GL_LIGHTING_BIT, Current.Attrib[FGL_ATTR_MAT_FIRST], Material, 0, NULL, restore_nothing),
   GROUP(GL_LINE_BIT, Line, Line, FGL_NEW_LINE, NULL, NULL),
   GROUP(GL_LIST_BIT, List, List, 0, NULL, NULL),
   GROUP(GL_PIXEL_MODE_BIT, Pixel, Pixel, FGL_NEW_PIXEL, NULL, NULL),
   GROUP(GL_POINT_BIT, Point, Point, FGL_NEW_POINT, NULL, NULL),
   GROUP(GL_POLYGON_BIT, Polygon, Polygon, FGL_NEW_POLYGON, NULL, NULL),
   GROUP(GL_POLYGON_STIPPLE_BIT, PolygonStipple, PolygonStipple, FGL_NEW_POLYGON, NULL, NULL),
   GROUP(GL_SCISSOR_BIT, Scissor, Scissor, FGL_NEW_SCISSOR, NULL, NULL),
   GROUP(GL_STENCIL_BUFFER_BIT, Stencil, Stencil, FGL_NEW_STENCIL, NULL, NULL),
   GROUP(GL_TRANSFORM_BIT, Transform, Transform, FGL_NEW_CLIP, NULL, restore_transform),
   GROUP(GL_TEXTURE_BIT, Texture, Texture, FGL_NEW_TEXTURE, NULL, NULL),
   HOOKS(GL_TEXTURE_BIT, save_texture, restore_texture),
   GROUP(GL_VIEWPORT_BIT, Viewport, Viewport, FGL_NEW_VIEWPORT, NULL, NULL),
   /* stored and queried only (no multisample buffer) */
   GROUP(GL_MULTISAMPLE_BIT, Multisample, Multisample, 0, NULL, NULL),
};

#define POP_FLUSH_ON_CHANGE (GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_HINT_BIT |   \
                             GL_LIGHTING_BIT | GL_POINT_BIT | GL_LINE_BIT | GL_POLYGON_BIT | \
                             GL_SCISSOR_BIT | GL_STENCIL_BUFFER_BIT | GL_FOG_BIT |      \
                             GL_MULTISAMPLE_BIT)
#define POP_FLUSH_ALWAYS GL_PIXEL_MODE_BIT

/* Whether Mesa restores group g through a setter that flushes: some value
 * other than those its pop sets without FLUSH_VERTICES (glClearColor,
 * glClearIndex, glClearDepth, glClearStencil, and the draw buffer, which
 * _mesa_drawbuffers sets directly) differs. */
static bool restore_flushes(const struct fgl_context *ctx, const struct fgl_attrib_node *node,
                            const struct attrib_group *g)
{
   if (g->bit == GL_COLOR_BUFFER_BIT) {
      /* (memcpy, not assignment: the padding bytes take part in memcmp) */
      struct fgl_colorbuffer_attrib a, b;
      memcpy(&a, &ctx->Color, sizeof(a));
      memcpy(&b, &node->Color, sizeof(b));
      memcpy(a.ClearColor, b.ClearColor, sizeof(a.ClearColor));
      a.ClearIndex = b.ClearIndex;
      a.DrawBuffer = b.DrawBuffer;
      return memcmp(&a, &b, sizeof(a)) != 0;
   }
   if (g->bit == GL_DEPTH_BUFFER_BIT) {
      struct fgl_depth_attrib a, b;
      memcpy(&a, &ctx->Depth, sizeof(a));
      memcpy(&b, &node->Depth, sizeof(b));
      a.Clear = b.Clear;
      return memcmp(&a, &b, sizeof(a)) != 0;
   }
   if (g->bit == GL_STENCIL_BUFFER_BIT) {
      struct fgl_stencil_attrib a, b;
      memcpy(&a, &ctx->Stencil, sizeof(a));
      memcpy(&b, &node->Stencil, sizeof(b));
      a.Clear = b.Clear;
      return memcmp(&a, &b, sizeof(a)) != 0;
   }
   return memcmp((const char *)ctx + g->ctx_offset, (const char *)node + g->node_offset,
                 g->size) != 0;
}

/* Copies the groups of mask into node (the save hooks first). */
static void save_groups(struct fgl_context *ctx, struct fgl_attrib_node *node, GLbitfield mask)
{
   for (size_t i = 0; i < sizeof(groups) / sizeof(groups[0]); i++) {
      const struct attrib_group *g = &groups[i];
      if (!(mask & g->bit))
         continue;
      if (g->save)
         g->save(ctx, node);
      if (g->size)
         memcpy((char *)node + g->node_offset, (const char *)ctx + g->ctx_offset, g->size);
   }
}

/* Mesa's ctx->PopAttribState: the groups changed since the last push,
 * reset to the outer level's value by each pop, so that an outer pop skips
 * the groups changed only while an inner push was active
 * [S: main/attrib.c:_mesa_PushAttrib, _mesa_PopAttrib; every setter's
 * FLUSH_VERTICES(ctx, new_state, pop_attrib_mask)].  GL_CURRENT_BIT and
 * GL_LIGHTING_BIT are marked where Mesa marks them (t_vbo.c,
 * FGL_FLUSH_VERTICES) and restored by their hooks; the other groups count
 * as changed when they differ from ctx->PopAttribBaseline, their copy at
 * the last push or pop.  (A value changed and set back is not counted:
 * restoring it would change nothing.) */
#define DIFF_TRACKED (~(GLbitfield)(GL_CURRENT_BIT | GL_LIGHTING_BIT))

static GLbitfield changed_groups(struct fgl_context *ctx)
{
   const struct fgl_attrib_node *base = &ctx->PopAttribBaseline;
   GLbitfield changed = 0;
   for (size_t i = 0; i < sizeof(groups) / sizeof(groups[0]); i++) {
      const struct attrib_group *g = &groups[i];
      if (!(g->bit & DIFF_TRACKED) || (changed & g->bit))
         continue;
      if (g->size) {
         if (memcmp((const char *)ctx + g->ctx_offset, (const char *)base + g->node_offset,
                    g->size) != 0)
            changed |= g->bit;
      } else if (g->bit == GL_ENABLE_BIT) {
         if (caps_differ(ctx, enable_caps, FGL_ENABLE_ATTRIB_CAPS, base->Enable) ||
             tex_enables_differ(ctx, base))
            changed |= g->bit;
      } else if (g->bit == GL_EVAL_BIT) {
         if (caps_differ(ctx, eval_caps, FGL_EVAL_ATTRIB_CAPS, base->EvalEnable))
            changed |= g->bit;
      }
   }
   return changed;
}

void GLAPIENTRY glPushAttrib(GLbitfield mask)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, PushAttrib, mask);
   /* not in the oracle's glBegin/glEnd dispatch table (generic_nop) */
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (ctx->AttribStackDepth >= FGL_MAX_ATTRIB_STACK_DEPTH) {
      fgl_error(ctx, GL_STACK_OVERFLOW);
      return;
   }
   struct fgl_attrib_node *node = &ctx->AttribStack[ctx->AttribStackDepth];
   node->Mask = mask;
   node->OldPopAttribState = ctx->PopAttribState | changed_groups(ctx);
   save_groups(ctx, node, mask);
   ctx->AttribStackDepth++;
   ctx->PopAttribState = 0;
   save_groups(ctx, &ctx->PopAttribBaseline, DIFF_TRACKED);
}

void GLAPIENTRY glPopAttrib(void)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE0(ctx, PopAttrib);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* FLUSH_VERTICES comes before the underflow check */
   fgl_flush_vertices(ctx);
   if (ctx->AttribStackDepth == 0) {
      fgl_error(ctx, GL_STACK_UNDERFLOW);
      return;
   }
   ctx->AttribStackDepth--;
   const struct fgl_attrib_node *node = &ctx->AttribStack[ctx->AttribStackDepth];
   /* FLUSH_CURRENT before anything is restored */
   if (node->Mask & GL_CURRENT_BIT)
      fgl_flush_current(ctx);
   /* _mesa_PopAttrib: mask &= ctx->PopAttribState, after the FLUSH_CURRENT
    * above (restore_light tests its bit itself) */
   const GLbitfield changed = ctx->PopAttribState | changed_groups(ctx) | GL_LIGHTING_BIT;
   for (size_t i = 0; i < sizeof(groups) / sizeof(groups[0]); i++) {
      const struct attrib_group *g = &groups[i];
      if (!(node->Mask & g->bit & changed))
         continue;
      /* Mesa restores these groups through setters whose FLUSH_VERTICES
       * (when the value changes; glReadBuffer's always) draws what is
       * batched and copies a vertex format left by an earlier
       * glPopAttrib(GL_CURRENT_BIT) into the current values, after this
       * pop restored them (probed group by group; GL_ENABLE_BIT flushes
       * through fgl_set_enable) */
      if ((g->bit & POP_FLUSH_ALWAYS) ||
          ((g->bit & POP_FLUSH_ON_CHANGE) && g->size && restore_flushes(ctx, node, g)))
         fgl_flush_vertices(ctx);
      if (g->restore) {
         g->restore(ctx, node);
         continue;
      }
      char *dst = (char *)ctx + g->ctx_offset;
      const char *src = (const char *)node + g->node_offset;
      if (memcmp(dst, src, g->size) != 0) {
         memcpy(dst, src, g->size);
         ctx->NewState |= g->dirty;
      }
   }
   ctx->PopAttribState = node->OldPopAttribState;
   save_groups(ctx, &ctx->PopAttribBaseline, DIFF_TRACKED);
}

void GLAPIENTRY glPushClientAttrib(GLbitfield mask)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   /* not in the oracle's glBegin/glEnd dispatch table (generic_nop) */
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   if (ctx->ClientAttribStackDepth >= FGL_MAX_CLIENT_ATTRIB_STACK_DEPTH) {
      fgl_error(ctx, GL_STACK_OVERFLOW);
      return;
   }
   struct fgl_client_attrib_node *head = &ctx->ClientAttribStack[ctx->ClientAttribStackDepth];
   head->Mask = mask;
   if (mask & GL_CLIENT_PIXEL_STORE_BIT) {
      head->Pack = ctx->Pack;
      head->Unpack = ctx->Unpack;
   }
   if (mask & GL_CLIENT_VERTEX_ARRAY_BIT) {
      /* [S: attrib.c:save_array_attrib] the arrays with their buffers,
       * and the GL_ARRAY_BUFFER and GL_ELEMENT_ARRAY_BUFFER bindings,
       * referenced */
      head->Array = ctx->Array;
      fgl_buffer_hold_array(ctx, &head->Array);
   }
   ctx->ClientAttribStackDepth++;
}

void GLAPIENTRY glPopClientAttrib(void)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   if (ctx->ClientAttribStackDepth == 0) {
      fgl_error(ctx, GL_STACK_UNDERFLOW);
      return;
   }
   ctx->ClientAttribStackDepth--;
   struct fgl_client_attrib_node *head = &ctx->ClientAttribStack[ctx->ClientAttribStackDepth];
   /* pixel store and arrays are read when used: no flush */
   if (head->Mask & GL_CLIENT_PIXEL_STORE_BIT) {
      ctx->Pack = head->Pack;
      ctx->Unpack = head->Unpack;
   }
   if (head->Mask & GL_CLIENT_VERTEX_ARRAY_BIT) {
      /* [S: attrib.c:restore_array_attrib] the arrays come back with the
       * buffers they had (the node's references move to the context),
       * then both targets are bound again by the saved names: a name
       * deleted since gets a new, empty buffer */
      fgl_buffer_release_array(ctx, &ctx->Array);
      ctx->Array = head->Array;
      const GLuint array_name = ctx->Array.ArrayBufferObj ? ctx->Array.ArrayBufferObj->Name : 0;
      const GLuint elt_name = ctx->Array.ElementBufferObj ? ctx->Array.ElementBufferObj->Name : 0;
      fgl_bind_buffer_name(ctx, GL_ARRAY_BUFFER, array_name);
      fgl_bind_buffer_name(ctx, GL_ELEMENT_ARRAY_BUFFER, elt_name);
      memset(&head->Array, 0, sizeof(head->Array));
   }
}
