/* fc_random.c - the random scene generator (see fc_random.h).
 *
 * Scenes cover the first slice of the library: all six polygon primitive
 * types with shared vertices, vertices on pixel centres, on the 1/256 snap
 * grid and on its half-way points; tiny, sliver and huge primitives; ortho,
 * frustum and arbitrary projections with vertices behind the eye, w near 0
 * and exactly on clip planes; random modelview builders; depth functions,
 * masks, clear depths and ranges; both shade models; odd viewports; every
 * glColor/glVertex entry-point variant. */
#include "fc_random.h"
#include "fc_random_shared.h"
#include "fc_rng.h"
#include "fc_trace.h"
#include "fc_emit.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

const GLenum fcr_depth_funcs[8] = {
    GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS
};
const GLenum fcr_modes[6] = {
    GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON
};

int fc_random_parse(const char *name, uint64_t *seed, uint32_t *index)
{
    char tail;
    return sscanf(name, "random/s%" SCNu64 "-i%" SCNu32 "%c", seed, index, &tail) == 2;
}

/* ---- GL entry-point variants ------------------------------------------ */

#define VERTEX_CALL(T, suf, x) do {                                          \
        T a[4] = { (T)(x)[0], (T)(x)[1], (T)(x)[2], (T)(x)[3] };             \
        if (vec) {                                                           \
            if (dim == 2) glVertex2##suf##v(a);                              \
            else if (dim == 3) glVertex3##suf##v(a);                         \
            else glVertex4##suf##v(a);                                       \
        } else {                                                             \
            if (dim == 2) glVertex2##suf(a[0], a[1]);                        \
            else if (dim == 3) glVertex3##suf(a[0], a[1], a[2]);             \
            else glVertex4##suf(a[0], a[1], a[2], a[3]);                     \
        }                                                                    \
    } while (0)

static int is_short(double v) { return v == floor(v) && fabs(v) <= 32767; }

/* Issues v (dim components used) through a random glVertex variant; the
 * integer variants are only used when the values are exact integers. */
void fcr_emit_vertex(struct scene *s, const double v[4], int dim)
{
    int vec = fc_rng_chance(&s->r, 40);
    int ints = 1;
    for (int i = 0; i < dim; i++)
        ints &= is_short(v[i]);
    switch (fc_rng_below(&s->r, ints ? 4 : 2)) {
    case 0: VERTEX_CALL(GLfloat, f, v); break;
    case 1: VERTEX_CALL(GLdouble, d, v); break;
    case 2: VERTEX_CALL(GLshort, s, v); break;
    default: VERTEX_CALL(GLint, i, v); break;
    }
}

#define COLOR_CALL(T, suf, x) do {                                           \
        T a[4] = { (T)(x)[0], (T)(x)[1], (T)(x)[2], (T)(x)[3] };             \
        if (vec) {                                                           \
            if (four) glColor4##suf##v(a); else glColor3##suf##v(a);         \
        } else {                                                             \
            if (four) glColor4##suf(a[0], a[1], a[2], a[3]);                 \
            else glColor3##suf(a[0], a[1], a[2]);                            \
        }                                                                    \
    } while (0)

/* A random integer of a GL type's range, biased towards the extremes. */
static double int_value(fc_rng *r, double lo, double hi)
{
    switch (fc_rng_below(r, 8)) {
    case 0: return lo;
    case 1: return hi;
    case 2: return 0;
    default: return floor(fc_rng_real(r, lo, hi + 1.0));
    }
}

void fcr_emit_color(struct scene *s)
{
    static const double lim[6][2] = {
        { -128, 127 }, { -32768, 32767 }, { -2147483648.0, 2147483647.0 },
        { 0, 255 }, { 0, 65535 }, { 0, 4294967295.0 },
    };
    fc_rng *r = &s->r;
    int vec = fc_rng_chance(r, 40), four = fc_rng_chance(r, 50);
    int type = (int)fc_rng_below(r, 10);
    double c[4];

    if (type >= 6) {            /* float / double, mostly in [0,1] */
        for (int i = 0; i < 4; i++) {
            int k = (int)fc_rng_below(r, 10);
            c[i] = k == 0 ? 0.0 : k == 1 ? 1.0 : k == 2 ? fc_rng_real(r, -0.3, 1.3)
                 : k == 3 ? fc_rng_range(r, 0, 510) / 510.0 : fc_rng_unit(r);
        }
        if (type & 1) COLOR_CALL(GLdouble, d, c); else COLOR_CALL(GLfloat, f, c);
        return;
    }
    for (int i = 0; i < 4; i++)
        c[i] = int_value(r, lim[type][0], lim[type][1]);
    switch (type) {
    case 0: COLOR_CALL(GLbyte, b, c); break;
    case 1: COLOR_CALL(GLshort, s, c); break;
    case 2: COLOR_CALL(GLint, i, c); break;
    case 3: COLOR_CALL(GLubyte, ub, c); break;
    case 4: COLOR_CALL(GLushort, us, c); break;
    default: COLOR_CALL(GLuint, ui, c); break;
    }
}

/* ---- coordinates ------------------------------------------------------ */

/* A pixel-space coordinate along an axis of n pixels. */
static double pixel_coord(fc_rng *r, int n)
{
    double i = fc_rng_range(r, -n / 4 - 1, n + n / 4 + 1);
    switch (fc_rng_below(r, 7)) {
    case 0: return i + 0.5;                                     /* pixel centre */
    case 1: return i;                                           /* pixel corner */
    case 2: return i + fc_rng_below(r, 256) / 256.0;            /* snap grid */
    case 3: return i + 0.5 + (2 * fc_rng_range(r, -3, 2) + 1) / 512.0; /* grid ties */
    case 4: return (float)(i + fc_rng_unit(r));
    case 5: return i + 0.5 + fc_rng_range(r, -2, 2) / 1048576.0; /* near a centre */
    default: return (float)fc_rng_real(r, -3.0 * n, 4.0 * n);   /* far outside */
    }
}

/* z (or an eye-space coordinate) exactly on, just inside or beyond a bound. */
static double near_bound(fc_rng *r, double lo, double hi)
{
    switch (fc_rng_below(r, 8)) {
    case 0: return lo;
    case 1: return hi;
    case 2: return lo - (hi - lo) * 0.25;
    case 3: return hi + (hi - lo) * 0.25;
    default: return (float)fc_rng_real(r, lo, hi);
    }
}

/* A fresh vertex of the scene's space; returns the glVertex dimension. */
int fcr_fresh_vertex(struct scene *s, double v[4])
{
    fc_rng *r = &s->r;
    v[2] = 0;
    v[3] = 1;
    switch (s->space) {
    case SP_PIXEL:
        v[0] = pixel_coord(r, s->vw);
        v[1] = pixel_coord(r, s->vh);
        if (fc_rng_chance(r, 40))
            return 2;
        v[2] = near_bound(r, -1, 1);
        return 3;
    case SP_BOX:
        v[0] = near_bound(r, s->box[0], s->box[1]);
        v[1] = near_bound(r, s->box[2], s->box[3]);
        v[2] = -near_bound(r, s->box[4], s->box[5]);
        return 3;
    case SP_FRUSTUM: {
        double ze;
        int k = (int)fc_rng_below(r, 20);
        ze = k == 0 ? 0.0 : k == 1 ? -s->fr[4] : k == 2 ? -s->fr[5]
           : k < 5 ? fc_rng_real(r, 0.01, 2.0 * s->fr[4])          /* behind the eye */
           : -(float)fc_rng_real(r, s->fr[4] * 0.5, s->fr[5] * 1.1);
        v[0] = fc_rng_real(r, -1.4, 1.4) * fabs(ze) * (s->fr[1] - s->fr[0]) / (2 * s->fr[4]);
        v[1] = fc_rng_real(r, -1.4, 1.4) * fabs(ze) * (s->fr[3] - s->fr[2]) / (2 * s->fr[4]);
        v[2] = ze;
        if (fc_rng_chance(r, 10)) {                                 /* w != 1 */
            v[3] = fc_rng_real(r, 0.25, 4.0);
            for (int i = 0; i < 3; i++)
                v[i] *= v[3];
            return 4;
        }
        return 3;
    }
    case SP_CLIP: {
        int k = (int)fc_rng_below(r, 20);
        v[3] = k < 8 ? 1.0 : k < 12 ? (float)fc_rng_real(r, 0.2, 3.0)
             : k < 15 ? (fc_rng_chance(r, 50) ? 1 : -1) * pow(10.0, -fc_rng_real(r, 3, 8))
             : k < 18 ? -(float)fc_rng_real(r, 0.1, 2.0) : 0.0;
        for (int i = 0; i < 3; i++) {
            int on = (int)fc_rng_below(r, 5);
            v[i] = on == 0 ? v[3] : on == 1 ? -v[3] : (float)(fc_rng_real(r, -1.4, 1.4) * v[3]);
        }
        return 4;
    }
    case SP_MATRIX:
        for (int i = 0; i < 3; i++)
            v[i] = (float)fc_rng_real(r, -2, 2);
        return 3;
    }
    return 3;
}

/* Vertex of a primitive: shared with an earlier one, near the anchor
 * (tiny), on the line anchor-second (sliver), huge, or fresh. */
static int pick_vertex(struct scene *s, int style, int k, const double anchor[4],
                       const double second[4], double v[4])
{
    fc_rng *r = &s->r;
    int dim = fcr_fresh_vertex(s, v);
    if (s->npool && fc_rng_chance(r, 25)) {
        memcpy(v, s->pool[fc_rng_below(r, (uint32_t)(s->npool < POOL ? s->npool : POOL))],
               4 * sizeof v[0]);
        return v[3] != 1 ? 4 : 3;
    }
    if (k > 0 && style == 1) {                  /* tiny */
        double scale = s->space == SP_PIXEL ? 3.0 : 0.02;
        for (int i = 0; i < 2; i++)
            v[i] = anchor[i] + fc_rng_range(r, -768, 768) / 256.0 * scale;
    } else if (k > 1 && style == 2) {           /* sliver */
        double t = fc_rng_real(r, -0.5, 1.5), eps = fc_rng_range(r, -2, 2) / 256.0;
        for (int i = 0; i < 3; i++)
            v[i] = anchor[i] + t * (second[i] - anchor[i]);
        v[3] = anchor[3] + t * (second[3] - anchor[3]);
        v[1] += eps;
        dim = 4;
    } else if (style == 3 && fc_rng_chance(r, 50)) { /* huge */
        for (int i = 0; i < 2; i++)
            v[i] = (fc_rng_chance(r, 50) ? 1 : -1) * pow(10.0, fc_rng_real(r, 3, 7));
    }
    return dim;
}

/* ---- state ------------------------------------------------------------ */

void fcr_viewport(struct scene *s)
{
    fc_rng *r = &s->r;
    int x = 0, y = 0;
    s->vw = s->w;
    s->vh = s->h;
    if (fc_rng_chance(r, 40)) {
        x = fc_rng_range(r, -s->w / 2, s->w - 1);
        y = fc_rng_range(r, -s->h / 2, s->h - 1);
        s->vw = fc_rng_range(r, 1, 2 * s->w);
        s->vh = fc_rng_range(r, 1, 2 * s->h);
        /* a viewport left or below the window shows nothing: widen it
         * into the window (from the witness's stream, so scenes with a
         * visible viewport keep their values) */
        if (x + s->vw <= 0)
            s->vw = -x + fc_rng_range(&s->vis, 1, s->w);
        if (y + s->vh <= 0)
            s->vh = -y + fc_rng_range(&s->vis, 1, s->h);
    }
    s->vx = x;
    s->vy = y;
    glViewport(x, y, s->vw, s->vh);
}

void fcr_depth_range(fc_rng *r)
{
    static const double v[6] = { 0.0, 1.0, 0.5, 0.25, -0.5, 1.5 };
    if (fc_rng_chance(r, 60))
        return;
    glDepthRange(fc_rng_chance(r, 50) ? v[fc_rng_below(r, 6)] : fc_rng_unit(r),
                 fc_rng_chance(r, 50) ? v[fc_rng_below(r, 6)] : fc_rng_unit(r));
}

void fcr_matrix(fc_rng *r, double m[16], int perspective)
{
    for (int i = 0; i < 16; i++)
        m[i] = (float)fc_rng_real(r, -2, 2);
    if (perspective) {
        m[3] = m[7] = m[15] = 0;
        m[11] = -1;
    } else if (fc_rng_chance(r, 60)) {
        m[3] = m[7] = m[11] = 0;
        m[15] = 1;
    }
}

void fcr_load_or_mult(fc_rng *r, const double m[16])
{
    GLfloat f[16];
    for (int i = 0; i < 16; i++)
        f[i] = (GLfloat)m[i];
    switch (fc_rng_below(r, 4)) {
    case 0: glLoadMatrixf(f); break;
    case 1: glLoadMatrixd(m); break;
    case 2: glLoadIdentity(); glMultMatrixf(f); break;
    default: glLoadIdentity(); glMultMatrixd(m); break;
    }
}

/* The matrices of glOrtho and glFrustum (column-major). */
static void ortho_matrix(double m[16], const double b[6])
{
    memset(m, 0, 16 * sizeof m[0]);
    m[0] = 2 / (b[1] - b[0]);
    m[5] = 2 / (b[3] - b[2]);
    m[10] = -2 / (b[5] - b[4]);
    m[12] = -(b[1] + b[0]) / (b[1] - b[0]);
    m[13] = -(b[3] + b[2]) / (b[3] - b[2]);
    m[14] = -(b[5] + b[4]) / (b[5] - b[4]);
    m[15] = 1;
}

static void frustum_matrix(double m[16], const double f[6])
{
    memset(m, 0, 16 * sizeof m[0]);
    m[0] = 2 * f[4] / (f[1] - f[0]);
    m[5] = 2 * f[4] / (f[3] - f[2]);
    m[8] = (f[1] + f[0]) / (f[1] - f[0]);
    m[9] = (f[3] + f[2]) / (f[3] - f[2]);
    m[10] = -(f[5] + f[4]) / (f[5] - f[4]);
    m[11] = -1;
    m[14] = -2 * f[5] * f[4] / (f[5] - f[4]);
}

void fcr_projection(struct scene *s)
{
    fc_rng *r = &s->r;
    double m[16];
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    memset(s->proj, 0, sizeof s->proj);
    s->proj[0] = s->proj[5] = s->proj[10] = s->proj[15] = 1;
    switch (s->space) {
    case SP_PIXEL: {
        const double b[6] = { 0, s->vw, 0, s->vh, -1, 1 };
        glOrtho(0, s->vw, 0, s->vh, -1, 1);
        ortho_matrix(s->proj, b);
        break;
    }
    case SP_BOX:
        for (int i = 0; i < 6; i += 2) {
            s->box[i] = (float)fc_rng_real(r, -50, 50);
            s->box[i + 1] = s->box[i] + (fc_rng_chance(r, 85) ? 1 : -1) * (float)fc_rng_real(r, 0.5, 100);
        }
        glOrtho(s->box[0], s->box[1], s->box[2], s->box[3], s->box[4], s->box[5]);
        ortho_matrix(s->proj, s->box);
        break;
    case SP_FRUSTUM:
        s->fr[4] = (float)fc_rng_real(r, 0.05, 3.0);
        s->fr[5] = s->fr[4] + (float)fc_rng_real(r, 0.5, 200.0);
        s->fr[0] = -(float)fc_rng_real(r, 0.05, 2.0) * s->fr[4];
        s->fr[1] = (float)fc_rng_real(r, 0.05, 2.0) * s->fr[4];
        s->fr[2] = -(float)fc_rng_real(r, 0.05, 2.0) * s->fr[4];
        s->fr[3] = (float)fc_rng_real(r, 0.05, 2.0) * s->fr[4];
        glFrustum(s->fr[0], s->fr[1], s->fr[2], s->fr[3], s->fr[4], s->fr[5]);
        frustum_matrix(s->proj, s->fr);
        break;
    case SP_CLIP:
        break;
    case SP_MATRIX:
        fcr_matrix(r, m, fc_rng_chance(r, 50));
        fcr_load_or_mult(r, m);
        memcpy(s->proj, m, sizeof s->proj);
        break;
    }
    glMatrixMode(GL_MODELVIEW);
}

/* ---- the witness -------------------------------------------------------- */

/* inv = m^-1 (column-major, Gauss-Jordan with partial pivoting); 0 when m
 * is (nearly) singular. */
static int invert4(const double m[16], double inv[16])
{
    double a[4][8];
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++) {
            a[r][c] = m[c * 4 + r];
            a[r][c + 4] = r == c;
        }
    for (int c = 0; c < 4; c++) {
        int p = c;
        for (int r = c + 1; r < 4; r++)
            if (fabs(a[r][c]) > fabs(a[p][c]))
                p = r;
        if (fabs(a[p][c]) < 1e-9)
            return 0;
        for (int k = 0; k < 8; k++) {
            double t = a[c][k];
            a[c][k] = a[p][k];
            a[p][k] = t;
        }
        for (int k = 7; k >= c; k--)
            a[c][k] /= a[c][c];
        for (int r = 0; r < 4; r++)
            if (r != c)
                for (int k = 7; k >= c; k--)
                    a[r][k] -= a[r][c] * a[c][k];
    }
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++)
            inv[c * 4 + r] = a[r][c + 4];
    return 1;
}

/* A window coordinate inside [lo, hi) of the viewport's part in the
 * window, as a normalised device coordinate of the viewport [o, o + n). */
static double visible_ndc(fc_rng *r, int lo, int hi, int o, int n)
{
    double x = fc_rng_real(r, lo - 0.5, hi + 0.5);
    x = x < o ? o : x > o + n ? o + n : x;
    double d = 2 * (x - o) / n - 1;
    return d < -0.999 ? -0.999 : d > 0.999 ? 0.999 : d;
}

void fcr_witness(struct scene *s)
{
    static const int counts[6][2] = { { 3, 3 }, { 3, 5 }, { 3, 5 }, { 4, 4 }, { 4, 4 }, { 3, 6 } };
    const int x0 = s->vx > 0 ? s->vx : 0, x1 = s->vx + s->vw < s->w ? s->vx + s->vw : s->w;
    const int y0 = s->vy > 0 ? s->vy : 0, y1 = s->vy + s->vh < s->h ? s->vy + s->vh : s->h;
    double inv[16];
    if (x1 <= x0 || y1 <= y0 || !invert4(s->proj, inv))
        return;
    const fc_rng saved = s->r;          /* the emitters draw from s->r */
    s->r = s->vis;
    fc_rng *r = &s->r;
    const int m = (int)fc_rng_below(r, 6);
    const int n = fc_rng_range(r, counts[m][0], counts[m][1]);
    glPushAttrib(GL_DEPTH_BUFFER_BIT);
    glDepthFunc(GL_ALWAYS);
    glPushMatrix();
    glLoadIdentity();
    glBegin(fcr_modes[m]);
    for (int k = 0; k < n; k++) {
        const double c[4] = { visible_ndc(r, x0, x1, s->vx, s->vw),
                              visible_ndc(r, y0, y1, s->vy, s->vh),
                              fc_rng_real(r, -0.95, 0.95), 1 };
        double v[4];
        for (int i = 0; i < 4; i++)
            v[i] = (float)(inv[i] * c[0] + inv[4 + i] * c[1] + inv[8 + i] * c[2] + inv[12 + i] * c[3]);
        if (k == 0 || fc_rng_chance(r, 70))
            fcr_emit_color(s);
        fcr_emit_vertex(s, v, v[3] != 1 ? 4 : 3);
    }
    glEnd();
    glPopMatrix();
    glPopAttrib();
    s->vis = s->r;
    s->r = saved;
}

/* One random modelview builder call. */
static void random_transform(struct scene *s)
{
    fc_rng *r = &s->r;
    double m[16], a[4];
    int pix = s->space == SP_PIXEL;
    for (int i = 0; i < 4; i++)
        a[i] = pix ? fc_rng_range(r, -8, 8) * 0.5 : (float)fc_rng_real(r, -2, 2);
    switch (fc_rng_below(r, pix ? 4 : 7)) {
    case 0: glTranslatef((GLfloat)a[0], (GLfloat)a[1], (GLfloat)a[2]); break;
    case 1: glTranslated(a[0], a[1], a[2]); break;
    case 2: case 3:                         /* mirror / quarter turn about the viewport centre */
        glTranslatef(0.5f * (GLfloat)s->vw, 0.5f * (GLfloat)s->vh, 0);
        if (fc_rng_chance(r, 50))
            glScalef(fc_rng_chance(r, 50) ? -1.0f : 1.0f, fc_rng_chance(r, 50) ? -1.0f : 1.0f, 1.0f);
        else
            glRotatef(90.0f * (GLfloat)fc_rng_range(r, 0, 3), 0, 0, 1);
        glTranslatef(-0.5f * (GLfloat)s->vw, -0.5f * (GLfloat)s->vh, 0);
        break;
    case 4: glScaled(a[0], a[1], a[2]); break;
    case 5:
        switch (fc_rng_below(r, 4)) {       /* axis-aligned and general axes */
        case 0: a[1] = a[2] = 0; break;
        case 1: a[0] = a[2] = 0; break;
        case 2: a[0] = a[1] = 0; break;
        default: break;
        }
        if (fc_rng_chance(r, 50))
            glRotatef((GLfloat)(a[3] * 200), (GLfloat)a[0], (GLfloat)a[1], (GLfloat)a[2]);
        else
            glRotated(a[3] * 200, a[0], a[1], a[2]);
        break;
    default:
        fcr_matrix(r, m, 0);
        if (fc_rng_chance(r, 50)) {
            GLfloat f[16];
            for (int i = 0; i < 16; i++)
                f[i] = (GLfloat)m[i];
            glMultMatrixf(f);
        } else {
            glMultMatrixd(m);
        }
        break;
    }
}

static void random_state_change(struct scene *s)
{
    fc_rng *r = &s->r;
    if (fc_rng_chance(r, 20))
        glShadeModel(fc_rng_chance(r, 50) ? GL_FLAT : GL_SMOOTH);
    if (fc_rng_chance(r, 20))
        glDepthFunc(fcr_depth_funcs[fc_rng_below(r, 8)]);
    if (fc_rng_chance(r, 10))
        glDepthMask(fc_rng_chance(r, 70) ? GL_TRUE : GL_FALSE);
    if (fc_rng_chance(r, 8)) {
        if (fc_rng_chance(r, 70)) glEnable(GL_DEPTH_TEST); else glDisable(GL_DEPTH_TEST);
    }
    if (fc_rng_chance(r, 4))
        fcr_depth_range(r);
}

/* ---- primitives ------------------------------------------------------- */

static int vertex_count(fc_rng *r, GLenum mode)
{
    int n = fc_rng_range(r, 1, 4);
    int extra = fc_rng_chance(r, 15) ? fc_rng_range(r, 0, 3) : 0; /* incomplete tails */
    switch (mode) {
    case GL_TRIANGLES: return 3 * n + (extra % 3);
    case GL_QUADS: return 4 * n + extra;
    case GL_QUAD_STRIP: return 2 + 2 * n + (extra & 1);
    default: return 2 + n + fc_rng_range(r, 0, 3) - (extra ? 2 : 0);
    }
}

static void random_primitive(struct scene *s)
{
    fc_rng *r = &s->r;
    GLenum mode = fcr_modes[fc_rng_below(r, 6)];
    int style = (int)fc_rng_below(r, 6) % 4;       /* fresh, tiny, sliver, huge */
    int n = vertex_count(r, mode);
    double v[4], anchor[4] = { 0, 0, 0, 1 }, second[4] = { 0, 0, 0, 1 };

    glBegin(mode);
    for (int k = 0; k < n; k++) {
        int dim = pick_vertex(s, style, k, anchor, second, v);
        if (k == 0) memcpy(anchor, v, sizeof anchor);
        if (k == 1) memcpy(second, v, sizeof second);
        if (fc_rng_chance(r, 90))
            fcr_emit_color(s);
        if (dim < 4 && v[3] != 1)
            dim = 4;
        if (dim == 2 && v[2] != 0)
            dim = 3;
        fcr_emit_vertex(s, v, dim);
        memcpy(s->pool[s->npool++ % POOL], v, sizeof v);
    }
    glEnd();
}

void fcr_clear(fc_rng *r, GLbitfield bits)
{
    static const double cd[6] = { 0.0, 1.0, 0.5, 1.0 / 3.0, -1.0, 2.0 };
    glClearColor((GLfloat)fc_rng_unit(r), (GLfloat)fc_rng_unit(r),
                 (GLfloat)fc_rng_unit(r), (GLfloat)fc_rng_unit(r));
    glClearDepth(fc_rng_chance(r, 60) ? cd[fc_rng_below(r, 6)] : fc_rng_unit(r));
    glClear(bits);
}

static void random_scene(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    struct scene s;
    uint64_t seed;
    uint32_t index;
    int nprim;

    memset(&s, 0, sizeof s);
    fc_random_parse(c->name, &seed, &index);
    s.r = fc_rng_make(seed, index, 2);
    s.vis = fc_rng_make(seed, index, 30);
    fce_scene_begin(FCE_PLAIN, seed, index, index);
    s.w = c->width;
    s.h = c->height;
    s.space = (enum space)(fc_rng_below(&s.r, 100) < 45 ? SP_PIXEL : 1 + fc_rng_below(&s.r, 4));

    fcr_clear(&s.r, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    fcr_viewport(&s);
    fcr_depth_range(&s.r);
    fcr_projection(&s);
    glLoadIdentity();
    for (int k = fc_rng_chance(&s.r, s.space == SP_PIXEL ? 20 : 60) ? fc_rng_range(&s.r, 1, 3) : 0; k > 0; k--)
        random_transform(&s);
    if (fc_rng_chance(&s.r, 70))
        glEnable(GL_DEPTH_TEST);
    glDepthFunc(fcr_depth_funcs[fc_rng_below(&s.r, 8)]);
    glShadeModel(fc_rng_chance(&s.r, 50) ? GL_FLAT : GL_SMOOTH);

    nprim = fc_rng_range(&s.r, 1, 12);
    const int witness = fc_rng_range(&s.vis, 0, nprim);      /* before primitive witness */
    for (int p = 0; p <= nprim; p++) {
        if (p == witness)
            fcr_witness(&s);
        if (p == nprim)
            break;
        int pushed = fc_rng_chance(&s.r, 15);
        random_state_change(&s);
        if (pushed) {
            glPushMatrix();
            random_transform(&s);
        }
        random_primitive(&s);
        if (pushed)
            glPopMatrix();
        if (c->frames == 2 && p == nprim / 2) {
            fc_capture(h);
            if (fc_rng_chance(&s.r, 30))
                fcr_clear(&s.r, fc_rng_chance(&s.r, 50) ? GL_COLOR_BUFFER_BIT : GL_DEPTH_BUFFER_BIT);
        }
    }
    fc_capture(h);
    fc_error(h, "scene glGetError");
}

void fc_random_case(uint64_t seed, uint32_t index, fc_case *out, char *name)
{
    static const GLenum formats[10] = {
        OSMESA_RGBA, OSMESA_RGBA, OSMESA_RGBA, OSMESA_RGBA, OSMESA_RGBA,
        OSMESA_RGBA, OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB, OSMESA_RGB,
    };
    static const int depths[12] = { 24, 24, 24, 24, 24, 24, 24, 24, 16, 32, 16, 0 };
    fc_rng r = fc_rng_make(seed, index, 1);
    int size = (int)fc_rng_below(&r, 100);

    snprintf(name, FC_RANDOM_NAME_MAX, "random/s%" PRIu64 "-i%" PRIu32, seed, index);
    memset(out, 0, sizeof *out);
    out->draws_nothing = FC_MAY_DRAW_NOTHING;   /* a generated scene (fc_case.h) */
    out->name = name;
    if (size < 88) {
        out->width = fc_rng_range(&r, 16, 128);
        out->height = fc_rng_range(&r, 16, 128);
    } else if (size < 98) {
        out->width = fc_rng_range(&r, 129, 320);
        out->height = fc_rng_range(&r, 129, 320);
    } else {
        out->width = fc_rng_range(&r, 1, 15);
        out->height = fc_rng_range(&r, 1, 15);
    }
    out->format = formats[fc_rng_below(&r, 10)];
    out->depth_bits = depths[fc_rng_below(&r, 12)];
    out->stencil_bits = fc_rng_chance(&r, 20) ? 8 : 0;
    out->frames = fc_rng_chance(&r, 30) ? 2 : 1;
    out->tags = "random";
    out->fn = random_scene;
}
