/* p_lines.c - non-antialiased lines: the "diamond exit" parallelogram of
 * llvmpipe's line setup, its snapping, width and attribute planes
 * (ORACLE-NOTES.md "Line and point rasterization").  Coverage and
 * colours of random lines, widths 0.6 to 4, float colour buffer, exact
 * compare. */
#include "probe.h"
#define W 40
#define H 40
static float buf[W*H*4], ref[W*H*4];
static int sgn(float x) { return x >= 0; }
static float fracf_(float f) { return f - floorf(f); }
typedef struct { float x, y, c[4]; } LV;
static void model_line(LV a, LV b, float lw) {
  float width = lw > 1.0f ? lw : 1.0f;
  const LV *v1 = &a, *v2 = &b;
  float dx = v1->x - v2->x, dy = v1->y - v2->y; float area = dx*dx + dy*dy; if (area == 0) return;
  float ooa = 1.0f / area, idx = dx, idy = dy; const LV *o1 = v1, *o2 = v2;  /* info.v1/v2 keep original order */
  float xo = 0, yo = 0, xoe = 0, yoe = 0;
  float x1d = v1->x - floorf(v1->x) - 0.5f, y1d = v1->y - floorf(v1->y) - 0.5f;
  float x2d = v2->x - floorf(v2->x) - 0.5f, y2d = v2->y - floorf(v2->y) - 0.5f;
  int fw = (int)(width >= 0 ? (int)(width + 0.5f) : (int)(width - 0.5f)) * 256;
  int X[4], Y[4]; int ds, de;
  if (fabsf(dx) >= fabsf(dy)) {
    float dydx = dy / dx;
    if (y2d == -0.5f && dy < 0) y2d = 0.5f;
    if (fabsf(x1d) + fabsf(y1d) < 0.5f) ds = 1; else if (sgn(x1d) == sgn(-dx)) ds = 0; else if (sgn(-y1d) != sgn(dy)) ds = 1;
    else { float yi = fracf_(v1->y) + x1d * dydx; ds = (yi < 1.0f && yi > 0.0f); }
    if (fabsf(x2d) + fabsf(y2d) < 0.5f) de = 0; else if (sgn(x2d) != sgn(-dx)) de = 0; else if (sgn(-y2d) == sgn(dy)) de = 1;
    else { float yi = fracf_(v2->y) + x2d * dydx; de = (yi < 1.0f && yi > 0.0f); }
    int wds = sgn(-x1d) != sgn(dx); int wde = (sgn(x2d) == sgn(-dx)) || x2d == 0;
    idx *= 1 + dydx * dydx; idy = 0;
    if (dx < 0) { const LV *t = v1; v1 = v2; v2 = t; dx = -dx; dy = -dy;
      if (wds != ds) { xoe = -x1d - 0.5f; yoe = xoe * dydx; } if (wde != de) { xo = -x2d - 0.5f; yo = xo * dydx; } }
    else { if (wds != ds) { xo = -x1d + 0.5f; yo = xo * dydx; } if (wde != de) { xoe = -x2d + 0.5f; yoe = xoe * dydx; } }
    X[0] = snap_iround(v1->x + xo - 0.5f); X[1] = snap_iround(v2->x + xoe - 0.5f); X[2] = X[1]; X[3] = X[0];
    Y[0] = snap_iround(v1->y + yo - 0.5f) - fw/2; Y[1] = snap_iround(v2->y + yoe - 0.5f) - fw/2;
    Y[2] = snap_iround(v2->y + yoe - 0.5f) + fw/2; Y[3] = snap_iround(v1->y + yo - 0.5f) + fw/2;
  } else {
    float dxdy = dx / dy;
    if (x2d == -0.5f && dx < 0) x2d = 0.5f;
    if (fabsf(x1d) + fabsf(y1d) < 0.5f) ds = 1; else if (sgn(-y1d) == sgn(dy)) ds = 0; else if (sgn(x1d) != sgn(-dx)) ds = 1;
    else { float xi = fracf_(v1->x) + y1d * dxdy; ds = (xi < 1.0f && xi > 0.0f); }
    if (fabsf(x2d) + fabsf(y2d) < 0.5f) de = 0; else if (sgn(-y2d) != sgn(dy)) de = 0; else if (sgn(x2d) == sgn(-dx)) de = 1;
    else { float xi = fracf_(v2->x) + y2d * dxdy; de = (xi < 1.0f && xi >= 0.0f); }
    int wds = sgn(y1d) == sgn(dy); int wde = (sgn(-y2d) == sgn(dy)) || y2d == 0;
    idx = 0; idy *= 1 + dxdy * dxdy;
    if (dy > 0) { const LV *t = v1; v1 = v2; v2 = t; dx = -dx; dy = -dy;
      if (wds != ds) { yoe = -y1d + 0.5f; xoe = yoe * dxdy; } if (wde != de) { yo = -y2d + 0.5f; xo = yo * dxdy; } }
    else { if (wds != ds) { yo = -y1d - 0.5f; xo = yo * dxdy; } if (wde != de) { yoe = -y2d - 0.5f; xoe = yoe * dxdy; } }
    X[0] = snap_iround(v1->x + xo - 0.5f) - fw/2; X[1] = snap_iround(v2->x + xoe - 0.5f) - fw/2;
    X[2] = snap_iround(v2->x + xoe - 0.5f) + fw/2; X[3] = snap_iround(v1->x + xo - 0.5f) + fw/2;
    Y[0] = snap_iround(v1->y + yo - 0.5f); Y[1] = snap_iround(v2->y + yoe - 0.5f); Y[2] = Y[1]; Y[3] = Y[0];
  }
  long long c[4]; int dcdx[4], dcdy[4];
  for (int i = 0; i < 4; i++) { int j = (i+1)&3; dcdy[i] = X[i]-X[j]; dcdx[i] = Y[i]-Y[j];
    c[i] = (long long)dcdx[i]*X[i] - (long long)dcdy[i]*Y[i];
    if (dcdx[i] < 0) c[i]++; else if (dcdx[i] == 0 && dcdy[i] < 0) c[i]++; }
  for (int py = 0; py < H; py++) for (int px = 0; px < W; px++) {
    int in = 1; for (int i = 0; i < 4; i++) if (c[i] - (long long)dcdx[i]*px*256 + (long long)dcdy[i]*py*256 <= 0) in = 0;
    if (!in) continue;
    float *r = &ref[4*((H-1-py)*W + px)];
    for (int k = 0; k < 4; k++) {   /* perspective_coef with 1/w = 1 */
      float a1 = o1->c[k] * 1.0f, a2 = o2->c[k] * 1.0f; float da = a1 - a2;
      float dadx = da * idx * ooa, dady = da * idy * ooa;
      float a0 = a1 - (dadx * (o1->x - 0.5f) + dady * (o1->y - 0.5f));
      r[k] = fmaf(dady, (float)py, fmaf(dadx, (float)px, a0)) * 1.0f;
    }
  }
}
int main(void) {
  probe_init_float(buf, W, H); glMatrixMode(GL_PROJECTION); glLoadIdentity(); glOrtho(0,W,0,H,-1,1);
  srand(1);
  long bad_cov = 0, bad_col = 0, tot = 0;
  for (int iter = 0; iter < 400; iter++) {
    float lw = (float)(1 + iter % 4) - ((iter % 7 == 0) ? 0.4f : 0.0f);
    float vx[2], vy[2], col[2][4];
    for (int i = 0; i < 2; i++) { vx[i] = 4 + (rand() % ((W-8)*8)) / 8.0f; vy[i] = 4 + (rand() % ((H-8)*8)) / 8.0f;
      if (iter % 3 == 0) { vx[i] = floorf(vx[i]) + 0.5f; }  /* some endpoints on pixel centres */
      for (int k = 0; k < 4; k++) col[i][k] = (rand() % 1000) / 1000.0f; }
    glLineWidth(lw);
    glClearColor(-1,-1,-1,-1); glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_LINES); for (int i = 0; i < 2; i++) { glColor4fv(col[i]); glVertex2f(vx[i], vy[i]); } glEnd(); glFinish();
    for (int i = 0; i < W*H*4; i++) ref[i] = -1.0f;
    LV a, b; win_from_ortho(vx[0], vy[0], W, H, &a.x, &a.y); win_from_ortho(vx[1], vy[1], W, H, &b.x, &b.y);
    for (int k = 0; k < 4; k++) { a.c[k] = col[0][k]; b.c[k] = col[1][k]; }
    model_line(a, b, lw);
    for (int i = 0; i < W*H; i++) { int gc = buf[4*i] != -1.0f, rc = ref[4*i] != -1.0f; if (gc != rc) bad_cov++;
      if (gc && rc) for (int k = 0; k < 4; k++) { tot++; if (buf[4*i+k] != ref[4*i+k]) bad_col++; } }
  }
  printf("     400 lines, %ld channels\n", tot);
  probe_expect("lines: pixels covered differently", bad_cov, 0);
  probe_expect("lines: colour channels missed", bad_col, 0);
  return probe_result();
}
