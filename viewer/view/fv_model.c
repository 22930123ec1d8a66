/*
 * Model loading through assimp's C API (fv_model.h), textures through
 * OpenImageIO (fv_image.h).
 */
#include <assimp/cimport.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "fv_image.h"
#include "fv_model.h"

/* The material of a file without materials (PLY, STL): assimp's default
 * one is a plain grey; the viewer shows a warm plastic instead. */
static const struct fv_material default_material = {
   .ambient = { 0.2f, 0.2f, 0.2f, 1.0f },
   .diffuse = { 0.8f, 0.55f, 0.25f, 1.0f },
   .specular = { 0.6f, 0.6f, 0.6f, 1.0f },
   .emission = { 0.0f, 0.0f, 0.0f, 1.0f },
   .shininess = 40.0f,
   .lit = 1,
};

/* key, type, index: an AI_MATKEY_COLOR_* triple */
static void get_color(const struct aiMaterial *am, const char *key, unsigned type, unsigned index,
                      float out[4])
{
   struct aiColor4D c;
   if (aiGetMaterialColor(am, key, type, index, &c) == aiReturn_SUCCESS) {
      out[0] = c.r, out[1] = c.g, out[2] = c.b;
   }
   out[3] = 1.0f;
}

/* MTL onto glMaterial: Ka -> GL_AMBIENT, Kd -> GL_DIFFUSE (alpha: d),
 * Ks -> GL_SPECULAR, Ke -> GL_EMISSION, Ns -> GL_SHININESS (clamped to
 * GL's 128; MTL goes to 1000); illum 0 (colour on, ambient off): Kd
 * unlit; illum 1 (colour, ambient, no highlight): no specular; illum 2
 * and above: everything. */
static void convert_material(const struct aiMaterial *am, struct fv_material *m)
{
   /* assimp's stand-in when the file has no material: unnamed (PLY) or
    * AI_DEFAULT_MATERIAL_NAME (STL, OBJ without MTL) */
   struct aiString name;
   if (aiGetMaterialString(am, AI_MATKEY_NAME, &name) != aiReturn_SUCCESS ||
       !strcmp(name.data, AI_DEFAULT_MATERIAL_NAME)) {
      *m = default_material;
      return;
   }
   memset(m, 0, sizeof *m);
   get_color(am, AI_MATKEY_COLOR_AMBIENT, m->ambient);
   get_color(am, AI_MATKEY_COLOR_DIFFUSE, m->diffuse);
   get_color(am, AI_MATKEY_COLOR_SPECULAR, m->specular);
   get_color(am, AI_MATKEY_COLOR_EMISSIVE, m->emission);
   float f;
   unsigned one = 1;
   if (aiGetMaterialFloatArray(am, AI_MATKEY_SHININESS, &f, &one) == aiReturn_SUCCESS)
      m->shininess = f < 0.0f ? 0.0f : f > 128.0f ? 128.0f : f;
   one = 1;
   if (aiGetMaterialFloatArray(am, AI_MATKEY_OPACITY, &f, &one) == aiReturn_SUCCESS)
      m->diffuse[3] = f < 0.0f ? 0.0f : f > 1.0f ? 1.0f : f;
   int illum = 2;
   one = 1;
   /* the MTL's own illum ("$mat.illum", assimp's AI_MATKEY_OBJ_ILLUM) */
   if (aiGetMaterialIntegerArray(am, "$mat.illum", 0, 0, &illum, &one) != aiReturn_SUCCESS) {
      int sm;
      one = 1;
      if (aiGetMaterialIntegerArray(am, AI_MATKEY_SHADING_MODEL, &sm, &one) == aiReturn_SUCCESS &&
          sm == aiShadingMode_NoShading)
         illum = 0;
   }
   m->lit = illum != 0;
   if (illum == 1)
      m->specular[0] = m->specular[1] = m->specular[2] = 0.0f;
}

/* ---- textures ------------------------------------------------------------ */

/* The directory MTL texture names are relative to: the .mtl's own, which
 * is the OBJ's "mtllib" relative to the OBJ (the model's directory for
 * other formats, or when the OBJ names no library).  Returns a malloc'd
 * string ending in '/', or "" for the current directory. */
static char *texture_dir(const char *path)
{
   const char *slash = strrchr(path, '/');
   size_t n = slash ? (size_t)(slash - path + 1) : 0;
   char lib[4096] = "";
   const char *dot = strrchr(path, '.');
   FILE *f = dot && !strcasecmp(dot, ".obj") ? fopen(path, "r") : NULL;
   char line[4096];
   while (f && fgets(line, sizeof line, f)) {
      if (!strncmp(line, "mtllib", 6) && (line[6] == ' ' || line[6] == '\t')) {
         if (sscanf(line + 6, " %4095[^\r\n]", lib) != 1)
            lib[0] = '\0';
         break;
      }
   }
   if (f)
      fclose(f);
   const char *lslash = strrchr(lib, '/');
   size_t ln = lib[0] == '/' ? 0 : n;   /* an absolute mtllib */
   size_t ld = lslash ? (size_t)(lslash - lib + 1) : 0;
   char *dir = malloc(ln + ld + 1);
   if (!dir)
      return NULL;
   memcpy(dir, path, ln);
   memcpy(dir + ln, lib, ld);
   dir[ln + ld] = '\0';
   return dir;
}

/* The material's texture file of a type, joined to dir; NULL when none. */
static char *texture_path(const struct aiMaterial *am, enum aiTextureType type, const char *dir)
{
   struct aiString s;
   if (aiGetMaterialTextureCount(am, type) == 0 ||
       aiGetMaterialTexture(am, type, 0, &s, NULL, NULL, NULL, NULL, NULL, NULL) != aiReturn_SUCCESS ||
       !s.length)
      return NULL;
   size_t dn = s.data[0] == '/' ? 0 : strlen(dir);
   char *p = malloc(dn + s.length + 1);
   if (!p)
      return NULL;
   memcpy(p, dir, dn);
   memcpy(p + dn, s.data, s.length + 1);
   /* an MTL written on Windows separates directories with backslashes */
   for (char *c = p + dn; *c; c++)
      if (*c == '\\')
         *c = '/';
   return p;
}

static void texture_warning(const char *model, const char *file, const char *why)
{
   fprintf(stderr, "fixgl-view: warning: %s: texture %s: %s; drawn untextured\n", model, file,
           why);
}

/* The texture of map_Kd (or map_Ka) and map_d, loaded once per pair:
 * its index in m->textures, or -1 (no map, or a map that cannot be read:
 * a warning). */
static int material_texture(struct fv_model *m, const char *model, const struct aiMaterial *am,
                            const char *dir)
{
   char *kd = texture_path(am, aiTextureType_DIFFUSE, dir);
   if (!kd)
      kd = texture_path(am, aiTextureType_AMBIENT, dir);
   char *d = texture_path(am, aiTextureType_OPACITY, dir);
   if (!kd && !d)
      return -1;
   for (int i = 0; i < m->num_textures; i++) {
      const struct fv_texture *t = &m->textures[i];
      if (!strcmp(t->kd ? t->kd : "", kd ? kd : "") && !strcmp(t->d ? t->d : "", d ? d : "")) {
         free(kd), free(d);
         return i;
      }
   }
   struct fv_image ci = { 0 }, ai = { 0 };
   char why[512];
   int ok = 1;
   if (kd && fv_image_read(kd, &ci, why, sizeof why) != 0) {
      texture_warning(model, kd, why);
      ok = 0;
   }
   if (ok && d && fv_image_read(d, &ai, why, sizeof why) != 0) {
      texture_warning(model, d, why);
      ok = 0;
   }
   if (ok && kd && d && (ci.w != ai.w || ci.h != ai.h)) {
      snprintf(why, sizeof why, "map_d is %dx%d, map_Kd %dx%d", ai.w, ai.h, ci.w, ci.h);
      texture_warning(model, d, why);
      ok = 0;
   }
   struct fv_texture *grown = ok ? realloc(m->textures, (size_t)(m->num_textures + 1) * sizeof *grown)
                                 : NULL;
   if (!grown) {
      fv_image_free(&ci), fv_image_free(&ai);
      free(kd), free(d);
      return -1;
   }
   m->textures = grown;
   struct fv_texture *t = &m->textures[m->num_textures];
   memset(t, 0, sizeof *t);
   if (kd) {
      t->w = ci.w, t->h = ci.h, t->rgba = ci.rgba;
   } else {
      /* map_d alone: white, its alpha */
      t->w = ai.w, t->h = ai.h, t->rgba = malloc((size_t)ai.w * ai.h * 4);
      if (t->rgba)
         memset(t->rgba, 255, (size_t)ai.w * ai.h * 4);
   }
   if (!t->rgba) {
      fv_image_free(&ci), fv_image_free(&ai);
      free(kd), free(d);
      return -1;
   }
   const size_t n = (size_t)t->w * t->h;
   if (d) {
      /* map_d is a scalar map: its alpha channel when it has one */
      const int a = ai.channels == 2 || ai.channels == 4 ? 3 : 0;
      for (size_t i = 0; i < n; i++)
         t->rgba[i * 4 + 3] = ai.rgba[i * 4 + a];
      fv_image_free(&ai);
   }
   for (size_t i = 0; i < n && !t->translucent; i++)
      t->translucent = t->rgba[i * 4 + 3] < 255;
   t->kd = kd, t->d = d;
   return m->num_textures++;
}

/* ---- loading ---------------------------------------------------------------- */

/* What the file holds before any post-processing, which would hide what
 * is wrong with it (assimp's vertex joining merges a NaN vertex into a
 * neighbour, and a model without faces ends as "No output meshes: all
 * meshes are orphaned ..."): a model without faces, or with points and
 * lines only, is empty; a vertex with a NaN or infinite coordinate is
 * counted (once per position) and the first few named with the face that
 * uses them.  Returns 0, or -1 with the message on stderr. */
static int check_raw(const struct aiScene *raw, const char *path)
{
   enum { SHOWN = 4 };
   unsigned long verts = 0, faces = 0, tris = 0, bad = 0;
   float *seen = NULL;
   size_t cap = 0;
   char where[SHOWN][160];
   for (unsigned i = 0; i < raw->mNumMeshes; i++) {
      const struct aiMesh *am = raw->mMeshes[i];
      verts += am->mNumVertices;
      faces += am->mNumFaces;
      if (am->mPrimitiveTypes & (aiPrimitiveType_TRIANGLE | aiPrimitiveType_POLYGON))
         tris += am->mNumFaces;
      for (unsigned v = 0; v < am->mNumVertices; v++) {
         const float p[3] = { am->mVertices[v].x, am->mVertices[v].y, am->mVertices[v].z };
         if (isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]))
            continue;
         int dup = 0;
         for (unsigned long k = 0; k < bad && !dup; k++)
            dup = !memcmp(&seen[k * 3], p, sizeof p);
         if (dup)
            continue;
         if (bad == cap) {
            cap = cap ? cap * 2 : 16;
            float *g = realloc(seen, cap * 3 * sizeof(float));
            if (!g) {
               free(seen);
               fprintf(stderr, "fixgl-view: out of memory loading %s\n", path);
               return -1;
            }
            seen = g;
         }
         memcpy(&seen[bad * 3], p, sizeof p);
         if (bad < SHOWN) {
            /* the first face that uses it (1-based, in the mesh's order) */
            unsigned face = 0;
            for (unsigned t = 0; t < am->mNumFaces && !face; t++)
               for (unsigned c = 0; c < am->mFaces[t].mNumIndices && !face; c++)
                  if (am->mFaces[t].mIndices[c] == v)
                     face = t + 1;
            char pos[96];
            snprintf(pos, sizeof pos, "(%g, %g, %g)", p[0], p[1], p[2]);
            if (face)
               snprintf(where[bad], sizeof where[bad], "%s in face %u of mesh %u", pos, face, i);
            else
               snprintf(where[bad], sizeof where[bad], "%s, vertex %u of mesh %u (in no face)", pos,
                        v, i);
         }
         bad++;
      }
   }
   free(seen);
   if (faces == 0) {
      fprintf(stderr, "fixgl-view: the model %s is empty: %lu vertices and no faces\n", path, verts);
      return -1;
   }
   if (tris == 0) {
      fprintf(stderr, "fixgl-view: the model %s is empty: %lu vertices, %lu points and lines, "
                      "no triangles or polygons\n", path, verts, faces);
      return -1;
   }
   if (bad) {
      fprintf(stderr, "fixgl-view: the model %s has %lu %s with NaN or infinite coordinates:", path,
              bad, bad == 1 ? "vertex" : "vertices");
      for (unsigned long k = 0; k < bad && k < SHOWN; k++)
         fprintf(stderr, "%s %s", k ? ";" : "", where[k]);
      fprintf(stderr, "%s\n", bad > SHOWN ? "; ..." : "");
      return -1;
   }
   return 0;
}

/* --normals flat: every triangle gets vertices of its own with its face's
 * normal (the cross product of its edges, normalised in double). */
static int make_flat(struct fv_mesh *me)
{
   const unsigned n = me->num_idx;
   float *pos = malloc((size_t)n * 3 * sizeof(float)), *nrm = malloc((size_t)n * 3 * sizeof(float));
   float *uv = me->uv ? malloc((size_t)n * 2 * sizeof(float)) : NULL;
   float *col = me->col ? malloc((size_t)n * 4 * sizeof(float)) : NULL;
   unsigned *idx = malloc((size_t)n * sizeof(unsigned));
   if (!pos || !nrm || !idx || (me->uv && !uv) || (me->col && !col)) {
      free(pos), free(nrm), free(uv), free(col), free(idx);
      return -1;
   }
   for (unsigned t = 0; t < n; t += 3) {
      const float *p[3];
      for (int c = 0; c < 3; c++)
         p[c] = &me->pos[me->idx[t + c] * 3];
      double e1[3], e2[3];
      for (int k = 0; k < 3; k++)
         e1[k] = (double)p[1][k] - p[0][k], e2[k] = (double)p[2][k] - p[0][k];
      double f[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                      e1[0] * e2[1] - e1[1] * e2[0] };
      double l = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
      if (!(l > 0.0 && isfinite(l)))
         f[0] = f[1] = 0.0, f[2] = 1.0, l = 1.0;
      for (int c = 0; c < 3; c++) {
         const unsigned src = me->idx[t + c], dst = t + (unsigned)c;
         for (int k = 0; k < 3; k++) {
            pos[dst * 3 + k] = me->pos[src * 3 + k];
            nrm[dst * 3 + k] = (float)(f[k] / l);
         }
         if (uv)
            memcpy(&uv[dst * 2], &me->uv[src * 2], 2 * sizeof(float));
         if (col)
            memcpy(&col[dst * 4], &me->col[src * 4], 4 * sizeof(float));
         idx[dst] = dst;
      }
   }
   free(me->pos), free(me->nrm), free(me->uv), free(me->col), free(me->idx);
   me->pos = pos, me->nrm = nrm, me->uv = uv, me->col = col, me->idx = idx;
   me->num_verts = n;
   return 0;
}

int fv_model_load(struct fv_model *m, const char *path, enum fv_normals normals)
{
   memset(m, 0, sizeof *m);
   FILE *f = fopen(path, "rb");
   if (!f) {
      fprintf(stderr, "fixgl-view: cannot open the model %s: ", path);
      perror(NULL);
      return -1;
   }
   fclose(f);

   unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                    aiProcess_GenSmoothNormals | aiProcess_PreTransformVertices |
                    aiProcess_SortByPType;
   /* STL stores one normal per facet: the normals are generated smooth
    * (across edges up to 80 degrees) as for a file without normals.
    * --normals smooth: generated for every file, averaged across every
    * edge (assimp's largest angle, 175 degrees). */
   const char *dot = strrchr(path, '.');
   float max_angle = 80.0f;
   if ((dot && !strcasecmp(dot, ".stl")) || normals == FV_NORMALS_SMOOTH)
      flags |= aiProcess_ForceGenNormals;
   if (normals == FV_NORMALS_SMOOTH)
      max_angle = 175.0f;
   struct aiPropertyStore *props = aiCreatePropertyStore();
   aiSetImportPropertyFloat(props, AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, max_angle);
   aiSetImportPropertyInteger(props, AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
   /* read as the file is, checked, then post-processed */
   const struct aiScene *sc = aiImportFileExWithProperties(path, 0, NULL, props);
   aiReleasePropertyStore(props);
   if (!sc) {
      fprintf(stderr, "fixgl-view: cannot load the model %s: %s\n", path, aiGetErrorString());
      return -1;
   }
   if (sc->mNumMeshes == 0) {
      fprintf(stderr, "fixgl-view: cannot load the model %s: no meshes in it\n", path);
      aiReleaseImport(sc);
      return -1;
   }
   if (check_raw(sc, path) != 0) {
      aiReleaseImport(sc);
      return -1;
   }
   sc = aiApplyPostProcessing(sc, flags);   /* releases the scene when it fails */
   if (!sc) {
      fprintf(stderr, "fixgl-view: cannot load the model %s: %s\n", path, aiGetErrorString());
      return -1;
   }

   char *tex_dir = texture_dir(path);
   m->meshes = calloc(sc->mNumMeshes ? sc->mNumMeshes : 1, sizeof *m->meshes);
   int oom = !m->meshes || !tex_dir;
   for (unsigned i = 0; !oom && i < sc->mNumMeshes; i++) {
      const struct aiMesh *am = sc->mMeshes[i];
      if (!(am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) || !am->mNormals)
         continue;
      struct fv_mesh *me = &m->meshes[m->num_meshes++];
      me->num_verts = am->mNumVertices;
      me->texture = -1;
      me->pos = malloc((size_t)am->mNumVertices * 3 * sizeof(float));
      me->nrm = malloc((size_t)am->mNumVertices * 3 * sizeof(float));
      me->idx = malloc((size_t)am->mNumFaces * 3 * sizeof(unsigned));
      if (am->mTextureCoords[0])
         me->uv = malloc((size_t)am->mNumVertices * 2 * sizeof(float));
      if (am->mColors[0])
         me->col = malloc((size_t)am->mNumVertices * 4 * sizeof(float));
      if (!me->pos || !me->nrm || !me->idx || (am->mTextureCoords[0] && !me->uv) ||
          (am->mColors[0] && !me->col)) {
         oom = 1;
         break;
      }
      for (unsigned v = 0; v < am->mNumVertices; v++) {
         const float p[3] = { am->mVertices[v].x, am->mVertices[v].y, am->mVertices[v].z };
         float n[3] = { am->mNormals[v].x, am->mNormals[v].y, am->mNormals[v].z };
         /* a degenerate corner (a patch's pole) gets no NaN normal */
         if (!(isfinite(n[0]) && isfinite(n[1]) && isfinite(n[2])))
            n[0] = n[1] = 0.0f, n[2] = 1.0f;
         for (int c = 0; c < 3; c++) {
            me->pos[v * 3 + c] = p[c];
            me->nrm[v * 3 + c] = n[c];
         }
         if (me->uv) {
            me->uv[v * 2 + 0] = am->mTextureCoords[0][v].x;
            me->uv[v * 2 + 1] = am->mTextureCoords[0][v].y;
         }
         if (me->col) {
            const struct aiColor4D c = am->mColors[0][v];
            me->col[v * 4 + 0] = c.r, me->col[v * 4 + 1] = c.g;
            me->col[v * 4 + 2] = c.b, me->col[v * 4 + 3] = c.a;
         }
      }
      for (unsigned t = 0; t < am->mNumFaces; t++) {
         if (am->mFaces[t].mNumIndices != 3)
            continue;
         for (int c = 0; c < 3; c++)
            me->idx[me->num_idx++] = am->mFaces[t].mIndices[c];
      }
      const struct aiMaterial *mat = sc->mMaterials[am->mMaterialIndex];
      convert_material(mat, &me->mat);
      me->texture = material_texture(m, path, mat, tex_dir);
      if (me->texture >= 0 && !me->uv) {
         fprintf(stderr, "fixgl-view: warning: %s: a mesh with the texture %s has no texture "
                         "coordinates; drawn untextured\n", path, m->textures[me->texture].kd
                         ? m->textures[me->texture].kd : m->textures[me->texture].d);
         me->texture = -1;
      }
      if (normals == FV_NORMALS_FLAT && make_flat(me) != 0) {
         oom = 1;
         break;
      }
      m->num_tris += me->num_idx / 3;
   }
   free(tex_dir);
   aiReleaseImport(sc);
   if (oom) {
      fprintf(stderr, "fixgl-view: out of memory loading %s\n", path);
      fv_model_free(m);
      return -1;
   }
   if (m->num_tris == 0) {
      fprintf(stderr, "fixgl-view: the model %s is empty: no triangles\n", path);
      fv_model_free(m);
      return -1;
   }

   /* Bounding sphere: the box's centre, the farthest vertex. */
   float lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
   for (int i = 0; i < m->num_meshes; i++)
      for (unsigned v = 0; v < m->meshes[i].num_verts; v++)
         for (int c = 0; c < 3; c++) {
            lo[c] = fminf(lo[c], m->meshes[i].pos[v * 3 + c]);
            hi[c] = fmaxf(hi[c], m->meshes[i].pos[v * 3 + c]);
         }
   float r2 = 0.0f;
   for (int c = 0; c < 3; c++)
      m->center[c] = 0.5f * (lo[c] + hi[c]);
   for (int i = 0; i < m->num_meshes; i++)
      for (unsigned v = 0; v < m->meshes[i].num_verts; v++) {
         const float *p = &m->meshes[i].pos[v * 3];
         float dx = p[0] - m->center[0], dy = p[1] - m->center[1], dz = p[2] - m->center[2];
         r2 = fmaxf(r2, dx * dx + dy * dy + dz * dz);
      }
   m->radius = r2 > 0.0f ? sqrtf(r2) : 1.0f;
   return 0;
}

void fv_model_free(struct fv_model *m)
{
   for (int i = 0; m->meshes && i < m->num_meshes; i++) {
      free(m->meshes[i].pos);
      free(m->meshes[i].nrm);
      free(m->meshes[i].uv);
      free(m->meshes[i].col);
      free(m->meshes[i].idx);
   }
   for (int i = 0; i < m->num_textures; i++) {
      free(m->textures[i].rgba);
      free(m->textures[i].kd);
      free(m->textures[i].d);
   }
   free(m->meshes);
   free(m->textures);
   memset(m, 0, sizeof *m);
}
