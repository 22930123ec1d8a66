/*
 * Models for the viewer, loaded through assimp's C API: OBJ (with its MTL
 * materials), PLY, STL and whatever else assimp reads.  Triangles only
 * (faces triangulated, points and lines dropped), smooth normals generated
 * when the file has none, every node's transform applied.
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
   unsigned *idx;        /* 3 per triangle */
   unsigned num_verts, num_idx;
   struct fv_material mat;
};

struct fv_model {
   struct fv_mesh *meshes;
   int num_meshes;
   float center[3], radius;   /* bounding sphere */
   unsigned num_tris;
};

/* Loads path; returns 0, or -1 with the reason on stderr. */
int fv_model_load(struct fv_model *m, const char *path);
void fv_model_free(struct fv_model *m);

#endif
