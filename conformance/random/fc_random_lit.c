/* fc_random_lit.c - random lit scenes, "random-lit/s<seed>-i<index>" (tag
 * random-lit).  Like the plain scenes (fc_random.c) a scene is a pure
 * function of (seed, index), drawn from its own splitmix64 streams (purposes
 * 3 and 4 for values, 5 and 6 for structure, see FC_LIT_PROFILES; the plain
 * scenes use 1 and 2), and nothing depends on GL results.
 *
 * A scene: a clear, viewport, depth range and projection like the plain
 * generator's but chosen so the lit region is seen (pixel ortho, ortho box or
 * frustum of about the viewport's aspect, now and then loaded as a matrix;
 * depth functions and clear depths that let it through), GL_LIGHTING on,
 * then
 *   - 1-8 lights at random indices: directional, positional (w != 1, w < 0)
 *     and spot (cutoff 0..90, exactly 0, 90, 180, or about the size of the
 *     lit region; exponent 0..128 incl. 0 and 128), colours with 0, > 1 and
 *     negative values, attenuation (now and then all three factors 0),
 *     each given under its own modelview: identity, the camera's, a look-at
 *     built from glRotate/glTranslate or glMultMatrix, scaled, or a general
 *     affine matrix.  Positions are aimed in eye space at the lit region and
 *     taken back to object space with the inverse of the mirrored modelview,
 *     so scenes are lit and not black or white;
 *   - a random light model (ambient, local viewer, two-side, separate
 *     specular) and front/back materials (shininess 0, 0.5, 128, random);
 *   - GL_COLOR_MATERIAL with a random face and mode and glColor between
 *     vertices, glMaterial between glBegin and glEnd;
 *   - GL_NORMALIZE / GL_RESCALE_NORMAL, glShadeModel, glFrontFace;
 *   - 1-4 tessellated patches (sphere sections, height fields, cylinder
 *     bands, fans, convex polygons) drawn with all six polygon primitive
 *     types, normals per vertex, per face or per primitive (unit,
 *     unnormalised, zero-length, random), through every glNormal3 variant
 *     (b, s, i, f, d; vector or not), under a camera modelview that is rigid
 *     (glTranslate/glRotate only: llvmpipe then lights in object space when
 *     the lights are directional), scaled (uniform, non-uniform, mirrored),
 *     a glMultMatrix look-at or a general affine matrix.
 *   - GL 1.4 state (issue 19), from streams of its own (purposes 81 for
 *     structure, 82 for values: a scene without it is the scene it was
 *     before it came): fog (linear, exp, exp2, on the scale of the lit
 *     region's eye distances), GL_FOG_COORD_SRC = GL_FOG_COORD with the
 *     current fog coordinate set before each glBegin, GL_COLOR_SUM with the
 *     current secondary colour set before each glBegin, separate specular
 *     forced on now and then, and patches drawn with lighting off (where
 *     the secondary colour is the current one; with lighting on it is the
 *     lit specular whatever GL_COLOR_SUM says).
 * Scenes stay small (a few hundred vertices): the oracle's time goes to
 * compiling shaders (see FC_LIT_PROFILES). */
#define GL_GLEXT_PROTOTYPES 1   /* GL 1.4's secondary colour and fog coordinate */
#include "fc_random.h"
#include "fc_random_shared.h"
#include "fc_rng.h"
#include "fc_trace.h"
#include "fc_emit.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846

/* call-trace wrappers (fc_trace.h) of the GL 1.4 entry points this family
 * calls */
static inline void fctl_glSecondaryColor3f(GLfloat a, GLfloat b, GLfloat c) { fc_trace_call("glSecondaryColor3f", 3, a, b, c, 0); glSecondaryColor3f(a, b, c); }
static inline void fctl_glSecondaryColor3fv(const GLfloat *p) { fc_trace_vf("glSecondaryColor3fv", "GLfloat", 3, p); glSecondaryColor3fv(p); }
static inline void fctl_glSecondaryColor3ub(GLubyte a, GLubyte b, GLubyte c) { fc_trace_calli("glSecondaryColor3ub", 3, a, b, c, 0); glSecondaryColor3ub(a, b, c); }
static inline void fctl_glSecondaryColor3dv(const GLdouble *p) { fc_trace_vd("glSecondaryColor3dv", "GLdouble", 3, p); glSecondaryColor3dv(p); }
static inline void fctl_glFogCoordf(GLfloat a) { fc_trace_call("glFogCoordf", 1, a, 0, 0, 0); glFogCoordf(a); }
static inline void fctl_glFogCoordd(GLdouble a) { fc_trace_call("glFogCoordd", 1, a, 0, 0, 0); glFogCoordd(a); }
static inline void fctl_glFogCoordfv(const GLfloat *p) { fc_trace_vf("glFogCoordfv", "GLfloat", 1, p); glFogCoordfv(p); }
static inline void fctl_glFogCoorddv(const GLdouble *p) { fc_trace_vd("glFogCoorddv", "GLdouble", 1, p); glFogCoorddv(p); }

#define glSecondaryColor3f fctl_glSecondaryColor3f
#define glSecondaryColor3fv fctl_glSecondaryColor3fv
#define glSecondaryColor3ub fctl_glSecondaryColor3ub
#define glSecondaryColor3dv fctl_glSecondaryColor3dv
#define glFogCoordf fctl_glFogCoordf
#define glFogCoordd fctl_glFogCoordd
#define glFogCoordfv fctl_glFogCoordfv
#define glFogCoorddv fctl_glFogCoorddv

/* Structure profiles.  Everything the oracle compiles a shader for (light
 * count, indices and kinds, attenuation and spot presence, light model
 * flags, colour material, normalize/rescale, which attributes are per
 * vertex, shininess 0, depth test and function, shade model, colour and
 * depth formats, rigid or scaled modelviews, state changes between patches)
 * is drawn from a stream keyed by index % FC_LIT_PROFILES; values
 * (colours, positions, directions, matrices, geometry) from one keyed by
 * the index.  Scenes i and i + FC_LIT_PROFILES share their structure with
 * other values, so a long run reuses llvmpipe's compiled shaders (Mesa's
 * on-disk shader cache): a fresh structure costs the oracle 50-150 ms of
 * LLVM compilation, a repeated one ~10 ms. */
#define FC_LIT_PROFILES 256
#define MAXGRID 12                  /* cells per side of a patch */

/* The camera (object) modelview, drawn once and issued as often as needed. */
struct camera {
    int kind;                       /* CAM_* */
    int use_d;                      /* double entry points */
    double t[3];                    /* eye-space centre */
    int nrot;
    double rot[3][4];               /* glRotate angle, axis */
    double scale[3];                /* CAM_SCALED: glScale */
    double lookat_t[3], lookat_back[3], m[16]; /* CAM_LOOKAT, CAM_GENERAL */
    int mult_d, load;               /* CAM_LOOKAT/GENERAL: glMultMatrixd; glLoadMatrix */
};

enum { CAM_RIGID, CAM_SCALED, CAM_LOOKAT, CAM_GENERAL };

/* Normal policy of a patch. */
struct npolicy {
    int mode;                       /* 0 per vertex, 1 perturbed, 2 once per primitive,
                                     * 3 per face, 4 none, 5 random per vertex */
    double scale;                   /* unnormalised: uniform factor */
    int vary, zero;                 /* per-vertex factors; zero-length percentage */
    int colors;                     /* 0 none, 1 smooth, 2 wild (fcr_emit_color), 3 per primitive */
    int color4;                     /* smooth colours: glColor4 (else glColor3) variants */
    int materials;                  /* percentage of vertices preceded by a glMaterial */
    double w;                       /* vertex w (1 mostly) */
};

/* The GL 1.4 part of a scene's structure (make_profile14) */
struct profile14 {
    int fog;                        /* 0 off, else 1 + index into fog_modes */
    int fogcoord;                   /* GL_FOG_COORD_SRC = GL_FOG_COORD */
    int seccolor;                   /* GL_COLOR_SUM, glSecondaryColor before glBegin */
    int separate;                   /* GL_SEPARATE_SPECULAR_COLOR forced on */
    int unlit;                      /* percentage of patches drawn with lighting off */
};

struct lit {
    struct scene s;                 /* s.r: the value stream */
    fc_rng k;                       /* the structure stream (see FC_LIT_PROFILES) */
    double mv[16];                  /* mirror of the modelview matrix (column-major) */
    double stack[4][16];
    int sp;
    double c[3];                    /* eye-space centre of the lit region */
    double rxy, rz;                 /* its radius across and in depth */
    int flat;                       /* rz much below rxy: keep the z axis towards the eye */
    double g[3];                    /* object units -> vertex coordinates */
    struct camera cam;
    int color_material;             /* GL_COLOR_MATERIAL enabled */
    int lighting;                   /* GL_LIGHTING enabled */
    GLenum faces[2];                /* material faces in use */
    /* Most scenes keep one shader variant: the same attribute policy for
     * every patch and glMaterial of one pname between glBegin and glEnd.
     * Dynamic scenes change state and policy between patches. */
    int dynamic;
    struct npolicy np;
    GLenum mat_pname;
    int mat_face;
    /* GL 1.4: structure (profile) and value streams of its own */
    struct profile14 p14;
    fc_rng k14, r14;
    double fog_near, fog_far;       /* eye distances the lit region spans */
};

/* ---- the modelview mirror (doubles; only used to aim lights) ---------- */

static void mat_identity(double m[16])
{
    memset(m, 0, 16 * sizeof m[0]);
    m[0] = m[5] = m[10] = m[15] = 1;
}

static void mat_mul(double out[16], const double a[16], const double b[16])
{
    double t[16];
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 4; r++) {
            double v = 0;
            for (int k = 0; k < 4; k++)
                v += a[k * 4 + r] * b[c * 4 + k];
            t[c * 4 + r] = v;
        }
    memcpy(out, t, sizeof t);
}

static void mat_apply(const double m[16], const double v[4], double out[4])
{
    for (int r = 0; r < 4; r++)
        out[r] = m[r] * v[0] + m[4 + r] * v[1] + m[8 + r] * v[2] + m[12 + r] * v[3];
}

/* Inverse by cofactors; 0 when (nearly) singular. */
static int mat_invert(const double m[16], double inv[16])
{
    double a[16], det;
    a[0] = m[5] * m[10] * m[15] - m[5] * m[11] * m[14] - m[9] * m[6] * m[15] + m[9] * m[7] * m[14] + m[13] * m[6] * m[11] - m[13] * m[7] * m[10];
    a[4] = -m[4] * m[10] * m[15] + m[4] * m[11] * m[14] + m[8] * m[6] * m[15] - m[8] * m[7] * m[14] - m[12] * m[6] * m[11] + m[12] * m[7] * m[10];
    a[8] = m[4] * m[9] * m[15] - m[4] * m[11] * m[13] - m[8] * m[5] * m[15] + m[8] * m[7] * m[13] + m[12] * m[5] * m[11] - m[12] * m[7] * m[9];
    a[12] = -m[4] * m[9] * m[14] + m[4] * m[10] * m[13] + m[8] * m[5] * m[14] - m[8] * m[6] * m[13] - m[12] * m[5] * m[10] + m[12] * m[6] * m[9];
    a[1] = -m[1] * m[10] * m[15] + m[1] * m[11] * m[14] + m[9] * m[2] * m[15] - m[9] * m[3] * m[14] - m[13] * m[2] * m[11] + m[13] * m[3] * m[10];
    a[5] = m[0] * m[10] * m[15] - m[0] * m[11] * m[14] - m[8] * m[2] * m[15] + m[8] * m[3] * m[14] + m[12] * m[2] * m[11] - m[12] * m[3] * m[10];
    a[9] = -m[0] * m[9] * m[15] + m[0] * m[11] * m[13] + m[8] * m[1] * m[15] - m[8] * m[3] * m[13] - m[12] * m[1] * m[11] + m[12] * m[3] * m[9];
    a[13] = m[0] * m[9] * m[14] - m[0] * m[10] * m[13] - m[8] * m[1] * m[14] + m[8] * m[2] * m[13] + m[12] * m[1] * m[10] - m[12] * m[2] * m[9];
    a[2] = m[1] * m[6] * m[15] - m[1] * m[7] * m[14] - m[5] * m[2] * m[15] + m[5] * m[3] * m[14] + m[13] * m[2] * m[7] - m[13] * m[3] * m[6];
    a[6] = -m[0] * m[6] * m[15] + m[0] * m[7] * m[14] + m[4] * m[2] * m[15] - m[4] * m[3] * m[14] - m[12] * m[2] * m[7] + m[12] * m[3] * m[6];
    a[10] = m[0] * m[5] * m[15] - m[0] * m[7] * m[13] - m[4] * m[1] * m[15] + m[4] * m[3] * m[13] + m[12] * m[1] * m[7] - m[12] * m[3] * m[5];
    a[14] = -m[0] * m[5] * m[14] + m[0] * m[6] * m[13] + m[4] * m[1] * m[14] - m[4] * m[2] * m[13] - m[12] * m[1] * m[6] + m[12] * m[2] * m[5];
    a[3] = -m[1] * m[6] * m[11] + m[1] * m[7] * m[10] + m[5] * m[2] * m[11] - m[5] * m[3] * m[10] - m[9] * m[2] * m[7] + m[9] * m[3] * m[6];
    a[7] = m[0] * m[6] * m[11] - m[0] * m[7] * m[10] - m[4] * m[2] * m[11] + m[4] * m[3] * m[10] + m[8] * m[2] * m[7] - m[8] * m[3] * m[6];
    a[11] = -m[0] * m[5] * m[11] + m[0] * m[7] * m[9] + m[4] * m[1] * m[11] - m[4] * m[3] * m[9] - m[8] * m[1] * m[7] + m[8] * m[3] * m[5];
    a[15] = m[0] * m[5] * m[10] - m[0] * m[6] * m[9] - m[4] * m[1] * m[10] + m[4] * m[2] * m[9] + m[8] * m[1] * m[6] - m[8] * m[2] * m[5];
    det = m[0] * a[0] + m[1] * a[4] + m[2] * a[8] + m[3] * a[12];
    if (fabs(det) < 1e-12)
        return 0;
    for (int i = 0; i < 16; i++)
        inv[i] = a[i] / det;
    return 1;
}

static void mv_mult(struct lit *L, const double m[16])
{
    mat_mul(L->mv, L->mv, m);
}

static void lt_identity(struct lit *L)
{
    glLoadIdentity();
    mat_identity(L->mv);
}

static void lt_translate(struct lit *L, double x, double y, double z, int use_d)
{
    double m[16];
    if (use_d) {
        glTranslated(x, y, z);
    } else {
        x = (float)x, y = (float)y, z = (float)z;
        glTranslatef((GLfloat)x, (GLfloat)y, (GLfloat)z);
    }
    mat_identity(m);
    m[12] = x, m[13] = y, m[14] = z;
    mv_mult(L, m);
}

static void lt_scale(struct lit *L, double x, double y, double z, int use_d)
{
    double m[16];
    if (use_d) {
        glScaled(x, y, z);
    } else {
        x = (float)x, y = (float)y, z = (float)z;
        glScalef((GLfloat)x, (GLfloat)y, (GLfloat)z);
    }
    mat_identity(m);
    m[0] = x, m[5] = y, m[10] = z;
    mv_mult(L, m);
}

static void lt_rotate(struct lit *L, double a, double x, double y, double z, int use_d)
{
    double m[16], len, c, s;
    if (use_d) {
        glRotated(a, x, y, z);
    } else {
        a = (float)a, x = (float)x, y = (float)y, z = (float)z;
        glRotatef((GLfloat)a, (GLfloat)x, (GLfloat)y, (GLfloat)z);
    }
    len = sqrt(x * x + y * y + z * z);
    mat_identity(m);
    if (len == 0)
        return;
    x /= len, y /= len, z /= len;
    c = cos(a * PI / 180), s = sin(a * PI / 180);
    m[0] = x * x * (1 - c) + c;     m[4] = x * y * (1 - c) - z * s; m[8] = x * z * (1 - c) + y * s;
    m[1] = y * x * (1 - c) + z * s; m[5] = y * y * (1 - c) + c;     m[9] = y * z * (1 - c) - x * s;
    m[2] = x * z * (1 - c) - y * s; m[6] = y * z * (1 - c) + x * s; m[10] = z * z * (1 - c) + c;
    mv_mult(L, m);
}

/* glMultMatrix (or glLoadMatrix) of m, as floats or doubles. */
static void lt_matrix(struct lit *L, const double m[16], int use_d, int load)
{
    double md[16];
    GLfloat f[16];
    for (int i = 0; i < 16; i++) {
        f[i] = (GLfloat)m[i];
        md[i] = use_d ? m[i] : (double)f[i];
    }
    if (load) {
        if (use_d) glLoadMatrixd(m); else glLoadMatrixf(f);
        memcpy(L->mv, md, sizeof md);
    } else {
        if (use_d) glMultMatrixd(m); else glMultMatrixf(f);
        mv_mult(L, md);
    }
}

static void lt_push(struct lit *L)
{
    glPushMatrix();
    memcpy(L->stack[L->sp++ & 3], L->mv, sizeof L->mv);
}

static void lt_pop(struct lit *L)
{
    glPopMatrix();
    memcpy(L->mv, L->stack[--L->sp & 3], sizeof L->mv);
}

/* ---- small random helpers ---------------------------------------------- */

/* Three uniform values in [lo, hi), drawn in order (never several draws in
 * one argument list: their order would be unspecified). */
static void real3(fc_rng *r, double lo, double hi, double out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = fc_rng_real(r, lo, hi);
}

static void unit_vector(fc_rng *r, double v[3])
{
    double len;
    do {
        for (int i = 0; i < 3; i++)
            v[i] = fc_rng_real(r, -1, 1);
        len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    } while (len < 0.1 || len > 1);
    for (int i = 0; i < 3; i++)
        v[i] /= len;
}

/* Mostly towards the viewer (+z), so what is lit faces the eye. */
static void towards_viewer(fc_rng *r, double v[3], int percent)
{
    unit_vector(r, v);
    if (fc_rng_chance(r, percent) && v[2] < 0.25) {
        v[2] = fabs(v[2]) + 0.5;
        double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        for (int i = 0; i < 3; i++)
            v[i] /= len;
    }
}

/* A light colour component: 0, 1, above 1, negative, or in range. */
static double light_component(fc_rng *r, double scale)
{
    int k = (int)fc_rng_below(r, 100);
    return k < 6 ? 0.0 : k < 12 ? 1.0 : k < 18 ? (float)fc_rng_real(r, 1.0, 2.5)
         : k < 20 ? -(float)fc_rng_real(r, 0.0, 0.5) : (float)(fc_rng_real(r, 0.35, 1.0) * scale);
}

static double clampd(double v, double lo, double hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/* Float-to-integer of glLightiv / glMaterialiv colours (maps [-1,1]). */
static GLint color_int(double c)
{
    return (GLint)clampd(floor(c * 2147483647.0 + 0.5), -2147483647.0, 2147483647.0);
}

static int is_int(double v)
{
    return v == floor(v) && fabs(v) < 1e6;
}

/* glLight{f,i}[v] of a pname with n values. */
static void set_light(fc_rng *r, GLenum light, GLenum pname, const double *v, int n, int color)
{
    GLfloat f[4];
    GLint iv[4];
    int ints = 1, big = 1;
    for (int i = 0; i < n; i++) {
        f[i] = (GLfloat)v[i];
        iv[i] = color ? color_int(v[i]) : (GLint)clampd(floor(v[i] + 0.5), -1e9, 1e9);
        ints &= color ? fabs(v[i]) <= 1 : is_int(v[i]);
        big &= fabs(v[i]) >= 16 || v[i] == 0;
    }
    if (n == 1 && ints && fc_rng_chance(r, 50)) {
        glLighti(light, pname, iv[0]);
    } else if (n == 1 && fc_rng_chance(r, 70)) {
        glLightf(light, pname, f[0]);
    } else if ((ints || (!color && n > 1 && big)) && fc_rng_chance(r, color ? 25 : 40)) {
        glLightiv(light, pname, iv);     /* positions, directions: rounded */
    } else {
        glLightfv(light, pname, f);
    }
}

static void set_material(fc_rng *r, GLenum face, GLenum pname, const double *v)
{
    int n = pname == GL_SHININESS ? 1 : 4;
    GLfloat f[4];
    GLint iv[4];
    int ints = 1;
    for (int i = 0; i < n; i++) {
        f[i] = (GLfloat)v[i];
        iv[i] = n == 1 ? (GLint)v[i] : color_int(v[i]);
        ints &= n == 1 ? is_int(v[i]) : fabs(v[i]) <= 1;
    }
    if (n == 1) {
        int k = (int)fc_rng_below(r, 10);
        if (ints && k < 3) glMateriali(face, pname, iv[0]);
        else if (ints && k < 4) glMaterialiv(face, pname, iv);
        else if (k < 8) glMaterialf(face, pname, f[0]);
        else glMaterialfv(face, pname, f);
    } else if (ints && fc_rng_chance(r, 15)) {
        glMaterialiv(face, pname, iv);
    } else {
        glMaterialfv(face, pname, f);
    }
}

static void light_model_int(fc_rng *r, GLenum pname, GLint v)
{
    GLint iv[1] = { v };
    GLfloat f[1] = { (GLfloat)v };
    switch (fc_rng_below(r, 4)) {
    case 0: glLightModeli(pname, v); break;
    case 1: glLightModeliv(pname, iv); break;
    case 2: glLightModelf(pname, (GLfloat)v); break;
    default: glLightModelfv(pname, f); break;
    }
}

/* ---- lights -------------------------------------------------------------- */

/* The camera modelview (glLoadIdentity first unless it loads a matrix). */
static void issue_camera(struct lit *L)
{
    const struct camera *k = &L->cam;
    if (k->kind == CAM_GENERAL && k->load) {
        lt_matrix(L, k->m, k->mult_d, 1);
        return;
    }
    lt_identity(L);
    switch (k->kind) {
    case CAM_RIGID:
    case CAM_SCALED:
        lt_translate(L, k->t[0], k->t[1], k->t[2], k->use_d);
        for (int i = 0; i < k->nrot; i++)
            lt_rotate(L, k->rot[i][0], k->rot[i][1], k->rot[i][2], k->rot[i][3], k->use_d);
        if (k->kind == CAM_SCALED)
            lt_scale(L, k->scale[0], k->scale[1], k->scale[2], k->use_d);
        break;
    case CAM_LOOKAT:                /* gluLookAt's R * T(-eye), after T(centre + (0,0,D)) */
        lt_translate(L, k->lookat_t[0], k->lookat_t[1], k->lookat_t[2], k->use_d);
        lt_matrix(L, k->m, k->mult_d, 0);
        lt_translate(L, k->lookat_back[0], k->lookat_back[1], k->lookat_back[2], k->use_d);
        break;
    default:
        lt_matrix(L, k->m, k->mult_d, 0);
        break;
    }
}

/* An orthonormal rotation: rows side, up, back of a look-at from direction
 * dir; for flat regions only a turn about z (and a flip). */
static void lookat_rotation(struct lit *L, double m[16], double eye_dir[3])
{
    fc_rng *r = &L->s.r;
    double f[3], up[3], s[3], u[3], len;
    if (L->flat) {
        double a = fc_rng_real(r, 0, 2 * PI), flip = fc_rng_chance(r, 25) ? -1 : 1;
        mat_identity(m);
        m[0] = cos(a), m[1] = sin(a), m[4] = -sin(a) * flip, m[5] = cos(a) * flip, m[10] = flip;
        eye_dir[0] = eye_dir[1] = 0, eye_dir[2] = flip;
        return;
    }
    towards_viewer(r, eye_dir, 75);             /* eye = origin + D * eye_dir */
    for (int i = 0; i < 3; i++)
        f[i] = -eye_dir[i];                     /* forward */
    unit_vector(r, up);
    s[0] = f[1] * up[2] - f[2] * up[1];
    s[1] = f[2] * up[0] - f[0] * up[2];
    s[2] = f[0] * up[1] - f[1] * up[0];
    len = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    if (len < 1e-3) {
        s[0] = 1, s[1] = s[2] = 0, len = 1;
    }
    for (int i = 0; i < 3; i++)
        s[i] /= len;
    u[0] = s[1] * f[2] - s[2] * f[1];
    u[1] = s[2] * f[0] - s[0] * f[2];
    u[2] = s[0] * f[1] - s[1] * f[0];
    mat_identity(m);
    for (int i = 0; i < 3; i++) {
        m[i * 4 + 0] = s[i];
        m[i * 4 + 1] = u[i];
        m[i * 4 + 2] = -f[i];
    }
}

static void random_rotations(struct lit *L, struct camera *k)
{
    fc_rng *r = &L->s.r;
    if (!L->flat && fc_rng_chance(r, 75)) {     /* object z within 70 degrees of the eye */
        double a = fc_rng_real(r, 0, 2 * PI);
        k->nrot = 3;
        k->rot[0][0] = fc_rng_real(r, -180, 180);
        k->rot[1][0] = fc_rng_real(r, -70, 70);
        k->rot[2][0] = fc_rng_real(r, -180, 180);
        for (int i = 0; i < 3; i++)
            k->rot[i][1] = k->rot[i][2] = 0, k->rot[i][3] = 1;
        k->rot[1][1] = cos(a), k->rot[1][2] = sin(a), k->rot[1][3] = 0;
        return;
    }
    k->nrot = L->flat ? 1 + fc_rng_chance(r, 30) : fc_rng_range(r, 1, 3);
    for (int i = 0; i < k->nrot; i++) {
        double *q = k->rot[i];
        if (L->flat) {                          /* about z, or a flip about x or y */
            q[0] = i == 0 ? (fc_rng_chance(r, 30) ? 90.0 * fc_rng_range(r, 0, 3) : fc_rng_real(r, -360, 360)) : 180.0;
            q[1] = q[2] = q[3] = 0;
            int axis = i == 0 ? 3 : 1 + (int)fc_rng_below(r, 2);
            q[axis] = fc_rng_chance(r, 80) ? 1 : fc_rng_real(r, 0.2, 3);
        } else {
            q[0] = fc_rng_real(r, -360, 360);
            if (fc_rng_chance(r, 40)) {
                q[1] = q[2] = q[3] = 0;
                int axis = 1 + (int)fc_rng_below(r, 3);
                q[axis] = fc_rng_chance(r, 80) ? 1 : -2;
            } else {
                for (int j = 1; j < 4; j++)
                    q[j] = fc_rng_real(r, -2, 2);
            }
        }
    }
}

static void random_camera(struct lit *L)
{
    fc_rng *r = &L->s.r;
    struct camera *k = &L->cam;
    int pick = (int)fc_rng_below(&L->k, 100);   /* rigid or not: object- or eye-space lighting */
    memset(k, 0, sizeof *k);
    k->kind = pick < 40 ? CAM_RIGID : pick < 72 ? CAM_SCALED : pick < 90 ? CAM_LOOKAT : CAM_GENERAL;
    k->use_d = fc_rng_chance(r, 30);
    k->mult_d = fc_rng_chance(r, 50);
    memcpy(k->t, L->c, sizeof k->t);
    L->g[0] = L->g[1] = L->rxy;
    L->g[2] = L->rz;
    switch (k->kind) {
    case CAM_RIGID:
        random_rotations(L, k);
        break;
    case CAM_SCALED:
        random_rotations(L, k);
        for (int i = 0; i < 3; i++)
            k->scale[i] = L->g[i];
        if (fc_rng_chance(r, 40))               /* non-uniform */
            for (int i = 0; i < 3; i++)
                k->scale[i] *= fc_rng_real(r, 0.6, 1.3);
        if (fc_rng_chance(r, 15))               /* mirrored */
            k->scale[fc_rng_below(r, 3)] *= -1;
        L->g[0] = L->g[1] = L->g[2] = 1;
        break;
    case CAM_LOOKAT: {
        double dir[3], d = fc_rng_real(r, 1.5, 6.0) * L->rxy;
        lookat_rotation(L, k->m, dir);
        for (int i = 0; i < 3; i++) {
            k->lookat_t[i] = L->c[i] + (i == 2 ? d : 0);
            k->lookat_back[i] = -d * dir[i];
        }
        break;
    }
    default: {                                  /* affine: rotation x shear x scale, then T */
        double dir[3], sh[16], sc[16];
        lookat_rotation(L, k->m, dir);
        mat_identity(sh);
        mat_identity(sc);
        for (int i = 0; i < 3; i++)
            sc[i * 5] = L->g[i] * fc_rng_real(r, 0.7, 1.2);
        if (!L->flat) {
            sh[4] = fc_rng_real(r, -0.4, 0.4);
            sh[8] = fc_rng_real(r, -0.4, 0.4);
            sh[9] = fc_rng_real(r, -0.4, 0.4);
        } else {
            sh[4] = fc_rng_real(r, -0.4, 0.4);
        }
        mat_mul(k->m, k->m, sh);
        mat_mul(k->m, k->m, sc);
        for (int i = 0; i < 3; i++)
            k->m[12 + i] = L->c[i];
        k->load = fc_rng_chance(r, 40);
        L->g[0] = L->g[1] = L->g[2] = 1;
        break;
    }
    }
}

/* The modelview a light is given under. */
static void light_modelview(struct lit *L)
{
    fc_rng *r = &L->s.r;
    int k = (int)fc_rng_below(r, 100);
    double t[3];
    if (k < 20) {
        lt_identity(L);
    } else if (k < 45) {
        issue_camera(L);                        /* moves with the objects */
    } else if (k < 75) {                        /* look-at: rotations and translations */
        int use_d = fc_rng_chance(r, 30);
        lt_identity(L);
        if (fc_rng_chance(r, 50)) {
            double m[16], dir[3];
            lookat_rotation(L, m, dir);
            lt_matrix(L, m, use_d, 0);
        } else {
            for (int i = fc_rng_range(r, 1, 3); i > 0; i--) {
                double a = fc_rng_real(r, -180, 180), axis[3];
                real3(r, -1, 1, axis);
                lt_rotate(L, a, axis[0], axis[1], axis[2] + 0.01, use_d);
            }
        }
        real3(r, -2, 2, t);
        lt_translate(L, t[0] * L->rxy, t[1] * L->rxy, t[2] * L->rxy, use_d);
    } else if (k < 92) {                        /* scaled */
        int use_d = fc_rng_chance(r, 30);
        double s = fc_rng_real(r, 0.2, 5);
        lt_identity(L);
        lt_rotate(L, fc_rng_real(r, -180, 180), 0, 0, 1, use_d);
        if (fc_rng_chance(r, 50)) {
            lt_scale(L, s, s, s, use_d);
        } else {
            real3(r, 0.2, 5, t);
            lt_scale(L, s, t[1], (fc_rng_chance(r, 20) ? -1 : 1) * t[2], use_d);
        }
    } else {                                    /* general affine */
        double m[16];
        for (int i = 0; i < 16; i++)
            m[i] = (float)fc_rng_real(r, -2, 2);
        m[3] = m[7] = m[11] = 0;
        m[15] = 1;
        lt_identity(L);
        k = fc_rng_chance(r, 50);
        lt_matrix(L, m, k, fc_rng_chance(r, 50));
    }
}

/* Eye-space v (4D) back to the object space of the current modelview. */
static int to_object(const struct lit *L, const double eye[4], double obj[4])
{
    double inv[16];
    if (!mat_invert(L->mv, inv))
        return 0;
    mat_apply(inv, eye, obj);
    return 1;
}

static void random_light(struct lit *L, GLenum light, int nlights, int first)
{
    fc_rng *r = &L->s.r, *K = &L->k;
    double scale = fc_rng_real(r, 0.9, 1.5) / sqrt((double)nlights);
    /* structure: what the oracle's shader depends on */
    int type = (int)fc_rng_below(K, 100);          /* <40 directional, <72 positional, spot */
    int set_pos = fc_rng_chance(K, 95);
    int spot = type >= 72 || (type < 40 && fc_rng_chance(K, 8));
    int cutoff = (int)fc_rng_below(K, 100);
    int att = fc_rng_chance(K, 45), att0 = (int)fc_rng_below(K, 10);
    int att1 = fc_rng_chance(K, 60), att2 = fc_rng_chance(K, 50), att_none = fc_rng_chance(K, 90);
    int enable = fc_rng_chance(K, 93) || first;   /* at least one light on */
    double v[4], eye[4], obj[4], dir[3], dist = 0;

    light_modelview(L);
    /* colours */
    if (fc_rng_chance(r, 40)) {
        for (int i = 0; i < 3; i++)
            v[i] = fc_rng_chance(r, 90) ? (float)fc_rng_real(r, 0, 0.25) : light_component(r, 1);
        v[3] = fc_rng_chance(r, 70) ? 1.0 : (float)fc_rng_unit(r);
        set_light(r, light, GL_AMBIENT, v, 4, 1);
    }
    if (fc_rng_chance(r, 92)) {
        double grey = fc_rng_chance(r, 40) ? light_component(r, scale) : -1;
        for (int i = 0; i < 3; i++)
            v[i] = grey >= 0 ? grey : light_component(r, scale);
        v[3] = fc_rng_chance(r, 70) ? 1.0 : (float)fc_rng_unit(r);
        set_light(r, light, GL_DIFFUSE, v, 4, 1);
    }
    if (fc_rng_chance(r, 80)) {
        double grey = fc_rng_chance(r, 60) ? light_component(r, scale) : -1;
        for (int i = 0; i < 3; i++)
            v[i] = grey >= 0 ? grey : light_component(r, scale);
        v[3] = 1;
        set_light(r, light, GL_SPECULAR, v, 4, 1);
    }
    /* position, aimed at the lit region */
    if (type < 40) {
        towards_viewer(r, dir, 85);
        double len = fc_rng_chance(r, 50) ? 1.0 : fc_rng_real(r, 0.3, 20);
        for (int i = 0; i < 3; i++)
            eye[i] = dir[i] * len;
        eye[3] = 0;
    } else {
        towards_viewer(r, dir, 75);
        dist = fc_rng_real(r, 1.1, 4.0) * L->rxy;
        for (int i = 0; i < 3; i++)
            eye[i] = L->c[i] + dir[i] * dist;
        eye[3] = 1;
        int w = (int)fc_rng_below(r, 20);
        if (w < 3) {                                /* homogeneous w != 1 */
            double k = w == 0 ? -1.0 : w == 1 ? fc_rng_real(r, 0.25, 4) : -fc_rng_real(r, 0.5, 3);
            for (int i = 0; i < 4; i++)
                eye[i] *= k;
        }
    }
    if (set_pos && to_object(L, eye, obj)) {
        for (int i = 0; i < 4; i++)
            v[i] = (float)obj[i];
        set_light(r, light, GL_POSITION, v, 4, 0);
    }
    /* spot */
    if (spot) {
        double target[4] = { 0, 0, 0, 0 }, d[4], len = 0;
        int k = cutoff;
        for (int i = 0; i < 3; i++) {
            target[i] = L->c[i] + fc_rng_real(r, -0.5, 0.5) * L->rxy;
            d[i] = type < 40 ? -dir[i] : target[i] - eye[i] / eye[3];
            len += d[i] * d[i];
        }
        len = sqrt(len);
        double scale_dir = fc_rng_chance(r, 60) ? 1.0 / (len > 0 ? len : 1) : fc_rng_real(r, 0.1, 10);
        for (int i = 0; i < 3; i++)
            d[i] *= scale_dir;
        d[3] = 0;
        if (fc_rng_chance(r, 95) && to_object(L, d, obj)) {
            for (int i = 0; i < 3; i++)
                v[i] = (float)obj[i];
            set_light(r, light, GL_SPOT_DIRECTION, v, 3, 0);
        }
        if (k < 25) {                               /* about the size of the region */
            double half = atan(L->rxy / (dist > 0 ? dist : L->rxy)) * 180 / PI;
            v[0] = (float)clampd(half * fc_rng_real(r, 0.4, 1.3), 0, 90);
        } else {
            v[0] = k < 30 ? 0.0 : k < 40 ? 90.0 : k < 55 ? 180.0 : k < 65 ? fc_rng_range(r, 0, 90)
                 : (float)fc_rng_real(r, 5, 90);
        }
        set_light(r, light, GL_SPOT_CUTOFF, v, 1, 0);
        k = (int)fc_rng_below(r, 100);
        v[0] = k < 20 ? 0.0 : k < 30 ? 128.0 : k < 60 ? (float)fc_rng_real(r, 0, 128)
             : k < 70 ? fc_rng_range(r, 1, 128) : (float)fc_rng_real(r, 0, 10);
        set_light(r, light, GL_SPOT_EXPONENT, v, 1, 0);
    }
    /* attenuation (ignored by directional lights) */
    if (att) {
        double ref = dist > 0 ? dist : L->rxy, k[3];
        k[0] = att0 < 3 ? 1.0 : att0 < 5 ? 0.0 : (float)fc_rng_real(r, 0.2, 2);
        k[1] = att1 ? (float)fc_rng_real(r, 1e-3, 0.7 / ref) : 0.0;
        k[2] = att2 ? (float)fc_rng_real(r, 1e-3, 0.7 / (ref * ref)) : 0.0;
        if (k[0] == 0 && k[1] == 0 && k[2] == 0 && att_none)
            k[0] = att0 == 3 ? 1.0 : 0.5;       /* else all three 0: 1/0 */
        if (k[0] != 1 || fc_rng_chance(r, 20))
            set_light(r, light, GL_CONSTANT_ATTENUATION, &k[0], 1, 0);
        if (k[1] != 0 || fc_rng_chance(r, 20))
            set_light(r, light, GL_LINEAR_ATTENUATION, &k[1], 1, 0);
        if (k[2] != 0 || fc_rng_chance(r, 20))
            set_light(r, light, GL_QUADRATIC_ATTENUATION, &k[2], 1, 0);
    }
    if (enable)
        glEnable(light);
}

static void random_light_model(struct lit *L)
{
    fc_rng *r = &L->s.r;
    double v[4];
    int k = (int)fc_rng_below(r, 100);
    if (k >= 40) {
        for (int i = 0; i < 3; i++)
            v[i] = k < 55 ? 0.0 : k < 95 ? (float)fc_rng_real(r, 0, 0.35) : (float)fc_rng_real(r, 0, 1.5);
        v[3] = fc_rng_chance(r, 70) ? 1.0 : (float)fc_rng_unit(r);
        if (fc_rng_chance(r, 20)) {
            GLint iv[4];
            for (int i = 0; i < 4; i++)
                iv[i] = color_int(v[i]);
            glLightModeliv(GL_LIGHT_MODEL_AMBIENT, iv);
        } else {
            GLfloat f[4] = { (GLfloat)v[0], (GLfloat)v[1], (GLfloat)v[2], (GLfloat)v[3] };
            glLightModelfv(GL_LIGHT_MODEL_AMBIENT, f);
        }
    }
    k = (int)fc_rng_below(&L->k, 100);
    if (k < 35)
        light_model_int(r, GL_LIGHT_MODEL_LOCAL_VIEWER, k < 30 ? (fc_rng_chance(r, 80) ? 1 : 7) : 0);
    k = (int)fc_rng_below(&L->k, 100);
    if (k < 40)
        light_model_int(r, GL_LIGHT_MODEL_TWO_SIDE, k < 35 ? 1 : 0);
    k = (int)fc_rng_below(&L->k, 100);
    if (k < 30)
        light_model_int(r, GL_LIGHT_MODEL_COLOR_CONTROL, k < 25 ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
}

/* ---- GL 1.4 state (streams L->k14 and L->r14 only) -------------------- */

static const GLenum fog_modes[3] = { GL_LINEAR, GL_EXP, GL_EXP2 };

static void make_profile14(fc_rng *k, struct profile14 *p)
{
    p->fog = fc_rng_chance(k, 25) ? 1 + (int)fc_rng_below(k, 3) : 0;
    p->fogcoord = p->fog && fc_rng_chance(k, 50);
    p->seccolor = fc_rng_chance(k, 25);
    p->separate = fc_rng_chance(k, 15);
    p->unlit = fc_rng_chance(k, 20) ? fc_rng_range(k, 25, 75) : 0;
}

/* Fog, the fog coordinate source, colour sum and separate specular, after
 * the lights (place_region has set the region). */
static void random_state14(struct lit *L)
{
    const struct profile14 *p = &L->p14;
    fc_rng *r = &L->r14;
    /* the region's eye distances (the oracle's fragment depth is |z_eye|) */
    double zc = fabs(L->c[2]), span;
    L->fog_near = zc > L->rz ? zc - L->rz : 0.0;
    L->fog_far = zc + L->rz;
    span = L->fog_far - L->fog_near;
    if (p->fog) {
        GLfloat color[4];
        for (int i = 0; i < 4; i++)
            color[i] = (GLfloat)(fc_rng_chance(r, 15) ? (double)fc_rng_range(r, 0, 255) / 255.0
                                                      : fc_rng_unit(r));
        glEnable(GL_FOG);
        glFogi(GL_FOG_MODE, (GLint)fog_modes[p->fog - 1]);
        glFogfv(GL_FOG_COLOR, color);
        if (p->fog == 1) {
            double start = L->fog_near + span * fc_rng_real(r, -0.5, 0.6);
            double end = start + span * fc_rng_real(r, 0.3, 1.6);
            glFogf(GL_FOG_START, (GLfloat)start);
            glFogf(GL_FOG_END, (GLfloat)end);
        } else {
            double far = L->fog_far > 0 ? L->fog_far : 1.0;
            glFogf(GL_FOG_DENSITY, (GLfloat)(fc_rng_real(r, 0.1, p->fog == 2 ? 2.5 : 1.8) / far));
        }
    }
    if (p->fogcoord) {
        if (fc_rng_chance(r, 70))
            glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
        else
            glFogf(GL_FOG_COORD_SRC, (GLfloat)GL_FOG_COORD);
    }
    if (p->seccolor)
        glEnable(GL_COLOR_SUM);
    if (p->separate)
        light_model_int(r, GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
}

/* The current secondary colour and fog coordinate, before a glBegin. */
static void random_attribs14(struct lit *L)
{
    const struct profile14 *p = &L->p14;
    fc_rng *r = &L->r14;
    if (p->seccolor && fc_rng_chance(r, 70)) {
        double c[3];
        for (int i = 0; i < 3; i++)
            c[i] = fc_rng_chance(r, 20) ? (double)fc_rng_range(r, 0, 255) / 255.0 : fc_rng_unit(r) * 0.6;
        switch (fc_rng_below(r, 4)) {
        case 0:
            glSecondaryColor3f((GLfloat)c[0], (GLfloat)c[1], (GLfloat)c[2]);
            break;
        case 1: {
            const GLfloat f[3] = { (GLfloat)c[0], (GLfloat)c[1], (GLfloat)c[2] };
            glSecondaryColor3fv(f);
            break;
        }
        case 2:
            glSecondaryColor3ub((GLubyte)(c[0] * 255.0 + 0.5), (GLubyte)(c[1] * 255.0 + 0.5),
                                (GLubyte)(c[2] * 255.0 + 0.5));
            break;
        default:
            if (fc_rng_chance(r, 20))       /* out of range: clamped after the sum */
                c[fc_rng_below(r, 3)] = fc_rng_real(r, -0.5, 1.5);
            glSecondaryColor3dv(c);
            break;
        }
    }
    if (p->fogcoord && fc_rng_chance(r, 70)) {
        const double span = L->fog_far - L->fog_near;
        const double f = fc_rng_chance(r, 10) ? -fc_rng_real(r, 0.0, L->fog_far + 0.1)
                                              : L->fog_near + span * fc_rng_real(r, -0.2, 1.2);
        const GLfloat ff = (GLfloat)f;
        switch (fc_rng_below(r, 4)) {
        case 0: glFogCoordf(ff); break;
        case 1: glFogCoordd(f); break;
        case 2: glFogCoordfv(&ff); break;
        default: glFogCoorddv(&f); break;
        }
    }
}

static void lit_begin(struct lit *L, GLenum mode)
{
    random_attribs14(L);
    glBegin(mode);
}

/* ---- materials --------------------------------------------------------- */

/* zero: 0 from the structure stream (Mesa specialises shininess 0). */
static double shininess(fc_rng *r, int zero)
{
    int k = (int)fc_rng_below(r, 85);
    return zero ? 0.0 : k < 10 ? 0.5 : k < 25 ? 128.0 : k < 55 ? (float)fc_rng_real(r, 1e-3, 128)
         : k < 70 ? fc_rng_range(r, 1, 60) : (float)fc_rng_real(r, 1, 40);
}

static void random_hue(fc_rng *r, double c[4], double lo, double hi)
{
    for (int i = 0; i < 3; i++)
        c[i] = (float)fc_rng_real(r, lo, hi);
    int k = (int)fc_rng_below(r, 3);
    c[k] = (float)fc_rng_real(r, 0.6, 1.0);
    if (fc_rng_chance(r, 5)) {
        k = (int)fc_rng_below(r, 3);
        c[k] = fc_rng_chance(r, 50) ? 0.0 : (float)fc_rng_real(r, 1, 1.5);
    }
    c[3] = fc_rng_chance(r, 60) ? 1.0 : (float)fc_rng_unit(r);
}

static void random_material(struct lit *L, GLenum face)
{
    fc_rng *r = &L->s.r;
    double diff[4], v[4];
    int set_shininess = fc_rng_chance(&L->k, 85), zero = fc_rng_chance(&L->k, 15);
    int k;
    random_hue(r, diff, 0.05, 0.9);
    k = (int)fc_rng_below(r, 100);
    if (k < 20) {
        set_material(r, face, GL_AMBIENT_AND_DIFFUSE, diff);
    } else {
        if (k < 80) {
            double a = fc_rng_real(r, 0.1, 1.0);
            for (int i = 0; i < 3; i++)
                v[i] = (float)(diff[i] * a);
            v[3] = fc_rng_chance(r, 70) ? 1.0 : (float)fc_rng_unit(r);
            set_material(r, face, GL_AMBIENT, v);
        }
        set_material(r, face, GL_DIFFUSE, diff);
    }
    k = (int)fc_rng_below(r, 100);
    if (k >= 25) {
        double grey = (float)fc_rng_real(r, 0.2, 1.0);
        for (int i = 0; i < 3; i++)
            v[i] = k < 75 ? grey : (float)fc_rng_real(r, 0, 1.0);
        v[3] = 1;
        set_material(r, face, GL_SPECULAR, v);
    }
    if (fc_rng_chance(r, 20)) {
        for (int i = 0; i < 3; i++)
            v[i] = (float)fc_rng_real(r, 0, 0.3);
        v[3] = fc_rng_unit(r);
        set_material(r, face, GL_EMISSION, v);
    }
    if (set_shininess) {
        v[0] = shininess(r, zero);
        set_material(r, face, GL_SHININESS, v);
    }
}

static const GLenum material_pnames[6] = {
    GL_DIFFUSE, GL_AMBIENT_AND_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS, GL_AMBIENT
};

/* One glMaterial between glBegin and glEnd. */
static void material_in_begin(struct lit *L)
{
    const GLenum *pnames = material_pnames;
    fc_rng *r = &L->s.r;
    GLenum pname = L->dynamic ? pnames[fc_rng_below(r, 6)] : L->mat_pname;
    int face = L->dynamic ? (int)fc_rng_below(r, 2) : L->mat_face;
    double v[4];
    if (pname == GL_SHININESS) {
        v[0] = shininess(r, fc_rng_chance(r, 15));
    } else {
        random_hue(r, v, 0.0, 0.9);
        if (pname == GL_EMISSION)
            for (int i = 0; i < 3; i++)
                v[i] = (float)(v[i] * 0.3);
    }
    set_material(r, L->faces[face], pname, v);
}

/* ---- per-vertex attributes ---------------------------------------------- */

static double iround(double v, double lo, double hi)
{
    return clampd(floor(v + 0.5), lo, hi);
}

static void emit_normal(struct lit *L, const double n[3])
{
    fc_rng *r = &L->s.r;
    int k = (int)fc_rng_below(r, 100), vec = fc_rng_chance(r, 50);
    if (k < 35) {
        GLfloat f[3] = { (GLfloat)n[0], (GLfloat)n[1], (GLfloat)n[2] };
        if (vec) glNormal3fv(f); else glNormal3f(f[0], f[1], f[2]);
    } else if (k < 60) {
        if (vec) glNormal3dv(n); else glNormal3d(n[0], n[1], n[2]);
    } else if (k < 75) {
        GLbyte b[3];
        for (int i = 0; i < 3; i++)
            b[i] = (GLbyte)iround(n[i] * 127.0, -128, 127);
        if (vec) glNormal3bv(b); else glNormal3b(b[0], b[1], b[2]);
    } else if (k < 88) {
        GLshort s[3];
        for (int i = 0; i < 3; i++)
            s[i] = (GLshort)iround(n[i] * 32767.0, -32768, 32767);
        if (vec) glNormal3sv(s); else glNormal3s(s[0], s[1], s[2]);
    } else {
        GLint iv[3];
        for (int i = 0; i < 3; i++)
            iv[i] = (GLint)iround(n[i] * 2147483647.0, -2147483648.0, 2147483647.0);
        if (vec) glNormal3iv(iv); else glNormal3i(iv[0], iv[1], iv[2]);
    }
}

/* glColor of c through a float, double or ubyte variant, with 4 or 3
 * components (one size per draw: the oracle compiles a vertex fetch per
 * attribute size). */
static void emit_rgba(fc_rng *r, const double c[4], int four)
{
    int k = 2 * (int)fc_rng_below(r, 4) + (four ? 1 : 0);
    GLfloat f[4] = { (GLfloat)c[0], (GLfloat)c[1], (GLfloat)c[2], (GLfloat)c[3] };
    GLubyte ub[4];
    for (int i = 0; i < 4; i++)
        ub[i] = (GLubyte)iround(c[i] * 255.0, 0, 255);
    switch (k) {
    case 0: glColor3f(f[0], f[1], f[2]); break;
    case 1: glColor4f(f[0], f[1], f[2], f[3]); break;
    case 2: glColor3fv(f); break;
    case 3: glColor4fv(f); break;
    case 4: glColor3dv(c); break;
    case 5: glColor4d(c[0], c[1], c[2], c[3]); break;
    case 6: glColor3ub(ub[0], ub[1], ub[2]); break;
    default: glColor4ubv(ub); break;
    }
}

/* ---- patches ----------------------------------------------------------- */

struct patch {
    int nu, nv;                     /* cells */
    double p[MAXGRID + 1][MAXGRID + 1][3];
    double n[MAXGRID + 1][MAXGRID + 1][3];
    double col[MAXGRID + 1][MAXGRID + 1][4];
};


static void build_patch(struct lit *L, struct patch *P, int type, int max_cells)
{
    fc_rng *r = &L->s.r;
    double hue[4];
    int nu = fc_rng_range(r, 2, 10), nv = fc_rng_range(r, 2, MAXGRID);
    while (nu * nv > max_cells)
        nu > 2 ? nu-- : nv--;
    P->nu = nu, P->nv = nv;
    random_hue(r, hue, 0.1, 1.0);
    if (type == 0) {                /* sphere section; u = theta, v = phi */
        double rho = fc_rng_real(r, 0.7, 1.0), t0 = 0, t1 = PI / 2, p0 = 0, p1 = 2 * PI;
        int inside = fc_rng_chance(r, 8) ? -1 : 1, k = (int)fc_rng_below(r, 100);
        if (k < 25) {                           /* a window */
            t0 = fc_rng_real(r, 0, 1.2), t1 = t0 + fc_rng_real(r, 0.6, 1.8);
            p0 = fc_rng_real(r, 0, 2 * PI), p1 = p0 + fc_rng_real(r, 1.2, 2 * PI);
        } else if (k < 65) {                    /* the whole sphere */
            t1 = PI;
        }
        for (int i = 0; i <= nu; i++)
            for (int j = 0; j <= nv; j++) {
                double t = t0 + (t1 - t0) * i / nu, ph = p0 + (p1 - p0) * j / nv;
                double d[3] = { sin(t) * cos(ph), sin(t) * sin(ph), cos(t) };
                for (int k = 0; k < 3; k++) {
                    P->p[i][j][k] = rho * d[k];
                    P->n[i][j][k] = inside * d[k];
                }
            }
    } else if (type == 1) {         /* height field over [-a,a]^2; u = x, v = y */
        double a = fc_rng_real(r, 0.5, 0.95), h = fc_rng_real(r, -0.6, 0.6), w = fc_rng_real(r, 1, 5);
        int wave = fc_rng_chance(r, 40);
        for (int i = 0; i <= nu; i++)
            for (int j = 0; j <= nv; j++) {
                double x = -a + 2 * a * i / nu, y = -a + 2 * a * j / nv, z, hx, hy;
                if (wave) {
                    z = h * sin(w * x) * cos(w * y);
                    hx = h * w * cos(w * x) * cos(w * y);
                    hy = -h * w * sin(w * x) * sin(w * y);
                } else {
                    z = h * (1 - x * x - y * y);
                    hx = -2 * h * x;
                    hy = -2 * h * y;
                }
                P->p[i][j][0] = x, P->p[i][j][1] = y, P->p[i][j][2] = z;
                P->n[i][j][0] = -hx, P->n[i][j][1] = -hy, P->n[i][j][2] = 1;
            }
    } else {                        /* cylinder band about y; u = y, v = phi */
        double rho = fc_rng_real(r, 0.4, 0.9), y0 = -fc_rng_real(r, 0.3, 0.9), y1 = fc_rng_real(r, 0.3, 0.9);
        double p0 = fc_rng_real(r, -PI, 0), p1 = p0 + fc_rng_real(r, PI / 2, 2 * PI);
        for (int i = 0; i <= nu; i++)
            for (int j = 0; j <= nv; j++) {
                double y = y0 + (y1 - y0) * i / nu, ph = p0 + (p1 - p0) * j / nv;
                P->p[i][j][0] = rho * sin(ph), P->p[i][j][1] = y, P->p[i][j][2] = rho * cos(ph);
                P->n[i][j][0] = sin(ph), P->n[i][j][1] = 0, P->n[i][j][2] = cos(ph);
            }
    }
    for (int i = 0; i <= nu; i++)
        for (int j = 0; j <= nv; j++) {
            double u = (double)i / nu, v = (double)j / nv;
            P->col[i][j][0] = clampd(hue[0] * (0.4 + 0.6 * u), 0, 1);
            P->col[i][j][1] = clampd(hue[1] * (0.4 + 0.6 * v), 0, 1);
            P->col[i][j][2] = clampd(hue[2] * (1.0 - 0.5 * u * v), 0, 1);
            P->col[i][j][3] = hue[3];
        }
}

/* Issues the attributes then the vertex at p (object units) with normal n. */
static void emit_attr_vertex(struct lit *L, const struct npolicy *np, const double p[3],
                             const double n[3], const double col[4], int first)
{
    fc_rng *r = &L->s.r;
    double nn[3], v[4];
    if (np->materials && fc_rng_chance(r, np->materials))
        material_in_begin(L);
    if (np->colors == 1 || (np->colors == 3 && first)) {
        emit_rgba(r, col, np->color4);
    } else if (np->colors == 2) {
        fcr_emit_color(&L->s);
    }
    if (np->mode == 0 || np->mode == 1 || np->mode == 5 || (np->mode == 3 && first)) {
        for (int i = 0; i < 3; i++)
            nn[i] = n[i] * np->scale;
        if (np->mode == 1)
            for (int i = 0; i < 3; i++)
                nn[i] += fc_rng_real(r, -0.3, 0.3);
        if (np->mode == 5)
            unit_vector(r, nn);
        if (np->vary)
            for (int i = 0; i < 3; i++)
                nn[i] *= fc_rng_real(r, 0.1, 3.0);
        if (np->zero && fc_rng_chance(r, np->zero))
            nn[0] = nn[1] = nn[2] = 0;
        emit_normal(L, nn);
    }
    for (int i = 0; i < 3; i++)
        v[i] = p[i] * L->g[i] * np->w;
    v[3] = np->w;
    fcr_emit_vertex(&L->s, v, np->w != 1 ? 4 : 3);
}

#define GV(P, i, j) (P)->p[i][j], (P)->n[i][j], (P)->col[i][j]

/* A face (cell) normal: the mean of its corners. */
static void face_normal(const struct patch *P, int i, int j, double out[3])
{
    for (int k = 0; k < 3; k++)
        out[k] = 0.25 * (P->n[i][j][k] + P->n[i + 1][j][k] + P->n[i + 1][j + 1][k] + P->n[i][j + 1][k]);
}

static void draw_grid(struct lit *L, const struct patch *P, const struct npolicy *np, GLenum mode)
{
    double fn[3];
    int nu = P->nu, nv = P->nv;
    if ((mode == GL_POLYGON || mode == GL_TRIANGLE_FAN) && nu * nv > 24)
        mode = GL_QUADS;
    switch (mode) {
    case GL_QUAD_STRIP:
    case GL_TRIANGLE_STRIP:
        for (int j = 0; j < nv; j++) {
            lit_begin(L, mode);
            for (int i = 0; i <= nu; i++) {
                emit_attr_vertex(L, np, GV(P, i, j + 1), i == 0);
                emit_attr_vertex(L, np, GV(P, i, j), 0);
            }
            glEnd();
        }
        break;
    case GL_QUADS:
    case GL_TRIANGLES:
        lit_begin(L, mode);
        for (int j = 0; j < nv; j++)
            for (int i = 0; i < nu; i++) {
                const double *n = P->n[i][j];
                if (np->mode == 3) {
                    face_normal(P, i, j, fn);
                    n = fn;
                }
                if (mode == GL_QUADS) {
                    emit_attr_vertex(L, np, P->p[i][j], n, P->col[i][j], 1);
                    emit_attr_vertex(L, np, GV(P, i + 1, j), 0);
                    emit_attr_vertex(L, np, GV(P, i + 1, j + 1), 0);
                    emit_attr_vertex(L, np, GV(P, i, j + 1), 0);
                } else {
                    emit_attr_vertex(L, np, P->p[i][j], n, P->col[i][j], 1);
                    emit_attr_vertex(L, np, GV(P, i + 1, j), 0);
                    emit_attr_vertex(L, np, GV(P, i + 1, j + 1), 0);
                    emit_attr_vertex(L, np, P->p[i][j], n, P->col[i][j], 1);
                    emit_attr_vertex(L, np, GV(P, i + 1, j + 1), 0);
                    emit_attr_vertex(L, np, GV(P, i, j + 1), 0);
                }
            }
        glEnd();
        break;
    default:                        /* one polygon or fan per cell */
        for (int j = 0; j < nv; j++)
            for (int i = 0; i < nu; i++) {
                const double *n = P->n[i][j];
                if (np->mode == 3) {
                    face_normal(P, i, j, fn);
                    n = fn;
                }
                lit_begin(L, mode);
                emit_attr_vertex(L, np, P->p[i][j], n, P->col[i][j], 1);
                emit_attr_vertex(L, np, GV(P, i + 1, j), 0);
                emit_attr_vertex(L, np, GV(P, i + 1, j + 1), 0);
                emit_attr_vertex(L, np, GV(P, i, j + 1), 0);
                glEnd();
            }
        break;
    }
}

/* A cap: a fan around a centre (or a convex polygon), CCW about +z. */
static void draw_cap(struct lit *L, const struct npolicy *np, GLenum mode)
{
    fc_rng *r = &L->s.r;
    int k = fc_rng_range(r, 5, 24);
    double rho = fc_rng_real(r, 0.5, 0.95), h = fc_rng_real(r, -0.5, 0.8), tilt = fc_rng_real(r, 0.2, 2.0);
    double a0 = fc_rng_real(r, 0, 2 * PI), hue[4], col[4];
    int closed = mode == GL_TRIANGLE_FAN;
    random_hue(r, hue, 0.1, 1.0);
    lit_begin(L, mode);
    if (mode == GL_TRIANGLE_FAN) {
        double p[3] = { 0, 0, h }, n[3] = { 0, 0, 1 };
        emit_attr_vertex(L, np, p, n, hue, 1);
    }
    for (int i = 0; i < k + closed; i++) {
        double a = a0 + 2 * PI * i / k;
        double p[3] = { rho * cos(a), rho * sin(a), 0 }, n[3] = { tilt * cos(a), tilt * sin(a), 1 };
        for (int c = 0; c < 3; c++)
            col[c] = clampd(hue[c] * (0.6 + 0.4 * cos(a + c)), 0, 1);
        col[3] = hue[3];
        emit_attr_vertex(L, np, p, n, col, i == 0 && mode == GL_POLYGON);
    }
    glEnd();
}

/* Which attributes are per vertex is structure (the oracle's shader
 * depends on it); the values are not. */
static void random_npolicy(struct lit *L, struct npolicy *np)
{
    fc_rng *r = &L->s.r, *K = &L->k;
    int k = (int)fc_rng_below(K, 100);
    int scaled = fc_rng_chance(K, 35), vary = fc_rng_chance(K, 12), zero = fc_rng_chance(K, 12);
    int colors = (int)fc_rng_below(K, 100), materials = fc_rng_chance(K, 15);
    int mfreq = fc_rng_range(K, 5, 30), w = fc_rng_chance(K, 5), color4 = fc_rng_chance(K, 60);
    memset(np, 0, sizeof *np);
    np->mode = k < 55 ? 0 : k < 68 ? 1 : k < 78 ? 2 : k < 90 ? 3 : k < 95 ? 4 : 5;
    np->scale = scaled ? fc_rng_real(r, 0.2, 4.0) : 1.0;
    np->vary = vary;
    np->zero = zero ? 10 : 0;
    if (L->color_material)
        np->colors = colors < 60 ? 1 : colors < 80 ? 2 : 3;
    else
        np->colors = colors < 20 ? 1 : colors < 27 ? 2 : 0;
    np->color4 = color4;
    np->materials = materials ? mfreq : 0;
    np->w = w ? (float)fc_rng_real(r, 0.5, 2.0) : 1.0;
}

/* Between patches: toggles of the state lighting depends on. */
static void random_toggles(struct lit *L)
{
    fc_rng *r = &L->s.r, *K = &L->k;
    if (fc_rng_chance(K, 12)) {
        int k = (int)fc_rng_below(K, 4);
        if (k == 0) glEnable(GL_NORMALIZE);
        else if (k == 1) glDisable(GL_NORMALIZE);
        else if (k == 2) glEnable(GL_RESCALE_NORMAL);
        else glDisable(GL_RESCALE_NORMAL);
    }
    if (fc_rng_chance(K, 10))
        glShadeModel(fc_rng_chance(K, 70) ? GL_SMOOTH : GL_FLAT);
    if (fc_rng_chance(K, 8))
        glFrontFace(fc_rng_chance(K, 50) ? GL_CW : GL_CCW);
    if (fc_rng_chance(K, 6)) {
        L->color_material = !L->color_material;
        if (L->color_material) glEnable(GL_COLOR_MATERIAL); else glDisable(GL_COLOR_MATERIAL);
    }
    if (fc_rng_chance(K, 5))
        light_model_int(r, GL_LIGHT_MODEL_TWO_SIDE, (GLint)fc_rng_below(K, 2));
    if (fc_rng_chance(K, 5))
        glEnable(GL_LIGHT0 + fc_rng_below(K, 8));
    if (fc_rng_chance(K, 4)) {
        L->lighting = !L->lighting;
        if (L->lighting) glEnable(GL_LIGHTING); else glDisable(GL_LIGHTING);
    } else if (!L->lighting && fc_rng_chance(K, 70)) {
        L->lighting = 1;
        glEnable(GL_LIGHTING);
    }
    if (fc_rng_chance(K, 5))
        random_material(L, L->faces[fc_rng_below(K, 2)]);
}

static void random_patch(struct lit *L, int npatches)
{
    fc_rng *r = &L->s.r, *K = &L->k;
    struct patch P;
    struct npolicy np;
    int type = (int)fc_rng_below(r, 100), pushed = 0;
    GLenum mode = fcr_modes[fc_rng_below(K, 6)];
    int place = npatches > 1 || fc_rng_chance(K, 20), unlit;

    np = L->np;
    if (L->dynamic) {
        random_toggles(L);
        if (fc_rng_chance(K, 50))
            random_npolicy(L, &np);
    }
    /* GL 1.4 profile: a patch with lighting off (the primary colour is the
     * current colour, the secondary the current secondary colour) */
    unlit = L->p14.unlit && L->lighting && fc_rng_chance(&L->k14, L->p14.unlit);
    if (unlit)
        glDisable(GL_LIGHTING);
    if (place) {                    /* a place of its own in the region (scaled) */
        double sc = npatches > 1 ? fc_rng_real(r, 0.55, 0.85) : fc_rng_real(r, 0.75, 1.0);
        int use_d = fc_rng_chance(r, 30);
        double t[3], a;
        lt_push(L);
        pushed = 1;
        real3(r, -0.5, 0.5, t);
        lt_translate(L, t[0] * L->g[0], t[1] * L->g[1], 0, use_d);
        if (!L->flat && fc_rng_chance(r, 60)) {
            a = fc_rng_real(r, -180, 180);
            real3(r, -1, 1, t);
            lt_rotate(L, a, t[0], t[1], t[2], use_d);
        } else if (fc_rng_chance(r, 50)) {
            lt_rotate(L, fc_rng_real(r, -180, 180), 0, 0, 1, use_d);
        }
        if (fc_rng_chance(r, 70)) {
            lt_scale(L, sc, sc, sc, use_d);
        } else {
            real3(r, 0.6, 1.4, t);
            lt_scale(L, sc * t[0], sc * t[1], sc * t[2], use_d);
        }
    }
    if (np.mode == 2 || (np.mode == 3 && mode != GL_QUADS && mode != GL_TRIANGLES &&
                         mode != GL_POLYGON && mode != GL_TRIANGLE_FAN)) {
        double n[3];
        towards_viewer(r, n, 70);
        for (int i = 0; i < 3; i++)
            n[i] *= np.scale;
        emit_normal(L, n);
        np.mode = 2;
    }
    if (type < 15) {
        draw_cap(L, &np, fc_rng_chance(r, 70) ? GL_TRIANGLE_FAN : GL_POLYGON);
    } else {
        build_patch(L, &P, type < 60 ? 0 : type < 85 ? 1 : 2, npatches > 2 ? 40 : 80);
        draw_grid(L, &P, &np, mode);
    }
    if (pushed)
        lt_pop(L);
    if (unlit)
        glEnable(GL_LIGHTING);
}

/* ---- the scene ----------------------------------------------------------- */

/* A mostly dark clear colour and a clear depth that lets the scene through
 * (fcr_clear's depths 0, -1, 1/3... would hide most lit scenes). */
static void lit_clear(fc_rng *r, GLbitfield bits, GLenum depth_func)
{
    double c[4], d;
    int k = (int)fc_rng_below(r, 100);
    for (int i = 0; i < 4; i++)
        c[i] = fc_rng_real(r, 0, k < 80 ? 0.3 : 1.0);
    k = (int)fc_rng_below(r, 100);
    d = k < 85 ? 1.0 : k < 95 ? fc_rng_real(r, 0.97, 1.0) : 2.0;
    if (depth_func == GL_GREATER || depth_func == GL_GEQUAL)
        d = 1 - d;
    glClearColor((GLfloat)c[0], (GLfloat)c[1], (GLfloat)c[2], (GLfloat)c[3]);
    glClearDepth(d);
    glClear(bits);
}

/* An ortho box or a frustum of about the viewport's aspect (the plain
 * generator's may be 40 times wider than high), now and then loaded as a
 * matrix; pixel space as the plain generator. */
static void lit_projection(struct lit *L)
{
    struct scene *s = &L->s;
    fc_rng *r = &s->r;
    double aspect = (double)s->vh / s->vw, e[6], m[16];
    int load = fc_rng_chance(r, 10);
    if (s->space == SP_PIXEL) {
        fcr_projection(s);
        return;
    }
    if (s->space == SP_BOX) {
        double cx = fc_rng_real(r, -50, 50), cy = fc_rng_real(r, -50, 50), hw = fc_rng_real(r, 0.5, 60);
        double hh = hw * aspect * fc_rng_real(r, 0.7, 1.4);
        double n = fc_rng_real(r, -50, 50), f = n + fc_rng_real(r, 0.1, 2.0) * hw + fc_rng_real(r, 0, 50);
        e[0] = cx - hw, e[1] = cx + hw, e[2] = cy - hh, e[3] = cy + hh, e[4] = n, e[5] = f;
        if (fc_rng_chance(r, 10)) {             /* mirrored */
            double t = e[0];
            e[0] = e[1], e[1] = t;
        }
    } else {
        double n = fc_rng_real(r, 0.05, 3.0), f = n + fc_rng_real(r, 0.5, 200.0);
        double hw = fc_rng_real(r, 0.15, 1.5) * n, hh = hw * aspect * fc_rng_real(r, 0.7, 1.4);
        double ox = fc_rng_real(r, -0.6, 0.6) * hw, oy = fc_rng_real(r, -0.6, 0.6) * hh;
        e[0] = ox - hw, e[1] = ox + hw, e[2] = oy - hh, e[3] = oy + hh, e[4] = n, e[5] = f;
    }
    for (int i = 0; i < 6; i++)
        e[i] = (float)e[i];
    memcpy(s->space == SP_BOX ? s->box : s->fr, e, sizeof e);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    if (load) {
        double w = e[1] - e[0], h = e[3] - e[2], d = e[5] - e[4];
        memset(m, 0, sizeof m);
        if (s->space == SP_BOX) {
            m[0] = 2 / w, m[5] = 2 / h, m[10] = -2 / d;
            m[12] = -(e[1] + e[0]) / w, m[13] = -(e[3] + e[2]) / h, m[14] = -(e[5] + e[4]) / d, m[15] = 1;
        } else {
            m[0] = 2 * e[4] / w, m[5] = 2 * e[4] / h;
            m[8] = (e[1] + e[0]) / w, m[9] = (e[3] + e[2]) / h, m[10] = -(e[5] + e[4]) / d, m[11] = -1;
            m[14] = -2 * e[5] * e[4] / d;
        }
        fcr_load_or_mult(r, m);
    } else if (s->space == SP_BOX) {
        glOrtho(e[0], e[1], e[2], e[3], e[4], e[5]);
    } else {
        glFrustum(e[0], e[1], e[2], e[3], e[4], e[5]);
    }
    glMatrixMode(GL_MODELVIEW);
}

/* Where the lit region lies in eye space, from the projection. */
static void place_region(struct lit *L)
{
    struct scene *s = &L->s;
    fc_rng *r = &s->r;
    switch (s->space) {
    case SP_PIXEL:
        L->c[0] = s->vw * fc_rng_real(r, 0.35, 0.65);
        L->c[1] = s->vh * fc_rng_real(r, 0.35, 0.65);
        L->c[2] = 0;
        L->rxy = (s->vw < s->vh ? s->vw : s->vh) * fc_rng_real(r, 0.35, 0.55);
        L->rz = 0.9;
        break;
    case SP_BOX: {
        double wx = fabs(s->box[1] - s->box[0]), wy = fabs(s->box[3] - s->box[2]);
        L->c[0] = 0.5 * (s->box[0] + s->box[1]);
        L->c[1] = 0.5 * (s->box[2] + s->box[3]);
        L->c[2] = -0.5 * (s->box[4] + s->box[5]);
        L->rxy = 0.5 * (wx < wy ? wx : wy) * fc_rng_real(r, 0.65, 1.0);
        L->rz = 0.45 * fabs(s->box[5] - s->box[4]);
        break;
    }
    case SP_FRUSTUM: {
        double n = s->fr[4], f = s->fr[5], dmax = f < 6 * n ? f : 6 * n;
        double d = n + (dmax - n) * fc_rng_real(r, 0.35, 0.85);
        double hw = d * (s->fr[1] - s->fr[0]) / (2 * n), hh = d * (s->fr[3] - s->fr[2]) / (2 * n);
        L->c[0] = d * (s->fr[0] + s->fr[1]) / (2 * n);
        L->c[1] = d * (s->fr[2] + s->fr[3]) / (2 * n);
        L->c[2] = -d;
        L->rxy = (hw < hh ? hw : hh) * fc_rng_real(r, 0.65, 1.0);
        L->rz = 0.9 * ((d - n) < (f - d) ? (d - n) : (f - d));
        break;
    }
    default:
        L->c[0] = L->c[1] = L->c[2] = 0;
        L->rxy = L->rz = 1;
        break;
    }
    if (L->rz > L->rxy)
        L->rz = L->rxy;
    L->flat = L->rz < 0.6 * L->rxy;
    if (!L->flat)
        L->rxy = L->rz;             /* a ball: any rotation stays inside */
}

static void lit_scene(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    struct lit L;
    fc_rng *r, *K;
    uint64_t seed;
    uint32_t index;
    int k, nlights, npatches;
    GLenum order[8], depth_func;

    memset(&L, 0, sizeof L);
    fc_lit_gl_load();
    fc_random_lit_parse(c->name, &seed, &index);
    r = &L.s.r;
    *r = fc_rng_make(seed, index, 4);
    K = &L.k;
    *K = fc_rng_make(seed, index % FC_LIT_PROFILES, 5);
    L.k14 = fc_rng_make(seed, index % FC_LIT_PROFILES, 81);
    make_profile14(&L.k14, &L.p14);
    L.r14 = fc_rng_make(seed, index, 82);
    fce_scene_begin(FCE_LIT, seed, index, index % FC_LIT_PROFILES);
    L.s.w = c->width;
    L.s.h = c->height;
    k = (int)fc_rng_below(r, 100);
    L.s.space = k < 22 ? SP_PIXEL : k < 45 ? SP_BOX : SP_FRUSTUM;
    mat_identity(L.mv);

    k = (int)fc_rng_below(K, 100);          /* depth functions that let the scene through */
    depth_func = k < 45 ? GL_LESS : k < 80 ? GL_LEQUAL : k < 88 ? GL_ALWAYS : k < 92 ? GL_NOTEQUAL
               : k < 96 ? GL_GREATER : GL_GEQUAL;
    lit_clear(r, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, depth_func);
    L.s.vw = L.s.w;
    L.s.vh = L.s.h;
    if (fc_rng_chance(r, 25)) {             /* odd, but centred inside the framebuffer */
        int cx = (int)(L.s.w * fc_rng_real(r, 0.25, 0.75)), cy = (int)(L.s.h * fc_rng_real(r, 0.25, 0.75));
        L.s.vw = fc_rng_range(r, (L.s.w + 2) / 3, L.s.w * 3 / 2 + 1);
        L.s.vh = fc_rng_range(r, (L.s.h + 2) / 3, L.s.h * 3 / 2 + 1);
        glViewport(cx - L.s.vw / 2, cy - L.s.vh / 2, L.s.vw, L.s.vh);
    } else {
        glViewport(0, 0, L.s.w, L.s.h);
    }
    if (fc_rng_chance(r, 20))
        fcr_depth_range(r);
    lit_projection(&L);
    place_region(&L);
    random_camera(&L);
    glLoadIdentity();

    if (fc_rng_chance(K, 80))
        glEnable(GL_DEPTH_TEST);
    glDepthFunc(depth_func);
    glShadeModel(fc_rng_chance(K, 82) ? GL_SMOOTH : GL_FLAT);
    if (fc_rng_chance(K, 30))
        glFrontFace(GL_CW);
    if (fc_rng_chance(r, 50)) {
        glEnable(GL_LIGHTING);
        L.lighting = 1;
    }

    random_light_model(&L);
    if (fc_rng_chance(K, 50)) {
        L.faces[0] = L.faces[1] = GL_FRONT_AND_BACK;
        random_material(&L, GL_FRONT_AND_BACK);
    } else {
        L.faces[0] = GL_FRONT;
        L.faces[1] = GL_BACK;
        random_material(&L, GL_FRONT);
        random_material(&L, GL_BACK);
    }
    if (fc_rng_chance(K, 35)) {
        static const GLenum cm_faces[3] = { GL_FRONT, GL_BACK, GL_FRONT_AND_BACK };
        static const GLenum cm_modes[5] = { GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_AMBIENT_AND_DIFFUSE };
        GLenum face = cm_faces[fc_rng_below(K, 100) < 60 ? 2 : fc_rng_below(K, 2)];
        GLenum mode = cm_modes[fc_rng_below(K, 100) < 50 ? 4 : fc_rng_below(K, 5)];
        int before = fc_rng_chance(r, 25);
        if (fc_rng_chance(r, 50)) {             /* the current colour at glEnable time */
            double col[4];
            random_hue(r, col, 0.1, 1.0);
            emit_rgba(r, col, fc_rng_chance(r, 50));
        }
        if (before) glEnable(GL_COLOR_MATERIAL);
        glColorMaterial(face, mode);
        if (!before) glEnable(GL_COLOR_MATERIAL);
        L.color_material = 1;
    }
    L.dynamic = fc_rng_chance(K, 25);
    random_npolicy(&L, &L.np);
    L.mat_pname = material_pnames[fc_rng_below(K, 6)];
    L.mat_face = (int)fc_rng_below(K, 2);
    k = (int)fc_rng_below(K, 100);
    if (k >= 40 && k < 75) glEnable(GL_NORMALIZE);
    else if (k >= 75 && k < 95) glEnable(GL_RESCALE_NORMAL);
    else if (k >= 95) { glEnable(GL_NORMALIZE); glEnable(GL_RESCALE_NORMAL); }

    /* lights at random indices */
    k = (int)fc_rng_below(K, 100);
    nlights = k < 30 ? 1 : k < 52 ? 2 : k < 68 ? 3 : k < 78 ? 4 : fc_rng_range(K, 5, 8);
    for (int i = 0; i < 8; i++)
        order[i] = GL_LIGHT0 + (GLenum)i;
    for (int i = 7; i > 0; i--) {
        int j = (int)fc_rng_below(K, (uint32_t)i + 1);
        GLenum t = order[i];
        order[i] = order[j];
        order[j] = t;
    }
    for (int i = 0; i < nlights; i++)
        random_light(&L, order[i], nlights, i == 0);
    if (!L.lighting) {
        glEnable(GL_LIGHTING);
        L.lighting = 1;
    }

    random_state14(&L);
    issue_camera(&L);
    npatches = (k = (int)fc_rng_below(K, 100)) < 45 ? 1 : k < 75 ? 2 : k < 92 ? 3 : 4;
    if (c->frames == 2 && npatches < 2)
        npatches = 2;                       /* something to draw after the first capture */
    for (int p = 0; p < npatches; p++) {
        random_patch(&L, npatches);
        if (c->frames == 2 && p == (npatches - 2) / 2) {
            fc_capture(h);
            if (fc_rng_chance(r, 30))
                lit_clear(r, fc_rng_chance(r, 50) ? GL_COLOR_BUFFER_BIT : GL_DEPTH_BUFFER_BIT, depth_func);
        }
    }
    fc_capture(h);
    fc_error(h, "scene glGetError");
}

int fc_random_lit_parse(const char *name, uint64_t *seed, uint32_t *index)
{
    char tail;
    return sscanf(name, "random-lit/s%" SCNu64 "-i%" SCNu32 "%c", seed, index, &tail) == 2;
}

void fc_random_lit_case(uint64_t seed, uint32_t index, fc_case *out, char *name)
{
    static const GLenum formats[10] = {
        OSMESA_RGBA, OSMESA_RGBA, OSMESA_RGBA, OSMESA_RGBA, OSMESA_RGBA,
        OSMESA_RGBA, OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB, OSMESA_RGB,
    };
    static const int depths[12] = { 24, 24, 24, 24, 24, 24, 24, 24, 24, 16, 32, 0 };
    fc_rng r = fc_rng_make(seed, index, 3);
    fc_rng k = fc_rng_make(seed, index % FC_LIT_PROFILES, 6);  /* formats: structure */
    int size = (int)fc_rng_below(&r, 100);

    snprintf(name, FC_RANDOM_NAME_MAX, "random-lit/s%" PRIu64 "-i%" PRIu32, seed, index);
    memset(out, 0, sizeof *out);
    out->draws_nothing = FC_MAY_DRAW_NOTHING;   /* a generated scene (fc_case.h) */
    out->name = name;
    if (size < 75) {
        out->width = fc_rng_range(&r, 40, 128);
        out->height = fc_rng_range(&r, 40, 128);
    } else if (size < 90) {
        out->width = fc_rng_range(&r, 129, 256);
        out->height = fc_rng_range(&r, 129, 256);
    } else if (size < 98) {
        out->width = fc_rng_range(&r, 16, 39);
        out->height = fc_rng_range(&r, 16, 39);
    } else {
        out->width = fc_rng_range(&r, 1, 15);
        out->height = fc_rng_range(&r, 1, 15);
    }
    out->format = formats[fc_rng_below(&k, 10)];
    out->depth_bits = depths[fc_rng_below(&k, 12)];
    out->stencil_bits = fc_rng_chance(&k, 15) ? 8 : 0;
    out->frames = fc_rng_chance(&k, 25) ? 2 : 1;
    out->tags = "random-lit";
    out->fn = lit_scene;
}
