/* p_points.c - legacy (non-sprite) points: size rounding, snapping, the
 * square's placement for odd and even sizes (ORACLE-NOTES.md "Line and
 * point rasterization"). */
#include "probe.h"
int main(void) {
  const int S = 40; probe_init_ub(S, S);
  srand(1); long bad = 0, n = 0;
  for (int iter = 0; iter < 500; iter++) {
    float size = (iter % 5 == 0) ? 1.0f + (rand() % 100) / 25.0f : (float)(1 + rand() % 6);
    float x = 3 + (rand() % ((S-6)*16)) / 16.0f, y = 3 + (rand() % ((S-6)*16)) / 16.0f;
    glPointSize(size); clear0(); glColor3f(1,1,1); glBegin(GL_POINTS); glVertex2f(x, y); glEnd(); glFinish();
    float gx, gy; win_from_ortho(x, y, S, S, &gx, &gy);
    int x0 = snap_iround(gx), y0 = snap_iround(gy) - 1;                        /* adj = 1 (bottom_edge_rule) */
    int fw = ((snap_iround(size) + 127) & ~255); if (fw < 256) fw = 256; int iw = fw >> 8;
    int bx0, by0;
    if (iw == 1) { bx0 = x0 >> 8; by0 = y0 >> 8; }
    else if (iw & 1) { bx0 = (x0 >> 8) - (iw-1)/2; by0 = (y0 >> 8) - (iw-1)/2; }
    else { bx0 = ((x0 + 128) >> 8) - iw/2; by0 = ((y0 + 128) >> 8) - iw/2; }
    for (int py = 0; py < S; py++) for (int px2 = 0; px2 < S; px2++) {
      int in = px2 >= bx0 && px2 < bx0 + iw && py >= by0 && py < by0 + iw;     /* gallium y-down */
      int got = px(px2, S-1-py)[0] != 0; n++; if (in != got) bad++;
    }
  }
  printf("     500 points, %ld pixels\n", n);
  probe_expect("points: pixels covered differently", bad, 0);
  return probe_result();
}
