/* c_cubemap.c - GL 1.3 cube maps (tags gl13 cubemap): the six face
 * targets of glTexImage2D, glTexSubImage2D, glCopyTexImage2D,
 * glCopyTexSubImage2D, glGetTexImage and glGetTexLevelParameter,
 * GL_PROXY_TEXTURE_CUBE_MAP, the square-face and size errors; sampled
 * through every filter (each face, face edges and corners where two or
 * three axes tie, directions exactly along an axis, wraps that the oracle
 * ignores), the per-pixel level of detail of mipmapped cube maps, the
 * general LOD path (bias, MIN_LOD/MAX_LOD), formats of the 8-bit and the
 * float path; completeness (a face missing or mismatched, a face's level
 * missing); GL_GENERATE_MIPMAP on a face; GL_REFLECTION_MAP and
 * GL_NORMAL_MAP texgen with lighting off and on, the texture matrix,
 * arrays and display lists; the unit's target priority (cube map before
 * 3D and 2D), glPushAttrib(GL_TEXTURE_BIT / GL_ENABLE_BIT) and the
 * queries. */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "cases.h"

static unsigned rng_state;

static unsigned rng(void)
{
    rng_state = rng_state * 1103515245u + 12345u;
    return (rng_state >> 16) & 0x7fff;
}

static unsigned char g_buf[64 * 64 * 4 * 2 + 4096];

static void noise(size_t n, unsigned seed)
{
    rng_state = seed * 7919u + 17u;
    for (size_t i = 0; i < n; i++)
        g_buf[i] = (unsigned char)(rng() & 255);
}

#define FACE(f) ((GLenum)(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (f)))

/* Face f of level `level`, n x n random texels (seeded) in internal
 * format ifmt. */
static void face_image(int f, int level, int n, GLenum ifmt, unsigned seed)
{
    noise((size_t)n * (size_t)n * 4, seed);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(FACE(f), level, (GLint)ifmt, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
}

/* Six faces of one level. */
static void cube_level(int level, int n, GLenum ifmt, unsigned seed)
{
    for (int f = 0; f < 6; f++)
        face_image(f, level, n, ifmt, seed + 101u * (unsigned)f);
}

/* A full chain from n down to 1 on every face. */
static void cube_chain(int n, GLenum ifmt, unsigned seed)
{
    for (int l = 0;; l++) {
        cube_level(l, n, ifmt, seed + 37u * (unsigned)l);
        if (n == 1)
            break;
        n /= 2;
    }
}

static void cparams(GLenum min, GLenum mag)
{
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, (GLint)min);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, (GLint)mag);
}

/* ---- scenes ---- */

/* The direction of grid point (i, j) of an n x n sweep: longitude and
 * latitude over the whole sphere, scaled by `len` (every face, its edges
 * and corners cross the grid). */
static void sweep_dir(int i, int j, int n, float len, float d[3])
{
    const float lon = -3.14159265f + 6.2831853f * (float)i / (float)n + 0.05f;
    const float lat = -1.5f + 3.0f * (float)j / (float)n;
    d[0] = cosf(lat) * cosf(lon) * len;
    d[1] = sinf(lat) * len;
    d[2] = cosf(lat) * sinf(lon) * len;
}

/* A grid of quads over the window whose corners carry sweep directions
 * (glTexCoord3f); `rep` > 1 wraps the sweep `rep` times (minifies);
 * captured. */
static void scene_sweep(fc_h *h, int n, float rep, float len)
{
    const fc_case *c = fc_this_case(h);
    const float w = (float)c->width, hh = (float)c->height;
    fc_pixel_ortho(h);
    fcu_clear(0.2f, 0.1f, 0.3f, 1, 1);
    glColor4f(0.9f, 0.8f, 0.7f, 1.0f);
    for (int j = 0; j < n; j++) {
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i <= n; i++) {
            float d[3];
            sweep_dir((int)((float)i * rep), j + 1, n, len, d);
            glTexCoord3fv(d);
            glVertex2f(w * (float)i / (float)n, hh * (float)(j + 1) / (float)n);
            sweep_dir((int)((float)i * rep), j, n, len, d);
            glTexCoord3fv(d);
            glVertex2f(w * (float)i / (float)n, hh * (float)j / (float)n);
        }
        glEnd();
    }
    fc_capture(h);
}

/* Small quads of constant directions: the axes, ties of two and three
 * axes of both signs, face edges (|minor| == |major|), near-ties, a
 * zero vector; captured. */
static void scene_axes(fc_h *h)
{
    static const float dirs[][3] = {
        { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 },
        { 1, 1, 0 }, { -1, 1, 0 }, { 1, -1, 0 }, { -1, -1, 0 }, { 0, 1, 1 }, { 0, -1, -1 },
        { 0, 1, -1 }, { 1, 0, 1 }, { -1, 0, -1 }, { 1, 0, -1 }, { 1, 1, 1 }, { -1, -1, -1 },
        { 1, -1, 1 }, { -1, 1, -1 }, { 2, 2, -2 }, { 0.5f, 0.5f, 0.25f }, { 1, 0.999f, 0.2f },
        { 0.3f, -1, 1 }, { -0.0f, -0.0f, 1 }, { 0, 0, -0.0f }, { 0, 0, 0 }, { 1e-20f, 0, 0 },
        { 3, 0.5f, -1 }, { -0.2f, 7, 0.1f }, { 0.7f, -0.1f, -0.71f }, { -1, 0.99999994f, 1 },
        { 0.25f, 0.25f, 0.25f }, { 1, -1, -1 }, { -1, 1, 1 }, { 0.001f, -0.002f, 0.0015f },
    };
    const int nd = (int)(sizeof dirs / sizeof dirs[0]);
    fc_pixel_ortho(h);
    fcu_clear(0.2f, 0.1f, 0.3f, 1, 1);
    glBegin(GL_QUADS);
    for (int k = 0; k < nd; k++) {
        const float x = (float)(k % 6) * 8.0f, y = (float)(k / 6) * 8.0f;
        glTexCoord3fv(dirs[k]);
        glVertex2f(x, y);
        glVertex2f(x + 7, y);
        glVertex2f(x + 7, y + 7);
        glVertex2f(x, y + 7);
    }
    glEnd();
    fc_capture(h);
}

/* A perspective floor whose directions point mostly up (+Y, running over
 * the face edges towards the far end) and a wall facing -Z: the level of
 * detail changes across the picture; captured. */
static void scene_persp(fc_h *h, float spread)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 60);
    fcu_clear(0.2f, 0.1f, 0.3f, 1, 1);
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_QUADS);
    glColor4f(1, 1, 1, 1);
    glTexCoord3f(-spread, 1.0f, -spread);           glVertex3f(-4, -1, -1.5f);
    glTexCoord3f(spread, 1.0f, -spread);            glVertex3f(4, -1, -1.5f);
    glTexCoord3f(spread * 3, 0.6f, spread * 3);     glVertex3f(4, -1, -40);
    glTexCoord3f(-spread * 3, 0.6f, spread * 3);    glVertex3f(-4, -1, -40);
    glEnd();
    glBegin(GL_TRIANGLES);
    glTexCoord3f(0.1f, 0.2f, -1.0f);                 glVertex3f(-0.2f, 0.9f, -2.0f);
    glTexCoord3f(spread, -0.1f, -1.0f);              glVertex3f(2.5f, 0.1f, -12);
    glTexCoord3f(-0.3f, spread * 0.5f, -0.9f);       glVertex3f(-1.5f, -0.4f, -6);
    glEnd();
    glDisable(GL_DEPTH_TEST);
    fc_capture(h);
}

/* ---- sampling cases, by parameters ---- */

struct cp {
    const char *name;
    int n;              /* face size */
    GLenum ifmt;
    GLenum min, mag;
    int mip;            /* 0: one level; 1: a chain; 2: GL_GENERATE_MIPMAP on each face;
                         * 3: a chain with LOD bias and MIN_LOD / MAX_LOD;
                         * 4: a chain from BASE_LEVEL 1 to MAX_LEVEL 3 */
    int scene;          /* 0: sweep; 1: axes; 2: perspective; 3: sweep repeated */
    GLenum wrap;        /* given to WRAP_S/T/R (ignored by the oracle) */
};

static const struct cp sample_params[] = {
    { "cubemap/nearest_sweep", 8, GL_RGBA, GL_NEAREST, GL_NEAREST, 0, 0, GL_REPEAT },
    { "cubemap/linear_sweep", 8, GL_RGBA, GL_LINEAR, GL_LINEAR, 0, 0, GL_REPEAT },
    { "cubemap/nearest_npot", 5, GL_RGBA, GL_NEAREST, GL_NEAREST, 0, 0, GL_REPEAT },
    { "cubemap/linear_npot", 7, GL_RGBA, GL_LINEAR, GL_LINEAR, 0, 0, GL_REPEAT },
    { "cubemap/linear_size1", 1, GL_RGBA, GL_LINEAR, GL_LINEAR, 0, 0, GL_REPEAT },
    { "cubemap/linear_size2_edges", 2, GL_RGBA, GL_LINEAR, GL_LINEAR, 0, 0, GL_REPEAT },
    { "cubemap/nearest_axes_ties", 4, GL_RGBA, GL_NEAREST, GL_NEAREST, 0, 1, GL_REPEAT },
    { "cubemap/linear_axes_ties", 4, GL_RGBA, GL_LINEAR, GL_LINEAR, 0, 1, GL_REPEAT },
    { "cubemap/wrap_border_ignored", 4, GL_RGBA, GL_LINEAR, GL_LINEAR, 0, 0,
      GL_CLAMP_TO_BORDER },
    { "cubemap/wrap_clamp_ignored", 4, GL_RGBA, GL_LINEAR, GL_LINEAR, 0, 0, GL_CLAMP },
    { "cubemap/wrap_mirror_ignored", 5, GL_RGBA, GL_NEAREST, GL_NEAREST, 0, 0,
      GL_MIRRORED_REPEAT },
    { "cubemap/minlin_magnear", 8, GL_RGBA, GL_LINEAR, GL_NEAREST, 0, 3, GL_REPEAT },
    { "cubemap/minnear_maglin", 8, GL_RGBA, GL_NEAREST, GL_LINEAR, 0, 3, GL_REPEAT },
    { "cubemap/mip_nearest_nearest", 16, GL_RGBA, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, 1, 2,
      GL_REPEAT },
    { "cubemap/mip_linear_nearest", 16, GL_RGBA, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, 1, 2,
      GL_REPEAT },
    { "cubemap/mip_nearest_linear", 16, GL_RGBA, GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST, 1, 2,
      GL_REPEAT },
    { "cubemap/mip_linear_linear", 16, GL_RGBA, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 1, 2,
      GL_REPEAT },
    { "cubemap/mip_sweep_repeated", 16, GL_RGBA, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 1, 3,
      GL_REPEAT },
    { "cubemap/mip_nearest_maglin", 16, GL_RGBA, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR, 1, 3,
      GL_REPEAT },
    { "cubemap/mip_bias_minmax_lod", 16, GL_RGBA, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 3, 2,
      GL_REPEAT },
    { "cubemap/mip_base_max_level", 16, GL_RGBA, GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST, 4, 2,
      GL_REPEAT },
    { "cubemap/genmipmap", 16, GL_RGBA, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 2, 2, GL_REPEAT },
    { "cubemap/genmipmap_npot", 12, GL_RGBA, GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR, 2, 3,
      GL_REPEAT },
    { "cubemap/format_luminance_alpha", 8, GL_LUMINANCE_ALPHA, GL_LINEAR, GL_LINEAR, 0, 0,
      GL_REPEAT },
    { "cubemap/format_rgb565", 8, GL_RGB565, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 1, 2,
      GL_REPEAT },
    { "cubemap/format_rgba16_float_path", 8, GL_RGBA16, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 1,
      2, GL_REPEAT },
    { "cubemap/format_intensity12_nearest", 8, GL_INTENSITY12, GL_NEAREST, GL_NEAREST, 0, 1,
      GL_REPEAT },
    { NULL, 0, 0, 0, 0, 0, 0, 0 },
};

static const struct cp *find_params(const char *name)
{
    for (const struct cp *p = sample_params; p->name; p++)
        if (strcmp(p->name, name) == 0)
            return p;
    return NULL;
}

static void sample_case(fc_h *h)
{
    const struct cp *p = find_params(fc_this_case(h)->name);
    if (!p) {
        fc_value(h, "unknown_case", 1);
        return;
    }
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, (GLint)p->wrap);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, (GLint)p->wrap);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, (GLint)p->wrap);
    static const GLfloat border[4] = { 1.0f, 0.0f, 0.5f, 1.0f };
    glTexParameterfv(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BORDER_COLOR, border);
    cparams(p->min, p->mag);
    switch (p->mip) {
    case 0:
        cube_level(0, p->n, p->ifmt, 11u);
        break;
    case 2:
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_GENERATE_MIPMAP, GL_TRUE);
        cube_level(0, p->n, p->ifmt, 12u);
        break;
    case 4:
        cube_chain(p->n, p->ifmt, 14u);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BASE_LEVEL, 1);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, 3);
        break;
    default:
        cube_chain(p->n, p->ifmt, 13u);
        break;
    }
    glEnable(GL_TEXTURE_CUBE_MAP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    for (int frame = 0; frame < (p->mip == 3 ? 2 : 1); frame++) {
        if (p->mip == 3) {
            glTexParameterf(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_LOD_BIAS, frame ? -0.75f : 1.25f);
            glTexParameterf(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_LOD, frame ? 0.5f : -2.0f);
            glTexParameterf(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LOD, frame ? 2.5f : 3.0f);
        }
        switch (p->scene) {
        case 0: scene_sweep(h, 12, 1.0f, 1.0f); break;
        case 1: scene_axes(h); break;
        case 2: scene_persp(h, 1.4f); break;
        default: scene_sweep(h, 12, 5.0f, 3.0f); break;
        }
    }
    fc_error(h, "sample");
    glDeleteTextures(1, &tex);
}

/* ---- completeness ---- */

/* A cube map with one defect (kind) over a complete 2D texture: an
 * incomplete cube map leaves the unit to the 2D texture. */
static void incomplete_case(fc_h *h, int kind)
{
    GLuint tex[2];
    glGenTextures(2, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    noise(8 * 8 * 4, 90);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[1]);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    switch (kind) {
    case 0:   /* face -Y missing */
        cparams(GL_NEAREST, GL_NEAREST);
        for (int f = 0; f < 6; f++)
            if (f != 3)
                face_image(f, 0, 4, GL_RGBA, 91u + (unsigned)f);
        break;
    case 1:   /* face +Z 2x2 among 4x4 */
        cparams(GL_LINEAR, GL_LINEAR);
        for (int f = 0; f < 6; f++)
            face_image(f, 0, f == 4 ? 2 : 4, GL_RGBA, 92u + (unsigned)f);
        break;
    case 2:   /* face -X in another internal format */
        cparams(GL_NEAREST, GL_NEAREST);
        for (int f = 0; f < 6; f++)
            face_image(f, 0, 4, f == 1 ? GL_RGB : GL_RGBA, 93u + (unsigned)f);
        break;
    default:  /* mipmapped, face +Y's level 1 missing; then given */
        cparams(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
        for (int l = 0, n = 4; l < 3; l++, n /= 2)
            for (int f = 0; f < 6; f++)
                if (!(l == 1 && f == 2))
                    face_image(f, l, n, GL_RGBA, 94u + (unsigned)(f + 6 * l));
        break;
    }
    scene_sweep(h, 8, 1.0f, 1.0f);
    /* the defect repaired: the cube map textures */
    switch (kind) {
    case 0: face_image(3, 0, 4, GL_RGBA, 95); break;
    case 1: face_image(4, 0, 4, GL_RGBA, 96); break;
    case 2: face_image(1, 0, 4, GL_RGBA, 97); break;
    default: face_image(2, 1, 2, GL_RGBA, 98); break;
    }
    scene_sweep(h, 8, 1.0f, 1.0f);
    fc_error(h, "incomplete");
    glDeleteTextures(2, tex);
}

static void incomplete_missing_face(fc_h *h) { incomplete_case(h, 0); }
static void incomplete_size_mismatch(fc_h *h) { incomplete_case(h, 1); }
static void incomplete_format_mismatch(fc_h *h) { incomplete_case(h, 2); }
static void incomplete_face_level(fc_h *h) { incomplete_case(h, 3); }

/* ---- texgen ---- */

/* A lit, tessellated sphere-ish mesh (normals per vertex) in perspective;
 * texture coordinates from texgen; drawn immediate (mode 0), by arrays
 * (1), or from a display list (2); captured. */
#define MESH_N 10
static GLfloat g_mesh_pos[(MESH_N + 1) * (MESH_N + 1) * 3];
static GLfloat g_mesh_nrm[(MESH_N + 1) * (MESH_N + 1) * 3];
static GLushort g_mesh_idx[MESH_N * MESH_N * 4];

static void build_mesh(void)
{
    for (int j = 0; j <= MESH_N; j++)
        for (int i = 0; i <= MESH_N; i++) {
            const float u = -1.2f + 2.4f * (float)i / MESH_N, v = -1.2f + 2.4f * (float)j / MESH_N;
            const float z = -0.6f * (u * u + v * v);
            GLfloat *p = &g_mesh_pos[3 * (j * (MESH_N + 1) + i)];
            GLfloat *n = &g_mesh_nrm[3 * (j * (MESH_N + 1) + i)];
            p[0] = u;
            p[1] = v;
            p[2] = z;
            /* unnormalised normals: the oracle normalises with
             * GL_NORMALIZE only */
            n[0] = 1.2f * u;
            n[1] = 1.2f * v;
            n[2] = 1.0f;
        }
    int k = 0;
    for (int j = 0; j < MESH_N; j++)
        for (int i = 0; i < MESH_N; i++) {
            g_mesh_idx[k++] = (GLushort)(j * (MESH_N + 1) + i);
            g_mesh_idx[k++] = (GLushort)(j * (MESH_N + 1) + i + 1);
            g_mesh_idx[k++] = (GLushort)((j + 1) * (MESH_N + 1) + i + 1);
            g_mesh_idx[k++] = (GLushort)((j + 1) * (MESH_N + 1) + i);
        }
}

static void draw_mesh(int mode)
{
    if (mode == 1) {
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_NORMAL_ARRAY);
        glVertexPointer(3, GL_FLOAT, 0, g_mesh_pos);
        glNormalPointer(GL_FLOAT, 0, g_mesh_nrm);
        glDrawElements(GL_QUADS, MESH_N * MESH_N * 4, GL_UNSIGNED_SHORT, g_mesh_idx);
        glDisableClientState(GL_NORMAL_ARRAY);
        glDisableClientState(GL_VERTEX_ARRAY);
        return;
    }
    glBegin(GL_QUADS);
    for (int k = 0; k < MESH_N * MESH_N * 4; k++) {
        glNormal3fv(&g_mesh_nrm[3 * g_mesh_idx[k]]);
        glVertex3fv(&g_mesh_pos[3 * g_mesh_idx[k]]);
    }
    glEnd();
}

static void scene_mesh(fc_h *h, int mode, bool lit, float angle)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_frustum(-0.6, 0.6, -0.6, 0.6, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.1f, -0.05f, -3.2f);
    glRotatef(angle, 0.4f, 1.0f, 0.1f);
    fcu_clear(0.1f, 0.1f, 0.2f, 1, 1);
    glEnable(GL_DEPTH_TEST);
    if (lit) {
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        const GLfloat lp[4] = { 1.0f, 2.0f, 3.0f, 0.0f };
        glLightfv(GL_LIGHT0, GL_POSITION, lp);
        glEnable(GL_NORMALIZE);
    } else {
        glColor4f(1.0f, 0.95f, 0.9f, 1.0f);
    }
    if (mode == 2) {
        const GLuint list = glGenLists(1);
        glNewList(list, GL_COMPILE);
        draw_mesh(0);
        glEndList();
        glCallList(list);
        glDeleteLists(list, 1);
    } else {
        draw_mesh(mode);
    }
    glDisable(GL_LIGHTING);
    glDisable(GL_NORMALIZE);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    fc_capture(h);
}

/* texgen `gmode` on S, T, R of a mipmapped cube map; two angles. */
static void texgen_case(fc_h *h, GLenum gmode, bool lit, int mode, bool texmat)
{
    build_mesh();
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
    cube_chain(16, GL_RGBA, 21u);
    cparams(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, (GLint)gmode);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, (GLint)gmode);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, (GLint)gmode);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_GEN_R);
    if (texmat) {
        glMatrixMode(GL_TEXTURE);
        glRotatef(40.0f, 0.2f, 1.0f, 0.3f);
        glScalef(1.0f, -1.0f, 1.5f);
        glMatrixMode(GL_MODELVIEW);
    }
    scene_mesh(h, mode, lit, 20.0f);
    scene_mesh(h, mode, lit, -55.0f);
    if (texmat) {
        glMatrixMode(GL_TEXTURE);
        glLoadIdentity();
        glMatrixMode(GL_MODELVIEW);
    }
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glDisable(GL_TEXTURE_GEN_R);
    fc_error(h, "texgen");
    glDeleteTextures(1, &tex);
}

static void reflection_unlit(fc_h *h) { texgen_case(h, GL_REFLECTION_MAP, false, 0, false); }
static void reflection_lit(fc_h *h) { texgen_case(h, GL_REFLECTION_MAP, true, 0, false); }
static void reflection_arrays(fc_h *h) { texgen_case(h, GL_REFLECTION_MAP, true, 1, false); }
static void reflection_dlist(fc_h *h) { texgen_case(h, GL_REFLECTION_MAP, false, 2, false); }
static void reflection_texmat(fc_h *h) { texgen_case(h, GL_REFLECTION_MAP, false, 0, true); }
static void normal_unlit(fc_h *h) { texgen_case(h, GL_NORMAL_MAP, false, 0, false); }
static void normal_lit(fc_h *h) { texgen_case(h, GL_NORMAL_MAP, true, 0, false); }
static void normal_arrays(fc_h *h) { texgen_case(h, GL_NORMAL_MAP, false, 1, false); }
static void normal_dlist_texmat(fc_h *h) { texgen_case(h, GL_NORMAL_MAP, true, 2, true); }

/* The ARB and EXT names of the modes and targets (the same values),
 * texgen errors: Q takes neither mode, SPHERE_MAP not R. */
static void texgen_errors_case(fc_h *h)
{
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    fc_error(h, "q_reflection");
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP_ARB);
    fc_error(h, "q_normal");
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP_EXT);
    fc_error(h, "r_reflection");
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    fc_error(h, "r_sphere");
    GLint v = 0;
    glGetTexGeniv(GL_R, GL_TEXTURE_GEN_MODE, &v);
    fc_value(h, "r_mode", v);
    glTexGenf(GL_S, GL_TEXTURE_GEN_MODE, (GLfloat)GL_NORMAL_MAP);
    glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &v);
    fc_value(h, "s_mode_f", v);
    glEnable(GL_TEXTURE_CUBE_MAP_ARB);
    fc_is_enabled(h, "enabled_arb", GL_TEXTURE_CUBE_MAP_EXT);
    glDisable(GL_TEXTURE_CUBE_MAP);
    fc_error(h, "end");
    fc_capture(h);
}

/* ---- images ---- */

/* glTexSubImage2D into faces, glGetTexImage of each face, level
 * parameters of faces and of the cube map target (an error). */
static void subimage_getimage_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
    cube_level(0, 4, GL_RGBA, 31u);
    cparams(GL_NEAREST, GL_NEAREST);
    noise(64, 32);
    for (int f = 0; f < 6; f++)
        glTexSubImage2D(FACE(f), 0, f % 3, f / 3, 2, 2, GL_LUMINANCE, GL_UNSIGNED_BYTE,
                        g_buf + f);
    fc_error(h, "sub");
    unsigned char out[4 * 4 * 4];
    for (int f = 0; f < 6; f++) {
        memset(out, 0, sizeof out);
        glGetTexImage(FACE(f), 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
        char label[32];
        snprintf(label, sizeof label, "face%d", f);
        fc_blob(h, label, out, sizeof out);
    }
    glGetTexImage(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
    fc_error(h, "get_cube_target");
    GLint v = -1;
    glGetTexLevelParameteriv(FACE(5), 0, GL_TEXTURE_WIDTH, &v);
    fc_value(h, "width_negz", v);
    glGetTexLevelParameteriv(FACE(2), 0, GL_TEXTURE_INTERNAL_FORMAT, &v);
    fc_value(h, "ifmt_posy", v);
    glGetTexLevelParameteriv(FACE(2), 1, GL_TEXTURE_WIDTH, &v);
    fc_value(h, "width_level1", v);
    glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &v);
    fc_error(h, "level_param_cube_target");
    glEnable(GL_TEXTURE_CUBE_MAP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_sweep(h, 8, 1.0f, 1.0f);
    glDeleteTextures(1, &tex);
}

/* glCopyTexImage2D and glCopyTexSubImage2D into faces. */
static void copy_case(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.3f, 0.3f, 0.3f, 1, 1);
    for (int i = 0; i < 6; i++) {
        fcu_color(i + 2);
        fcu_rect((float)(i * 4), (float)(i * 3), (float)(i * 4 + 9), (float)(i * 3 + 7), 0);
    }
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
    for (int f = 0; f < 6; f++)
        glCopyTexImage2D(FACE(f), 0, f & 1 ? GL_RGB : GL_RGBA, f * 3, f * 2, 8, 8, 0);
    fc_error(h, "copy");
    glCopyTexImage2D(FACE(1), 0, GL_RGBA, 0, 0, 8, 8, 0);   /* all RGBA again */
    glCopyTexImage2D(FACE(3), 0, GL_RGBA, 20, 2, 8, 8, 0);
    glCopyTexImage2D(FACE(5), 0, GL_RGBA, 44, 40, 8, 8, 0); /* partly outside */
    glCopyTexSubImage2D(FACE(2), 0, 2, 3, 10, 12, 4, 5);
    glCopyTexSubImage2D(FACE(4), 0, 0, 0, 30, 30, 8, 8);
    fc_error(h, "copy_sub");
    glCopyTexImage2D(FACE(0), 0, GL_RGBA, 0, 0, 8, 6, 0);
    fc_error(h, "copy_not_square");
    glCopyTexSubImage2D(GL_TEXTURE_CUBE_MAP, 0, 0, 0, 0, 0, 2, 2);
    fc_error(h, "copy_sub_cube_target");
    glCopyTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, 0, 0, 8, 8, 0);
    fc_error(h, "copy_proxy");
    cparams(GL_NEAREST, GL_NEAREST);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_sweep(h, 8, 1.0f, 1.0f);
    glDeleteTextures(1, &tex);
}

/* GL_PROXY_TEXTURE_CUBE_MAP: fitting, not square, too large (one face
 * fits, six do not), level too high, border; read back. */
static void proxy_case(fc_h *h)
{
    static const int sizes[][3] = {
        { 64, 64, 0 }, { 64, 32, 0 }, { 16384, 16384, 0 }, { 8192, 8192, 0 }, { 16385, 16385, 0 },
        { 4, 4, 13 }, { 1, 1, 14 }, { 2, 2, 14 }, { 6, 6, 1 }, { 0, 0, 0 }, { 10, 10, 2 },
    };
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
        const int border = sizes[k][0] == 6 ? 1 : 0;
        glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, sizes[k][2], GL_RGBA, sizes[k][0], sizes[k][1],
                     border, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
        char label[48];
        snprintf(label, sizeof label, "proxy%zu_err", k);
        fc_error(h, label);
        GLint v[3] = { -1, -1, -1 };
        glGetTexLevelParameteriv(GL_PROXY_TEXTURE_CUBE_MAP, sizes[k][2] < 15 ? sizes[k][2] : 0,
                                 GL_TEXTURE_WIDTH, &v[0]);
        glGetTexLevelParameteriv(GL_PROXY_TEXTURE_CUBE_MAP, sizes[k][2] < 15 ? sizes[k][2] : 0,
                                 GL_TEXTURE_HEIGHT, &v[1]);
        glGetTexLevelParameteriv(GL_PROXY_TEXTURE_CUBE_MAP, sizes[k][2] < 15 ? sizes[k][2] : 0,
                                 GL_TEXTURE_BORDER, &v[2]);
        snprintf(label, sizeof label, "proxy%zu", k);
        fc_blob(h, label, v, sizeof v);
    }
    GLint v = -1;
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_INTERNAL_FORMAT, &v);
    fc_value(h, "proxy_ifmt", v);
    glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA16, 8192, 8192, 0, GL_RGBA,
                 GL_UNSIGNED_SHORT, NULL);
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &v);
    fc_value(h, "proxy_rgba16_8192", v);
    fc_error(h, "end");
    fc_get_integer(h, "max_cube_size", GL_MAX_CUBE_MAP_TEXTURE_SIZE, 1);
    fc_capture(h);
}

/* The errors of each entry point on the cube map targets. */
static void errors_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
    noise(64 * 64 * 4, 41);
    glTexImage2D(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "teximage_cube_target");
    glTexImage2D(FACE(0), 0, GL_RGBA, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "teximage_not_square");
    glTexImage2D(FACE(1), 0, GL_RGBA, 16385, 16385, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "teximage_too_large");
    glTexImage2D(FACE(1), 14, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "teximage_level14_too_large");
    glTexImage2D(FACE(1), 15, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "teximage_level15");
    glTexImage2D(FACE(2), 0, GL_RGBA, 4, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "teximage_border2");
    glTexImage2D(FACE(2), 0, GL_RGBA, 8192, 8192, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "teximage_8192");
    glTexImage2D(FACE(2), 0, GL_RGBA, 16384, 16384, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "teximage_16384_oom");
    glTexImage2D(FACE(3), 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "teximage_good");
    glTexImage1D(FACE(3), 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "teximage1d_face");
    glTexImage3D(FACE(3), 0, GL_RGBA, 4, 4, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "teximage3d_face");
    glTexImage3D(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, 4, 4, 6, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "teximage3d_cube");
    glTexSubImage2D(FACE(3), 0, 2, 2, 3, 2, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "sub_over");
    glTexSubImage2D(FACE(4), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "sub_no_image");
    glTexSubImage2D(GL_TEXTURE_CUBE_MAP, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "sub_cube_target");
    glTexSubImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "sub_proxy");
    glTexSubImage2D(FACE(3), 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "sub_good");
    glCopyTexImage2D(FACE(0), 0, GL_RGBA, 0, 0, 4, 3, 0);
    fc_error(h, "copy_not_square");
    glCopyTexImage2D(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, 0, 0, 4, 4, 0);
    fc_error(h, "copy_cube_target");
    glCopyTexSubImage2D(FACE(5), 0, 0, 0, 0, 0, 1, 1);
    fc_error(h, "copy_sub_no_image");
    glGetTexImage(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "get_proxy");
    GLint v;
    glGetTexLevelParameteriv(FACE(0), 15, GL_TEXTURE_WIDTH, &v);
    fc_error(h, "level_param_15");
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    fc_error(h, "param_wrap_r");
    glTexParameteri(GL_PROXY_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    fc_error(h, "param_proxy");
    glTexParameteri(FACE(0), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    fc_error(h, "param_face");
    glBindTexture(FACE(0), tex);
    fc_error(h, "bind_face");
    glBindTexture(GL_TEXTURE_2D, tex);
    fc_error(h, "bind_other_target");
    glEnable(FACE(0));
    fc_error(h, "enable_face");
    glBegin(GL_TRIANGLES);
    glTexImage2D(FACE(3), 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    glEnd();
    fc_error(h, "in_begin");
    glDeleteTextures(1, &tex);
    fc_capture(h);
}

/* ---- state ---- */

/* The unit's target priority: a complete cube map over 3D and 2D; an
 * incomplete one (NEAREST_MIPMAP with one level) gives way. */
static void priority_case(fc_h *h)
{
    GLuint tex[3];
    glGenTextures(3, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    noise(8 * 8 * 4, 61);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_3D, tex[1]);
    noise(4 * 4 * 4 * 4, 62);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[2]);
    cube_level(0, 4, GL_RGBA, 63u);   /* mipmap filter, one level: incomplete */
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_TEXTURE_3D);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_sweep(h, 8, 1.0f, 1.0f);   /* 3D */
    cparams(GL_NEAREST, GL_NEAREST);
    scene_sweep(h, 8, 1.0f, 1.0f);   /* cube */
    glDisable(GL_TEXTURE_3D);
    glDisable(GL_TEXTURE_CUBE_MAP);
    scene_sweep(h, 8, 1.0f, 1.0f);   /* 2D */
    fc_is_enabled(h, "enabled_cube", GL_TEXTURE_CUBE_MAP);
    glDeleteTextures(3, tex);
}

/* glPushAttrib(GL_TEXTURE_BIT) / GL_ENABLE_BIT: the binding, the enable;
 * the queries. */
static void attrib_case(fc_h *h)
{
    GLuint tex[2];
    glGenTextures(2, tex);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[0]);
    cube_level(0, 4, GL_RGBA, 71u);
    cparams(GL_NEAREST, GL_NEAREST);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glPushAttrib(GL_TEXTURE_BIT);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[1]);
    cube_level(0, 2, GL_RGBA, 72u);
    cparams(GL_LINEAR, GL_LINEAR);
    glDisable(GL_TEXTURE_CUBE_MAP);
    fc_get_integer(h, "binding_inside", GL_TEXTURE_BINDING_CUBE_MAP, 1);
    fc_is_enabled(h, "enabled_inside", GL_TEXTURE_CUBE_MAP);
    glPopAttrib();
    fc_get_integer(h, "binding_after", GL_TEXTURE_BINDING_CUBE_MAP, 1);
    fc_is_enabled(h, "enabled_after", GL_TEXTURE_CUBE_MAP);
    GLint v = 0;
    glGetTexParameteriv(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, &v);
    fc_value(h, "min_after", v);
    scene_sweep(h, 8, 1.0f, 1.0f);
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_TEXTURE_CUBE_MAP);
    glPopAttrib();
    fc_is_enabled(h, "enabled_enable_bit", GL_TEXTURE_CUBE_MAP);
    fc_get_boolean(h, "enabled_get", GL_TEXTURE_CUBE_MAP, 1);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[1]);
    fc_get_integer(h, "binding_1", GL_TEXTURE_BINDING_CUBE_MAP_ARB, 1);
    fc_value(h, "is_texture", glIsTexture(tex[1]));
    glActiveTexture(GL_TEXTURE1);
    fc_get_integer(h, "binding_unit1", GL_TEXTURE_BINDING_CUBE_MAP, 1);
    glActiveTexture(GL_TEXTURE0);
    fc_error(h, "attrib");
    glDeleteTextures(2, tex);
    fc_get_integer(h, "binding_deleted", GL_TEXTURE_BINDING_CUBE_MAP, 1);
}

/* Display lists: face images, a proxy (compiled: only the 2D proxy runs
 * at once), errors, copies. */
static void dlist_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
    cparams(GL_LINEAR, GL_LINEAR);
    const GLuint list = glGenLists(1);
    noise(sizeof g_buf, 81);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    glNewList(list, GL_COMPILE);
    for (int f = 0; f < 6; f++)
        glTexImage2D(FACE(f), 0, GL_RGBA, 3, 3, 0, GL_RGB, GL_UNSIGNED_BYTE, g_buf + 40 * f);
    glTexSubImage2D(FACE(2), 0, 1, 1, 2, 2, GL_LUMINANCE, GL_UNSIGNED_BYTE, g_buf + 9);
    glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 NULL);
    glTexImage2D(FACE(0), 0, GL_RGBA, 3, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glEndList();
    fc_error(h, "compile");
    GLint v = -1;
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &v);
    fc_value(h, "proxy_width_at_compile", v);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glCallList(list);
    fc_error(h, "call");
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &v);
    fc_value(h, "proxy_width_after_call", v);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_sweep(h, 8, 1.0f, 1.0f);
    glDeleteLists(list, 1);
    glDeleteTextures(1, &tex);
}

/* A cube map on unit 1 (texgen reflection) over a 2D texture on unit 0;
 * lines and points through a cube map. */
static void multitex_lines_case(fc_h *h)
{
    build_mesh();
    GLuint tex[2];
    glGenTextures(2, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    noise(8 * 8 * 4, 51);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[1]);
    cube_chain(8, GL_RGBA, 52u);
    cparams(GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_GEN_R);
    scene_mesh(h, 1, true, 35.0f);
    /* lines and points */
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glDisable(GL_TEXTURE_GEN_R);
    glLineWidth(3.0f);
    glBegin(GL_LINES);
    for (int i = 0; i < 8; i++) {
        float d[3];
        sweep_dir(i, 2, 8, 1.0f, d);
        glMultiTexCoord3fv(GL_TEXTURE1, d);
        glVertex2f(2.0f + 5.0f * (float)i, 3);
        sweep_dir(i + 3, 6, 8, 1.0f, d);
        glMultiTexCoord3fv(GL_TEXTURE1, d);
        glVertex2f(40.0f - 3.0f * (float)i, 45);
    }
    glEnd();
    glPointSize(4.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 12; i++) {
        float d[3];
        sweep_dir(i, i % 8, 12, 1.0f, d);
        glMultiTexCoord3fv(GL_TEXTURE1, d);
        glVertex2f(4.0f + 3.5f * (float)i, 20.0f + (float)(i % 3) * 6.0f);
    }
    glEnd();
    glLineWidth(1.0f);
    glPointSize(1.0f);
    fc_capture(h);
    glDisable(GL_TEXTURE_CUBE_MAP);
    glActiveTexture(GL_TEXTURE0);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glDeleteTextures(2, tex);
}

/* Projective coordinates (q != 1) and GL_GENERATE_MIPMAP of one face
 * after the others: the other faces keep their levels. */
static void projective_genmip_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
    cube_chain(8, GL_RGBA, 55u);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_GENERATE_MIPMAP, GL_TRUE);
    face_image(2, 0, 8, GL_RGBA, 56u);   /* +Y regenerated, the others kept */
    cparams(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_persp(h, 2.0f);
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1);
    glBegin(GL_TRIANGLES);
    glTexCoord4f(0.5f, 1.0f, -0.2f, 1.0f);   glVertex2f(2, 2);
    glTexCoord4f(-2.0f, 0.5f, 1.5f, 2.0f);   glVertex2f(46, 4);
    glTexCoord4f(0.1f, -0.5f, 0.2f, -0.5f);  glVertex2f(8, 46);
    glEnd();
    fc_capture(h);
    unsigned char out[4 * 4 * 4];
    glGetTexImage(FACE(2), 2, GL_RGBA, GL_UNSIGNED_BYTE, out);
    fc_blob(h, "posy_level2", out, 2 * 2 * 4);
    glGetTexImage(FACE(3), 2, GL_RGBA, GL_UNSIGNED_BYTE, out);
    fc_blob(h, "negy_level2", out, 2 * 2 * 4);
    fc_error(h, "end");
    glDeleteTextures(1, &tex);
}

/* Coordinates divided by q = 0 (random-tex/s1-i451, s1-i963): infinite
 * (or, for s = t = r = 0, NaN) coordinates whose derivatives are NaN.
 * The cube's rho comes from explicit derivatives, and llvmpipe replaces
 * an infinite or NaN one by 0 (magnified, level 0), where the implicit 2D
 * rho keeps the NaN and minifies (texture/wrap_lod_nan).  Points of sizes
 * 1 and 3, a line and a triangle, with q = 0 and q = 1 beside them; frame
 * 1 mipmapped with min == mag (NEAREST_MIPMAP_LINEAR, NEAREST), frame 2
 * min != mag (LINEAR_MIPMAP_NEAREST, NEAREST: the float path), frame 3
 * the general LOD path (bias, MIN_LOD/MAX_LOD), frame 4 min != mag
 * without a mipmap filter (one LOD per quad). */
static void q_zero_case(fc_h *h)
{
    static const struct { GLenum min, mag; float bias; } filt[4] = {
        { GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST, 0.0f },
        { GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST, 0.0f },
        { GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR, 0.5f },
        { GL_LINEAR, GL_NEAREST, 0.0f },
    };
    static const GLfloat tc[4][4] = {
        { -1.0f, 5.0f, 380.0f, 0.0f },   /* (-inf, inf, inf): face +Z */
        { 3.0f, -0.5f, 0.25f, 0.0f },    /* (inf, -inf, inf): face +Z (ties) */
        { 0.0f, 0.0f, 0.0f, 0.0f },      /* NaN */
        { -1.0f, 5.0f, 380.0f, 1.0f },   /* finite, for comparison */
    };
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
    cube_chain(16, GL_RGBA, 77u);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    fc_pixel_ortho(h);
    for (int f = 0; f < 4; f++) {
        cparams(filt[f].min, filt[f].mag);
        glTexParameterf(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_LOD_BIAS, filt[f].bias);
        if (f == 2) {
            glTexParameterf(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_LOD, 0.5f);
            glTexParameterf(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LOD, 3.0f);
        }
        fcu_clear(0.2f, 0.1f, 0.3f, 1.0f, 1.0);
        for (int k = 0; k < 4; k++) {
            const float y = 4.0f + 11.0f * (float)k;
            glPointSize(1.0f);
            glBegin(GL_POINTS);
            glTexCoord4fv(tc[k]);
            glVertex2f(3.5f, y + 0.5f);
            glEnd();
            glPointSize(3.0f);
            glBegin(GL_POINTS);
            glTexCoord4fv(tc[k]);
            glVertex2f(9.5f, y + 0.5f);
            glEnd();
            glBegin(GL_LINES);
            glTexCoord4fv(tc[k]);
            glVertex2f(14.0f, y + 0.5f);
            glVertex2f(24.0f, y + 3.5f);
            glEnd();
            glBegin(GL_TRIANGLES);
            glTexCoord4fv(tc[k]);
            glVertex2f(26.0f, y - 2.0f);
            glVertex2f(46.0f, y);
            glVertex2f(30.0f, y + 7.0f);
            glEnd();
        }
        fc_capture(h);
    }
    fc_error(h, "q_zero");
    glDeleteTextures(1, &tex);
}

const fc_case fc_cases_cubemap[] = {
#define SC(n) FC_CASE_RGBA(n, 48, 48, 1, "gl13 cubemap", sample_case)
#define SC2(n) FC_CASE_RGBA(n, 48, 48, 2, "gl13 cubemap", sample_case)
    SC("cubemap/nearest_sweep"),
    SC("cubemap/linear_sweep"),
    SC("cubemap/nearest_npot"),
    SC("cubemap/linear_npot"),
    SC("cubemap/linear_size1"),
    SC("cubemap/linear_size2_edges"),
    SC("cubemap/nearest_axes_ties"),
    SC("cubemap/linear_axes_ties"),
    SC("cubemap/wrap_border_ignored"),
    SC("cubemap/wrap_clamp_ignored"),
    SC("cubemap/wrap_mirror_ignored"),
    SC("cubemap/minlin_magnear"),
    SC("cubemap/minnear_maglin"),
    SC("cubemap/mip_nearest_nearest"),
    SC("cubemap/mip_linear_nearest"),
    SC("cubemap/mip_nearest_linear"),
    SC("cubemap/mip_linear_linear"),
    SC("cubemap/mip_sweep_repeated"),
    SC("cubemap/mip_nearest_maglin"),
    SC2("cubemap/mip_bias_minmax_lod"),
    SC("cubemap/mip_base_max_level"),
    SC("cubemap/genmipmap"),
    SC("cubemap/genmipmap_npot"),
    SC("cubemap/format_luminance_alpha"),
    SC("cubemap/format_rgb565"),
    SC("cubemap/format_rgba16_float_path"),
    SC("cubemap/format_intensity12_nearest"),
#undef SC
#undef SC2
    FC_CASE_RGBA("cubemap/incomplete_missing_face", 48, 48, 2, "gl13 cubemap",
                 incomplete_missing_face),
    FC_CASE_RGBA("cubemap/incomplete_size_mismatch", 48, 48, 2, "gl13 cubemap",
                 incomplete_size_mismatch),
    FC_CASE_RGBA("cubemap/incomplete_format_mismatch", 48, 48, 2, "gl13 cubemap",
                 incomplete_format_mismatch),
    FC_CASE_RGBA("cubemap/incomplete_face_level", 48, 48, 2, "gl13 cubemap",
                 incomplete_face_level),
    FC_CASE_RGBA("cubemap/reflection_map_unlit", 48, 48, 2, "gl13 cubemap", reflection_unlit),
    FC_CASE_RGBA("cubemap/reflection_map_lit", 48, 48, 2, "gl13 cubemap", reflection_lit),
    FC_CASE_RGBA("cubemap/reflection_map_arrays", 48, 48, 2, "gl13 cubemap",
                 reflection_arrays),
    FC_CASE_RGBA("cubemap/reflection_map_dlist", 48, 48, 2, "gl13 cubemap", reflection_dlist),
    FC_CASE_RGBA("cubemap/reflection_map_texmatrix", 48, 48, 2, "gl13 cubemap",
                 reflection_texmat),
    FC_CASE_RGBA("cubemap/normal_map_unlit", 48, 48, 2, "gl13 cubemap", normal_unlit),
    FC_CASE_RGBA("cubemap/normal_map_lit", 48, 48, 2, "gl13 cubemap", normal_lit),
    FC_CASE_RGBA("cubemap/normal_map_arrays", 48, 48, 2, "gl13 cubemap", normal_arrays),
    FC_CASE_RGBA("cubemap/normal_map_dlist_texmatrix", 48, 48, 2, "gl13 cubemap",
                 normal_dlist_texmat),
    FC_CASE_NODRAW("cubemap/texgen_errors_aliases", 16, 16, OSMESA_RGBA, 24, 0, 1,
                   "gl13 cubemap", texgen_errors_case),
    FC_CASE_RGBA("cubemap/subimage_getteximage", 48, 48, 1, "gl13 cubemap",
                 subimage_getimage_case),
    FC_CASE_RGBA("cubemap/copy_tex_image", 48, 48, 1, "gl13 cubemap", copy_case),
    FC_CASE_NODRAW("cubemap/proxy", 16, 16, OSMESA_RGBA, 24, 0, 1, "gl13 cubemap", proxy_case),
    FC_CASE_NODRAW("cubemap/errors", 16, 16, OSMESA_RGBA, 24, 0, 1, "gl13 cubemap",
                   errors_case),
    FC_CASE_RGBA("cubemap/target_priority", 48, 48, 3, "gl13 cubemap", priority_case),
    FC_CASE_RGBA("cubemap/attrib_queries", 48, 48, 1, "gl13 cubemap", attrib_case),
    FC_CASE_RGBA("cubemap/dlist", 48, 48, 1, "gl13 cubemap", dlist_case),
    FC_CASE_RGBA("cubemap/multitexture_lines_points", 48, 48, 2, "gl13 cubemap",
                 multitex_lines_case),
    FC_CASE_RGBA("cubemap/projective_genmipmap_face", 48, 48, 2, "gl13 cubemap",
                 projective_genmip_case),
    FC_CASE_RGBA("cubemap/projective_q_zero", 48, 48, 4, "gl13 cubemap", q_zero_case),
    { 0 },
};
