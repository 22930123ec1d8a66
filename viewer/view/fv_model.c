/*
 * Model loading through assimp's C API (fv_model.h).
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

int fv_model_load(struct fv_model *m, const char *path)
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
    * (across edges up to 80 degrees) as for a file without normals. */
   const char *dot = strrchr(path, '.');
   if (dot && !strcasecmp(dot, ".stl"))
      flags |= aiProcess_ForceGenNormals;
   struct aiPropertyStore *props = aiCreatePropertyStore();
   aiSetImportPropertyFloat(props, AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, 80.0f);
   aiSetImportPropertyInteger(props, AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
   const struct aiScene *sc = aiImportFileExWithProperties(path, flags, NULL, props);
   aiReleasePropertyStore(props);
   if (!sc) {
      fprintf(stderr, "fixgl-view: cannot load the model %s: %s\n", path, aiGetErrorString());
      return -1;
   }

   m->meshes = calloc(sc->mNumMeshes ? sc->mNumMeshes : 1, sizeof *m->meshes);
   float lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
   for (unsigned i = 0; m->meshes && i < sc->mNumMeshes; i++) {
      const struct aiMesh *am = sc->mMeshes[i];
      if (!(am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) || !am->mNormals)
         continue;
      struct fv_mesh *me = &m->meshes[m->num_meshes++];
      me->num_verts = am->mNumVertices;
      me->pos = malloc((size_t)am->mNumVertices * 3 * sizeof(float));
      me->nrm = malloc((size_t)am->mNumVertices * 3 * sizeof(float));
      me->idx = malloc((size_t)am->mNumFaces * 3 * sizeof(unsigned));
      if (!me->pos || !me->nrm || !me->idx) {
         fprintf(stderr, "fixgl-view: out of memory loading %s\n", path);
         aiReleaseImport(sc);
         fv_model_free(m);
         return -1;
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
            lo[c] = fminf(lo[c], p[c]);
            hi[c] = fmaxf(hi[c], p[c]);
         }
      }
      for (unsigned t = 0; t < am->mNumFaces; t++) {
         if (am->mFaces[t].mNumIndices != 3)
            continue;
         for (int c = 0; c < 3; c++)
            me->idx[me->num_idx++] = am->mFaces[t].mIndices[c];
      }
      convert_material(sc->mMaterials[am->mMaterialIndex], &me->mat);
      m->num_tris += me->num_idx / 3;
   }
   aiReleaseImport(sc);
   if (m->num_tris == 0) {
      fprintf(stderr, "fixgl-view: cannot load the model %s: it has no triangles\n", path);
      fv_model_free(m);
      return -1;
   }

   /* Bounding sphere: the box's centre, the farthest vertex. */
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
      free(m->meshes[i].idx);
   }
   free(m->meshes);
   memset(m, 0, sizeof *m);
}
