/* fc_random_shading.c - random lit scenes of fixgl's shading extensions
 * (include/fixgl/shading.md: GL_WIN_phong_shading, GL_FIXGL_cook_torrance),
 * "random-shading/s<seed>-i<index>".  Like the other families a scene is a
 * pure function of (seed, index) and nothing depends on GL results.
 *
 * These are reference scenes (fc_case.h): the oracle has neither extension,
 * so under FC_ORACLE the scene binds the GLSL reference
 * (conformance/reference/fcr_shading.c) where fixgl calls glShadeModel
 * (GL_PHONG_WIN) and the Cook-Torrance glMaterial parameters (sh_begin /
 * sh_end, cases/c_shading.c).  Tags: reference and random-shading, plus
 * phong (per-fragment shading) and cook-torrance (a Cook-Torrance face) by
 * what the scene uses; colour tolerance 1 LSB, as the fixed reference
 * cases (the agreement table of the report counts them).
 *
 * A scene: a random perspective (field of view, near plane in front of or
 * cutting the object), 1-4 lights of every kind (directional, point with
 * attenuation, spot with cutoff 90 or 5-80 and exponent 0-128) given under
 * random modelviews, the light model (ambient, local viewer, two-sided,
 * separate specular), both materials, both faces' reflectance models
 * (Blinn-Phong or Cook-Torrance with roughness 0, 0.05, 0.25, 0.5, 1 or
 * random, metalness, f0), colour material (each face and property),
 * GL_NORMALIZE / GL_RESCALE_NORMAL with a scale, blending, sometimes the
 * GL_MODULATE texture of unit 0 and fog (GL_LINEAR, GL_EXP, GL_EXP2);
 * then a sphere, a height field, two big triangles with bent normals or a
 * disc, as triangle strips, quad strips, quads, triangles, fans or a
 * polygon, sometimes as points or lines, sometimes in polygon mode
 * GL_LINE / GL_POINT, immediate, through a display list or through vertex
 * arrays (glDrawArrays / glDrawElements, interleaved); shaded per fragment
 * (GL_PHONG_WIN) or (25%, Cook-Torrance front face) per vertex under
 * GL_SMOOTH or GL_FLAT.
 *
 * The calls are not traced: FC_TRACE prints the case header and the
 * scene's structure (describe()). */
#include "fc_random.h"
#include "fc_rng.h"
#include "lt_util.h"
#include "sh_util.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

extern FILE *fc_trace_out;   /* fc_trace.c; its wrappers (fc_trace.h) are not used */

/* ---- the scene's structure (also decides the tags) ---------------------- */

enum shape { SHAPE_SPHERE, SHAPE_WAVE, SHAPE_QUAD, SHAPE_DISC };
enum path { PATH_IMMEDIATE, PATH_DLIST, PATH_ARRAYS, PATH_ELEMENTS };

struct profile {
    enum sh_mode mode;
    struct fcr_face front, back;
    enum shape shape;
    int alt_prim;               /* quads / quad strips / fan / polygon */
    GLenum as;                  /* 0, GL_POINTS or a line type: drawn as */
    GLenum polygon_mode;        /* GL_FILL, GL_LINE or GL_POINT (front) */
    enum path path;
    int colored, textured, fog; /* fog: 0 or GL_LINEAR, GL_EXP, GL_EXP2 */
};

static struct fcr_face rand_face(fc_rng *r)
{
    static const float rough[6] = { 0, 0.05f, 0.25f, 0.5f, 1, -1 };
    struct fcr_face f;
    f.cook_torrance = fc_rng_chance(r, 60);
    f.roughness = rough[fc_rng_below(r, 6)];
    if (f.roughness < 0)
        f.roughness = (float)fc_rng_unit(r);
    f.metalness = fc_rng_chance(r, 30) ? 0.0f : fc_rng_chance(r, 50) ? 1.0f : (float)fc_rng_unit(r);
    f.f0 = fc_rng_chance(r, 50) ? 0.04f : (float)fc_rng_unit(r);
    return f;
}

static void make_profile(uint64_t seed, uint32_t index, struct profile *p)
{
    static const GLenum lines[3] = { GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP };
    static const GLenum fogs[3] = { GL_LINEAR, GL_EXP, GL_EXP2 };
    fc_rng r = fc_rng_make(seed, index, 21);
    memset(p, 0, sizeof *p);
    p->front = rand_face(&r);
    p->back = rand_face(&r);
    p->mode = SH_PHONG;
    if (fc_rng_chance(&r, 25)) {
        p->front.cook_torrance = 1;
        p->mode = fc_rng_chance(&r, 70) ? SH_SMOOTH : SH_FLAT;
    }
    p->shape = (enum shape)fc_rng_below(&r, 4);
    p->alt_prim = fc_rng_chance(&r, 40);
    {
        const uint32_t k = fc_rng_below(&r, 100);
        p->as = k < 8 ? GL_POINTS : k < 16 ? lines[fc_rng_below(&r, 3)] : 0;
    }
    p->polygon_mode = !p->as && fc_rng_chance(&r, 6) ? (fc_rng_chance(&r, 50) ? GL_LINE : GL_POINT) : GL_FILL;
    p->path = (enum path)fc_rng_below(&r, 4);
    if (p->path >= PATH_ARRAYS && fc_rng_chance(&r, 33))
        p->path = PATH_IMMEDIATE;     /* immediate about 1/2 of the scenes */
    p->colored = fc_rng_chance(&r, 40);
    p->textured = fc_rng_chance(&r, 25);
    p->fog = fc_rng_chance(&r, 30) ? (int)fogs[fc_rng_below(&r, 3)] : 0;
}

/* The structure of a scene as a comment of the FC_TRACE output. */
static void describe(const struct profile *p)
{
    static const char *const modes[3] = { "GL_PHONG_WIN", "GL_SMOOTH", "GL_FLAT" };
    static const char *const shapes[4] = { "sphere", "wave", "quad", "disc" };
    static const char *const paths[4] = { "immediate", "dlist", "arrays", "elements" };
    const struct fcr_face *f[2] = { &p->front, &p->back };
    if (!fc_trace_out)
        return;
    fprintf(fc_trace_out, "/* %s", modes[p->mode]);
    for (int i = 0; i < 2; i++)
        fprintf(fc_trace_out, ", %s %s roughness %a metalness %a f0 %a", i ? "back" : "front",
                f[i]->cook_torrance ? "cook-torrance" : "blinn-phong", f[i]->roughness,
                f[i]->metalness, f[i]->f0);
    fprintf(fc_trace_out, ", %s%s as 0x%x polygon mode 0x%x, %s%s%s fog 0x%x */\n",
            shapes[p->shape], p->alt_prim ? " (alt)" : "", p->as, p->polygon_mode, paths[p->path],
            p->colored ? ", colour material" : "", p->textured ? ", textured" : "", p->fog);
}

/* ---- the geometry, built once, then emitted by the scene's path ---------- */

#define MAXV 2048
#define MAXB 64

struct vtx {
    float p[3], n[3], c[4], t[2];
};

struct mesh {
    struct vtx v[MAXV];
    int nv;
    struct {
        GLenum mode;
        int first, count;
    } b[MAXB];
    int nb;
};

static void hue(float t, float a, float c[4])
{
    float h = 6.0f * (t - floorf(t));
    int k = (int)h;
    float f = h - (float)k, q = 1 - f;
    float rgb[6][3] = { { 1, f, 0 }, { q, 1, 0 }, { 0, 1, f }, { 0, q, 1 }, { f, 0, 1 }, { 1, 0, q } };
    memcpy(c, rgb[k % 6], sizeof rgb[0]);
    c[3] = a;
}

static void begin_batch(struct mesh *m, GLenum mode)
{
    m->b[m->nb].mode = mode;
    m->b[m->nb].first = m->nv;
    m->b[m->nb].count = 0;
}

static void end_batch(struct mesh *m)
{
    m->b[m->nb].count = m->nv - m->b[m->nb].first;
    m->nb++;
}

/* A vertex at p with normal n (scaled by ns), a hue from t0 and the
 * texture coordinates from the position. */
static void add(struct mesh *m, float x, float y, float z, float nx, float ny, float nz, float ns,
                float t0, float alpha)
{
    struct vtx *v = &m->v[m->nv++];
    v->p[0] = x, v->p[1] = y, v->p[2] = z;
    v->n[0] = nx * ns, v->n[1] = ny * ns, v->n[2] = nz * ns;
    hue(t0 + 0.3f * y, alpha, v->c);
    v->t[0] = 0.7f * x + 0.5f;
    v->t[1] = 0.7f * y + 0.5f;
}

static void sphere(struct mesh *m, fc_rng *r, int alt, float ns, float alpha)
{
    const float rad = (float)fc_rng_real(r, 0.8, 1.4);
    const int slices = fc_rng_range(r, 10, 24), stacks = fc_rng_range(r, 6, 14);
    for (int i = 0; i < stacks; i++) {
        double lat[2] = { LT_PI * i / stacks - LT_PI / 2, LT_PI * (i + 1) / stacks - LT_PI / 2 };
        begin_batch(m, alt ? GL_QUAD_STRIP : GL_TRIANGLE_STRIP);
        for (int j = 0; j <= slices; j++) {
            double lon = 2 * LT_PI * j / slices;
            for (int k = 1; k >= 0; k--) {
                float x = (float)(cos(lat[k]) * sin(lon)), y = (float)sin(lat[k]),
                      z = (float)(cos(lat[k]) * cos(lon));
                add(m, x * rad, y * rad, z * rad, x, y, z, ns, (float)j / (float)slices, alpha);
            }
        }
        end_batch(m);
    }
}

static void wave_vertex(struct mesh *m, float x, float y, float amp, float f, float ns, float alpha)
{
    double z = amp * sin(f * x) * cos(f * y);
    double dx = amp * f * cos(f * x) * cos(f * y), dy = -amp * f * sin(f * x) * sin(f * y);
    double l = sqrt(dx * dx + dy * dy + 1);
    add(m, x, y, (float)z, (float)(-dx / l), (float)(-dy / l), (float)(1 / l), ns, 0.2f * x, alpha);
}

/* A height field over [-1.6,1.6]^2: n strips, or (alt) n*n quads. */
static void wave(struct mesh *m, fc_rng *r, int alt, float ns, float alpha)
{
    const int n = fc_rng_range(r, 4, 12);
    const float amp = (float)fc_rng_real(r, 0.1, 0.4), f = (float)fc_rng_real(r, 1, 3);
    const float s = 1.6f;
    if (alt)
        begin_batch(m, GL_QUADS);
    for (int j = 0; j < n; j++) {
        float ya = -s + 2 * s * (float)j / (float)n, yb = -s + 2 * s * (float)(j + 1) / (float)n;
        if (!alt) {
            begin_batch(m, GL_TRIANGLE_STRIP);
            for (int i = 0; i <= n; i++) {
                float x = -s + 2 * s * (float)i / (float)n;
                wave_vertex(m, x, yb, amp, f, ns, alpha);
                wave_vertex(m, x, ya, amp, f, ns, alpha);
            }
            end_batch(m);
        } else {
            for (int i = 0; i < n; i++) {
                float xa = -s + 2 * s * (float)i / (float)n, xb = -s + 2 * s * (float)(i + 1) / (float)n;
                wave_vertex(m, xa, ya, amp, f, ns, alpha);
                wave_vertex(m, xb, ya, amp, f, ns, alpha);
                wave_vertex(m, xb, yb, amp, f, ns, alpha);
                wave_vertex(m, xa, yb, amp, f, ns, alpha);
            }
        }
    }
    if (alt)
        end_batch(m);
}

/* [-s,s]^2 at z = 0 with the normals bent outwards at the corners (a
 * shallow dome): two triangles, or (alt) one quad or a fan.  Gouraud
 * interpolates the corner colours, Phong finds a highlight inside. */
static void big_quad(struct mesh *m, fc_rng *r, int alt, float ns, float alpha)
{
    static const float c[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
    static const int tris[6] = { 0, 1, 2, 0, 2, 3 };
    const float s = (float)fc_rng_real(r, 1, 1.8), bend = (float)fc_rng_real(r, 0, 0.6);
    const int fan = alt && fc_rng_chance(r, 50);
    begin_batch(m, !alt ? GL_TRIANGLES : fan ? GL_TRIANGLE_FAN : GL_QUADS);
    for (int i = 0; i < (alt ? 4 : 6); i++) {
        const float *v = c[alt ? i : tris[i]];
        float l = sqrtf(v[0] * bend * v[0] * bend + v[1] * bend * v[1] * bend + 1);
        add(m, v[0] * s, v[1] * s, 0, v[0] * bend / l, v[1] * bend / l, 1 / l, ns, 0.1f * (float)i, alpha);
    }
    end_batch(m);
}

/* A disc of radius s in z = 0, normals tilted outwards (a cone): a fan
 * around the centre, or (alt) a polygon of its rim. */
static void disc(struct mesh *m, fc_rng *r, int alt, float ns, float alpha)
{
    const float s = (float)fc_rng_real(r, 0.8, 1.8), tilt = (float)fc_rng_real(r, 0, 0.8);
    const int n = fc_rng_range(r, 5, 24);
    begin_batch(m, alt ? GL_POLYGON : GL_TRIANGLE_FAN);
    if (!alt)
        add(m, 0, 0, 0, 0, 0, 1, ns, 0.5f, alpha);
    for (int i = 0; i <= n - alt; i++) {
        float a = 2 * (float)LT_PI * (float)i / (float)n, x = cosf(a), y = sinf(a);
        float l = sqrtf(tilt * tilt + 1);
        add(m, s * x, s * y, 0, tilt * x / l, tilt * y / l, 1 / l, ns, (float)i / (float)n, alpha);
    }
    end_batch(m);
}

/* Vertex attributes of one vertex in immediate mode. */
static void immediate(const struct mesh *m, const struct profile *p)
{
    for (int b = 0; b < m->nb; b++) {
        glBegin(p->as ? p->as : m->b[b].mode);
        for (int i = m->b[b].first; i < m->b[b].first + m->b[b].count; i++) {
            const struct vtx *v = &m->v[i];
            if (p->colored)
                glColor4fv(v->c);
            if (p->textured)
                glTexCoord2fv(v->t);
            glNormal3fv(v->n);
            glVertex3fv(v->p);
        }
        glEnd();
    }
}

static void emit(const struct mesh *m, const struct profile *p, fc_rng *r)
{
    static GLushort idx[MAXV];
    switch (p->path) {
    case PATH_IMMEDIATE:
        immediate(m, p);
        break;
    case PATH_DLIST:
        if (fc_rng_chance(r, 50)) {
            glNewList(7, GL_COMPILE_AND_EXECUTE);
            immediate(m, p);
            glEndList();
        } else {
            glNewList(7, GL_COMPILE);
            immediate(m, p);
            glEndList();
            glCallList(7);
        }
        glDeleteLists(7, 1);
        break;
    default:
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_NORMAL_ARRAY);
        glVertexPointer(3, GL_FLOAT, sizeof m->v[0], m->v[0].p);
        glNormalPointer(GL_FLOAT, sizeof m->v[0], m->v[0].n);
        if (p->colored) {
            glEnableClientState(GL_COLOR_ARRAY);
            glColorPointer(4, GL_FLOAT, sizeof m->v[0], m->v[0].c);
        }
        if (p->textured) {
            glEnableClientState(GL_TEXTURE_COORD_ARRAY);
            glTexCoordPointer(2, GL_FLOAT, sizeof m->v[0], m->v[0].t);
        }
        for (int b = 0; b < m->nb; b++) {
            const GLenum mode = p->as ? p->as : m->b[b].mode;
            if (p->path == PATH_ARRAYS) {
                glDrawArrays(mode, m->b[b].first, m->b[b].count);
            } else {
                for (int i = 0; i < m->b[b].count; i++)
                    idx[i] = (GLushort)(m->b[b].first + i);
                glDrawElements(mode, m->b[b].count, GL_UNSIGNED_SHORT, idx);
            }
        }
        glDisableClientState(GL_VERTEX_ARRAY);
        glDisableClientState(GL_NORMAL_ARRAY);
        glDisableClientState(GL_COLOR_ARRAY);
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
        break;
    }
}

/* ---- the scene ------------------------------------------------------------ */

static float rf(fc_rng *r, double lo, double hi)
{
    return (float)fc_rng_real(r, lo, hi);
}

static float ru(fc_rng *r)
{
    return (float)fc_rng_unit(r);
}

static void random_lights(fc_rng *r)
{
    const int nl = fc_rng_range(r, 1, 4);
    for (int i = 0; i < 8; i++)
        glDisable(GL_LIGHT0 + (GLenum)i);
    for (int i = 0; i < nl; i++) {
        const GLenum l = GL_LIGHT0 + (GLenum)fc_rng_below(r, 8);
        const int kind = (int)fc_rng_below(r, 3);   /* directional, point, spot */
        glPushMatrix();
        glRotatef(rf(r, -90, 90), ru(r), ru(r), ru(r) + 0.1f);
        lt_light(l, GL_AMBIENT, rf(r, 0, 0.2), rf(r, 0, 0.2), rf(r, 0, 0.2), 1);
        lt_light(l, GL_DIFFUSE, ru(r), ru(r), ru(r), 1);
        lt_light(l, GL_SPECULAR, rf(r, 0.3, 1.2), rf(r, 0.3, 1.2), rf(r, 0.3, 1.2), 1);
        if (kind == 0)
            lt_light(l, GL_POSITION, rf(r, -1, 1), rf(r, -1, 1), rf(r, -0.3, 1), 0);
        else
            lt_light(l, GL_POSITION, rf(r, -2, 2), rf(r, -2, 2), rf(r, -5, 1), rf(r, 0.5, 2));
        glLightf(l, GL_CONSTANT_ATTENUATION, kind && fc_rng_chance(r, 50) ? rf(r, 0.3, 1.5) : 1);
        glLightf(l, GL_LINEAR_ATTENUATION, kind && fc_rng_chance(r, 50) ? rf(r, 0, 0.5) : 0);
        glLightf(l, GL_QUADRATIC_ATTENUATION, kind && fc_rng_chance(r, 50) ? rf(r, 0, 0.3) : 0);
        lt_light(l, GL_SPOT_DIRECTION, rf(r, -1, 1), rf(r, -1, 1), rf(r, -1, 0.2), 0);
        glLightf(l, GL_SPOT_CUTOFF, kind == 2 ? (fc_rng_chance(r, 20) ? 90.0f : rf(r, 5, 80)) : 180.0f);
        glLightf(l, GL_SPOT_EXPONENT,
                 fc_rng_chance(r, 30) ? 0.0f : fc_rng_chance(r, 20) ? 128.0f : rf(r, 0, 40));
        glPopMatrix();
        glEnable(l);
    }
}

static void random_materials(fc_rng *r, const struct profile *p)
{
    lt_model(GL_LIGHT_MODEL_AMBIENT, rf(r, 0, 0.3), rf(r, 0, 0.3), rf(r, 0, 0.3), 1);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, fc_rng_chance(r, 50));
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, fc_rng_chance(r, 50));
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL,
                  fc_rng_chance(r, 50) ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
    for (int f = 0; f < 2; f++) {
        const GLenum face = f ? GL_BACK : GL_FRONT;
        lt_mat(face, GL_AMBIENT, ru(r), ru(r), ru(r), 1);
        lt_mat(face, GL_DIFFUSE, ru(r), ru(r), ru(r), rf(r, 0.3, 1));
        lt_mat(face, GL_SPECULAR, ru(r), ru(r), ru(r), 1);
        lt_mat(face, GL_EMISSION, rf(r, 0, 0.2), rf(r, 0, 0.2), rf(r, 0, 0.2), 1);
        glMaterialf(face, GL_SHININESS,
                    fc_rng_chance(r, 20) ? 0.0f : fc_rng_chance(r, 20) ? 128.0f : rf(r, 1, 100));
    }
    if (p->colored) {
        static const GLenum faces[3] = { GL_FRONT, GL_BACK, GL_FRONT_AND_BACK };
        static const GLenum params[5] = {
            GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_AMBIENT_AND_DIFFUSE,
        };
        glColorMaterial(faces[fc_rng_below(r, 3)], params[fc_rng_below(r, 5)]);
        glEnable(GL_COLOR_MATERIAL);
    }
}

static void random_fog(fc_rng *r, const struct profile *p)
{
    const float color[4] = { ru(r), ru(r), ru(r), 1 };
    if (!p->fog)
        return;
    glFogfv(GL_FOG_COLOR, color);
    glFogi(GL_FOG_MODE, p->fog);
    if (p->fog == GL_LINEAR) {
        const float start = rf(r, 0, 4);
        glFogf(GL_FOG_START, start);
        glFogf(GL_FOG_END, start + rf(r, 0.5, 4));
    } else {
        glFogf(GL_FOG_DENSITY, rf(r, 0.05, 0.5));
    }
    glEnable(GL_FOG);
}

static void shading_scene(fc_h *h)
{
    static struct mesh m;
    const fc_case *c = fc_this_case(h);
    struct profile p;
    uint64_t seed;
    uint32_t index;
    fc_rng r;

    fc_random_shading_parse(c->name, &seed, &index);
    make_profile(seed, index, &p);
    describe(&p);
    r = fc_rng_make(seed, index, 22);

    /* perspective: camera at the origin looking down -z, the object at
     * z -3.5..-5 with radius up to 1.8; the near plane cuts it sometimes */
    {
        const double n = fc_rng_chance(&r, 20) ? fc_rng_real(&r, 2.2, 3.4) : fc_rng_real(&r, 0.5, 2);
        const double t = n * tan(fc_rng_real(&r, 12, 30) * LT_PI / 180);
        const double a = (double)c->width / c->height;
        glViewport(0, 0, c->width, c->height);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glFrustum(-t * a, t * a, -t, t, n, fc_rng_real(&r, 6, 20));
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearColor(rf(&r, 0, 0.3), rf(&r, 0, 0.3), rf(&r, 0, 0.3), 1);
    glClearDepth(1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    glEnable(GL_LIGHTING);
    random_lights(&r);
    random_materials(&r, &p);
    const int nmode = (int)fc_rng_below(&r, 3);
    if (nmode == 1)
        glEnable(GL_NORMALIZE);
    else if (nmode == 2)
        glEnable(GL_RESCALE_NORMAL);
    if (fc_rng_chance(&r, 30)) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }
    if (p.textured)
        sh_texture();
    random_fog(&r, &p);
    if (p.as == GL_POINTS)
        glPointSize((float)fc_rng_range(&r, 1, 4));
    if (p.polygon_mode != GL_FILL)
        glPolygonMode(GL_FRONT, p.polygon_mode);

    sh_begin(h, p.mode, &p.front, &p.back);
    glTranslatef(rf(&r, -0.5, 0.5), rf(&r, -0.5, 0.5), rf(&r, -5, -3.5));
    glRotatef(rf(&r, 0, 360), ru(&r) - 0.5f, ru(&r) - 0.5f, ru(&r) - 0.5f);
    if (nmode)
        glScalef(rf(&r, 0.6, 1.4), rf(&r, 0.6, 1.4), rf(&r, 0.6, 1.4));
    {
        /* GL_NORMALIZE: normals of another length, as shading.md's n */
        const float ns = nmode == 1 && fc_rng_chance(&r, 50) ? rf(&r, 0.3, 3) : 1;
        const float alpha = rf(&r, 0.5, 1);
        m.nv = m.nb = 0;
        switch (p.shape) {
        case SHAPE_SPHERE: sphere(&m, &r, p.alt_prim, ns, alpha); break;
        case SHAPE_WAVE: wave(&m, &r, p.alt_prim, ns, alpha); break;
        case SHAPE_QUAD: big_quad(&m, &r, p.alt_prim, ns, alpha); break;
        default: disc(&m, &r, p.alt_prim, ns, alpha); break;
        }
    }
    emit(&m, &p, &r);
    fc_capture(h);
    sh_end();
    fc_error(h, "scene glGetError");
}

/* ---- the family ------------------------------------------------------------ */

int fc_random_shading_parse(const char *name, uint64_t *seed, uint32_t *index)
{
    char tail;
    return sscanf(name, "random-shading/s%" SCNu64 "-i%" SCNu32 "%c", seed, index, &tail) == 2;
}

void fc_random_shading_case(uint64_t seed, uint32_t index, fc_case *out, char *name)
{
    fc_rng r = fc_rng_make(seed, index, 20);
    struct profile p;
    int ct;

    make_profile(seed, index, &p);
    ct = p.front.cook_torrance || p.back.cook_torrance;
    snprintf(name, FC_RANDOM_NAME_MAX, "random-shading/s%" PRIu64 "-i%" PRIu32, seed, index);
    memset(out, 0, sizeof *out);
    out->draws_nothing = FC_MAY_DRAW_NOTHING;   /* a generated scene (fc_case.h) */
    out->name = name;
    out->width = fc_rng_range(&r, 24, 64);
    out->height = fc_rng_range(&r, 24, 64);
    out->format = OSMESA_RGBA;
    out->depth_bits = 24;
    out->frames = 1;
    out->tags = p.mode != SH_PHONG ? "reference random-shading cook-torrance"
              : ct ? "reference random-shading phong cook-torrance"
              : "reference random-shading phong";
    out->fn = shading_scene;
    out->tolerance_lsb = 1;
}
