/* p_blend.c - blending on RGBA8 is 8-bit integer arithmetic: the source
 * colour converted first (RNE), each term round(a*f/255) as
 * (t + (t >> 8) + 128) >> 8, a saturating sum (ORACLE-NOTES.md
 * "Blending, alpha test, dithering"). */
#include "probe.h"
static int u8(float v){ if (v < 0) v = 0; if (v > 1) v = 1; return (int)nearbyintf(v * 255.0f); }
static int muln(int a, int b){ int t = a * b; return (t + (t >> 8) + 128) >> 8; }
static int fac(GLenum f, int c, const int *s, const int *d) {
  switch (f) { case GL_ZERO: return 0; case GL_ONE: return 255; case GL_SRC_COLOR: return s[c];
  case GL_ONE_MINUS_SRC_COLOR: return 255 - s[c]; case GL_SRC_ALPHA: return s[3]; case GL_ONE_MINUS_SRC_ALPHA: return 255 - s[3];
  case GL_DST_COLOR: return d[c]; case GL_ONE_MINUS_DST_COLOR: return 255 - d[c]; case GL_DST_ALPHA: return d[3];
  case GL_ONE_MINUS_DST_ALPHA: return 255 - d[3]; }
  return -1; }
int main(void) {
  probe_init_ub(64, 64);
  const GLenum fs[][2] = { {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA}, {GL_ONE, GL_ONE}, {GL_DST_COLOR, GL_ZERO},
    {GL_ONE, GL_ONE_MINUS_SRC_ALPHA}, {GL_SRC_ALPHA, GL_ONE}, {GL_ONE_MINUS_DST_COLOR, GL_SRC_COLOR}, {GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA} };
  const char *nm[] = { "SRC_ALPHA,1-SRC_ALPHA", "ONE,ONE", "DST_COLOR,ZERO", "ONE,1-SRC_ALPHA", "SRC_ALPHA,ONE", "1-DST_COLOR,SRC_COLOR", "DST_ALPHA,1-DST_ALPHA" };
  srand(5);
  long total_badf = 0;
  for (int b = 0; b < 7; b++) {
    static float dst[64*64][4], src[64*64][4];
    for (int i = 0; i < 64*64; i++) for (int c = 0; c < 4; c++) { dst[i][c] = (rand() % 1001) / 1000.0f; src[i][c] = (rand() % 1001) / 1000.0f; }
    glDisable(GL_BLEND); clear0();
    glBegin(GL_POINTS); for (int i = 0; i < 64*64; i++) { glColor4fv(dst[i]); glVertex2f(i % 64 + 0.5f, i / 64 + 0.5f); } glEnd();
    glEnable(GL_BLEND); glBlendFunc(fs[b][0], fs[b][1]);
    glBegin(GL_POINTS); for (int i = 0; i < 64*64; i++) { glColor4fv(src[i]); glVertex2f(i % 64 + 0.5f, i / 64 + 0.5f); } glEnd();
    glFinish();
    long bad = 0, badf = 0;
    for (int i = 0; i < 64*64; i++) {
      int s[4], d[4]; for (int c = 0; c < 4; c++) { s[c] = u8(src[i][c]); d[c] = u8(dst[i][c]); }
      for (int c = 0; c < 4; c++) {
        int r = muln(s[c], fac(fs[b][0], c, s, d)) + muln(d[c], fac(fs[b][1], c, s, d)); if (r > 255) r = 255;
        /* alternative: float blend then RNE */
        float sf = fac(fs[b][0], c, s, d) / 255.0f, df = fac(fs[b][1], c, s, d) / 255.0f;
        int rf = u8(s[c] / 255.0f * sf + d[c] / 255.0f * df);
        int got = px(i % 64, i / 64)[c];
        if (got != r) bad++;
        if (got != rf) badf++;
      }
    }
    char what[96];
    snprintf(what, sizeof what, "blend %s: channels the 8-bit model misses", nm[b]);
    probe_expect(what, bad, 0);
    total_badf += badf;
  }
  probe_expect("a float blending model misses some", total_badf > 0, 1);
  return probe_result();
}
