/*
 * Models for the viewer, loaded through assimp's C API: OBJ (with its MTL
 * materials and textures), PLY, STL and whatever else assimp reads.
 * Triangles only (faces triangulated, points and lines dropped), normals as
 * the file has them, or generated (smooth, or flat: one per face), every
 * node's transform applied, per-vertex colours and texture coordinates
 * kept.
 */
#ifndef FV_MODEL_H
#define FV_MODEL_H

/* A material as the viewer gives it to glMaterial (MTL: Ka, Kd, Ks, Ke,
 * Ns, d, illum). */
struct fv_material {
   float ambient[4], diffuse[4], specular[4], emission[4];
   float shininess;      /* GL's [0, 128] */
   int lit;              /* 0: illum 0, constant colour Kd, no lighting */
};

struct fv_mesh {
   float *pos, *nrm;     /* xyz per vertex */
   float *uv;            /* st per vertex (assimp's first UV channel), or NULL */
   float *col;           /* RGBA per vertex (its first colour channel), or NULL */
   unsigned *idx;        /* 3 per triangle */
   unsigned num_verts, num_idx;
   int texture;          /* index into fv_model.textures, or -1 */
   struct fv_material mat;
};

/* A material's texture: MTL map_Kd (map_Ka when it has no map_Kd) gives the
 * RGB, map_d the alpha (its alpha channel, or its first one), drawn with
 * GL_MODULATE over the lit colour. */
struct fv_texture {
   int w, h;
   unsigned char *rgba;  /* bottom row first */
   char *kd, *d;         /* the files it was made of (d: NULL when none) */
   int translucent;      /* some alpha < 255 */
};

/* --normals: as the file has them (generated smooth where it has none), all
 * generated smooth (averaged over the faces around a position), or flat
 * (one normal per face, its vertices split). */
enum fv_normals { FV_NORMALS_FILE, FV_NORMALS_SMOOTH, FV_NORMALS_FLAT };

struct fv_model {
   struct fv_mesh *meshes;
   int num_meshes;
   struct fv_texture *textures;
   int num_textures;
   float center[3], radius;   /* bounding sphere */
   unsigned num_tris;
};

/* Loads path; returns 0, or -1 with the reason on stderr: a file that
 * cannot be read or parsed, a model without faces, non-finite vertex
 * coordinates (how many, and the first few).  A texture that cannot be read
 * is a warning on stderr: its meshes are drawn untextured. */
int fv_model_load(struct fv_model *m, const char *path, enum fv_normals normals);
void fv_model_free(struct fv_model *m);

#endif
