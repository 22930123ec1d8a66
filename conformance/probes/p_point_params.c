/* p_point_params.c - glPointParameter (ORACLE-NOTES.md "Point
 * parameters"): under a distance attenuation the vertex program's size
 * rsq(|a0 + d*(a1 + d*a2)|) * Size, d = |z_eye|, clamped to
 * [max(MinSize, 1), min(MaxSize, 255)], rasterized as a legacy point of
 * that size; without attenuation the size clamped to [MinSize, MaxSize]
 * (Mesa's CLAMP); the fade threshold changes nothing. */
#include "probe.h"

/* the legacy point's whole size (lp_setup_point.c) */
static int legacy_width(float size)
{
    int fw = (snap_iround(size) + 127) & ~255;
    if (fw < 256)
        fw = 256;
    return fw >> 8;
}

/* the width of the square of lit pixels in row y (0 when none) */
static int lit_width(int S)
{
    int w = 0;
    for (int y = 0; y < S; y++) {
        int n = 0;
        for (int x = 0; x < S; x++)
            n += px(x, y)[0] != 0;
        if (n > w)
            w = n;
    }
    return w;
}

int main(void)
{
    const int S = 64;
    probe_init_ub(S, S);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, S, 0, S, 0.1, 1000);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    srand(7);
    long bad = 0, n = 0;
    for (int iter = 0; iter < 400; iter++) {
        const float a[3] = { 0.2f + (float)(rand() % 100) / 50.0f, (float)(rand() % 100) / 200.0f,
                             (float)(rand() % 100) / 4000.0f };
        const float size = 1.0f + (float)(rand() % 400) / 10.0f;
        const float mn = (float)(rand() % 60) / 10.0f, mx = 5.0f + (float)(rand() % 300) / 10.0f;
        const float d = 0.5f + (float)(rand() % 4000) / 100.0f;
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, a);
        glPointParameterf(GL_POINT_SIZE_MIN, mn);
        glPointParameterf(GL_POINT_SIZE_MAX, mx);
        glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, (float)(rand() % 50));
        glPointSize(size);
        clear0();
        glColor3f(1, 1, 1);
        glBegin(GL_POINTS);
        glVertex3f(32.25f, 31.75f, -d);
        glEnd();
        glFinish();
        /* the model: z_eye = -d exactly (identity modelview), MADs as a
         * multiply and an add, rsq as 1/sqrt */
        float t = d * a[2] + a[1];
        t = d * t + a[0];
        float s = (1.0f / sqrtf(fabsf(t))) * size;
        const float lo = mn >= 1.0f ? mn : 1.0f, hi = mx <= 255.0f ? mx : 255.0f;
        s = s > lo ? s : lo;
        s = s < hi ? s : hi;
        n++;
        if (lit_width(S) != legacy_width(s))
            bad++;
        /* and every lit pixel white: no fade */
        for (int y = 0; y < S; y++)
            for (int x = 0; x < S; x++)
                if (px(x, y)[0] && (px(x, y)[0] != 255 || px(x, y)[3] != 255))
                    bad++;
    }
    /* no attenuation: Size clamped to [MinSize, MaxSize] */
    const float none[3] = { 1, 0, 0 };
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);
    for (int iter = 0; iter < 200; iter++) {
        const float size = 0.5f + (float)(rand() % 300) / 10.0f;
        const float mn = (float)(rand() % 200) / 10.0f, mx = (float)(rand() % 300) / 10.0f;
        glPointParameterf(GL_POINT_SIZE_MIN, mn);
        glPointParameterf(GL_POINT_SIZE_MAX, mx);
        glPointSize(size);
        clear0();
        glBegin(GL_POINTS);
        glVertex3f(32.25f, 31.75f, -5);
        glEnd();
        glFinish();
        const float s = size > mn ? (size > mx ? mx : size) : mn;   /* Mesa's CLAMP */
        n++;
        if (lit_width(S) != legacy_width(s))
            bad++;
    }
    printf("     %ld points\n", n);
    probe_expect("point parameters: sizes drawn differently", bad, 0);
    return probe_result();
}
