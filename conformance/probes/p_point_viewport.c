/* p_point_viewport.c - points and lines under a per-vertex point size
 * (ORACLE-NOTES.md "Point parameters", "Point sprites"): while
 * GL_POINT_DISTANCE_ATTENUATION is not (1, 0, 0), llvmpipe cuts legacy
 * points, sprites and non-smooth lines to the viewport rectangle (vpwh:
 * (int)(x0 + 0.499f) .. (int)(x1 - 0.501f) inclusive, truncated toward
 * zero, y-down) besides the framebuffer and the scissor box; smooth points
 * are not cut.  A sprite cut at its bottom (y-down) by that region, by the
 * scissor box or not, also covers the one row below it, inside the
 * framebuffer and the same 64-row band of tiles.
 *
 * Each case draws the primitive twice: without attenuation at size 2s
 * (reference R) and with attenuation (0.25, 0, 0) at size s (so the
 * vertex's size is exactly 2s), and compares the second image with R cut
 * as the rule says, byte for byte. */
#include <stdbool.h>

#include "probe.h"

enum { W = 80, H = 72 };

static unsigned char ref[W * H * 4];
/* sprites with the row below the region, and with one kept off by the
 * 64-row band */
static long leaks, band_stops;

/* the region, y-down, exclusive ends */
struct region { int x0, y0, x1, y1; };

static struct region vp_region(int vx, int vy, int vw, int vh, bool attenuated,
                               bool scissor, const int sc[4])
{
    struct region r = { 0, 0, W, H };
    if (scissor) {
        int sx1 = sc[0] + sc[2], sy1 = sc[1] + sc[3];
        int x0 = sc[0] > 0 ? sc[0] : 0, x1 = sx1 < W ? sx1 : W;
        int gy0 = sc[1] > 0 ? sc[1] : 0, gy1 = sy1 < H ? sy1 : H;
        r.x0 = x0;
        r.x1 = x1;
        r.y0 = H - gy1;
        r.y1 = H - gy0;
    }
    if (attenuated) {
        const float hw = 0.5f * (float)vw, hh = 0.5f * (float)vh;
        const float tx = hw + (float)vx, ty = (float)H - (hh + (float)vy);
        const int x0 = (int)((tx - hw) + 0.499f), x1 = (int)((tx + hw) - 0.501f) + 1;
        const int y0 = (int)((ty - hh) + 0.499f), y1 = (int)((ty + hh) - 0.501f) + 1;
        if (r.x0 < x0) r.x0 = x0;
        if (r.y0 < y0) r.y0 = y0;
        if (r.x1 > x1) r.x1 = x1;
        if (r.y1 > y1) r.y1 = y1;
    }
    if (r.x0 >= r.x1 || r.y0 >= r.y1)
        r.x0 = r.y0 = r.x1 = r.y1 = 0;
    return r;
}

static int inside(const struct region *r, int x, int ydown)
{
    return x >= r->x0 && x < r->x1 && ydown >= r->y0 && ydown < r->y1;
}

/* R cut to the region; a sprite also keeps the row below the region where
 * R reaches beyond the region's bottom */
static long compare_cut(const struct region *r, bool sprite)
{
    long bad = 0;
    int leak = 0;
    if (sprite && r->y1 > r->y0 && r->y1 < H) {
        /* R reaches the row below the region inside its columns */
        for (int x = r->x0; x < r->x1; x++)
            if (ref[4 * ((H - 1 - r->y1) * W + x)])
                leak = 1;
        if (leak && r->y1 % 64 == 0) {
            band_stops++;
            leak = 0;
        }
        leaks += leak;
    }
    for (int gy = 0; gy < H; gy++) {
        const int yd = H - 1 - gy;
        for (int x = 0; x < W; x++) {
            const unsigned char *a = px(x, gy), *b = ref + 4 * (gy * W + x);
            int keep = inside(r, x, yd) || (leak && yd == r->y1 && x >= r->x0 && x < r->x1);
            for (int c = 0; c < 4; c++)
                bad += a[c] != (keep ? b[c] : 0);
        }
    }
    return bad != 0;
}

static void draw(int kind, float s, const float *p)
{
    glClear(GL_COLOR_BUFFER_BIT);
    if (kind == 3) {
        glLineWidth(s);
        glBegin(GL_LINES);
        glVertex2f(p[0], p[1]);
        glVertex2f(p[2], p[3]);
        glEnd();
    } else {
        glPointSize(s);
        glBegin(GL_POINTS);
        glVertex2f(p[0], p[1]);
        glEnd();
    }
    glFinish();
}

int main(void)
{
    probe_init_ub(W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 0);
    glColor4f(1, 1, 1, 1);
    const float none[3] = { 1, 0, 0 }, quarter[3] = { 0.25f, 0, 0 };
    srand(11);
    static const char *names[] = { "legacy points", "sprites", "smooth points", "lines" };
    long bad[4] = { 0 }, n[4] = { 0 }, cut[4] = { 0 };
    for (int iter = 0; iter < 1600; iter++) {
        const int kind = iter % 4;
        const int vx = rand() % 130 - 45;
        /* every other sprite's viewport ends at y-down row 64 (a tile) */
        const int vy = kind == 1 && iter % 8 == 1 ? 8 : rand() % 120 - 45;
        const int vw = 1 + rand() % 80, vh = 1 + rand() % 80;
        const bool scissor = rand() % 4 == 0;
        const int sc[4] = { rand() % 70 - 5, rand() % 60 - 5, 1 + rand() % 60, 1 + rand() % 60 };
        /* smooth points from size 3 on (below, the constant size has the
         * "2 or less gives radius 1" rule, the per-vertex one not) */
        const float s = kind == 3 ? 0.5f + (float)(rand() % 16) / 2.0f
                                  : (kind == 2 ? 1.5f : 0.5f) + (float)(rand() % 60) / 4.0f;
        const float p[4] = { (float)(rand() % 2400 - 1200) / 1000.0f, (float)(rand() % 2400 - 1200) / 1000.0f,
                             (float)(rand() % 2400 - 1200) / 1000.0f, (float)(rand() % 2400 - 1200) / 1000.0f };
        glViewport(vx, vy, vw, vh);
        if (kind == 1) glEnable(GL_POINT_SPRITE); else glDisable(GL_POINT_SPRITE);
        if (kind == 2) glEnable(GL_POINT_SMOOTH); else glDisable(GL_POINT_SMOOTH);
        /* the reference: a constant size, no scissor (cut below) */
        glDisable(GL_SCISSOR_TEST);
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);
        draw(kind, kind == 3 ? s : 2.0f * s, p);
        memcpy(ref, g_buf, sizeof ref);
        /* attenuated; the scissor is set after the clear (draw clears) */
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, quarter);
        if (scissor) {
            glScissor(sc[0], sc[1], sc[2], sc[3]);
        }
        glClear(GL_COLOR_BUFFER_BIT);
        if (scissor)
            glEnable(GL_SCISSOR_TEST);
        if (kind == 3) {
            glLineWidth(s);
            glBegin(GL_LINES);
            glVertex2f(p[0], p[1]);
            glVertex2f(p[2], p[3]);
            glEnd();
        } else {
            glPointSize(s);
            glBegin(GL_POINTS);
            glVertex2f(p[0], p[1]);
            glEnd();
        }
        glFinish();
        glDisable(GL_SCISSOR_TEST);
        n[kind]++;
        if (kind == 2) {
            /* smooth: not cut by the viewport (scissor cut only) */
            const struct region r = vp_region(vx, vy, vw, vh, false, scissor, sc);
            bad[kind] += compare_cut(&r, false);
            continue;
        }
        const struct region r = vp_region(vx, vy, vw, vh, true, scissor, sc);
        const struct region r0 = vp_region(vx, vy, vw, vh, false, scissor, sc);
        bad[kind] += compare_cut(&r, kind == 1);
        /* the cut shows: the image differs from the one without it */
        cut[kind] += memcmp(&r, &r0, sizeof r) != 0 && memcmp(g_buf, ref, sizeof ref) != 0;
    }
    for (int k = 0; k < 4; k++) {
        char what[96];
        snprintf(what, sizeof what, "%s: cases differing from the model (of %ld, %ld cut)", names[k], n[k], cut[k]);
        probe_expect(what, bad[k], 0);
    }
    printf("sprites keeping the row below the region: %ld, stopped by the tile band: %ld\n",
           leaks, band_stops);
    probe_expect("the sprite rule's two branches both seen", leaks > 0 && band_stops > 0, 1);
    return probe_result();
}
