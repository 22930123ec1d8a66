/* p_clip.c - clipping in the draw module: outcodes, plane order, the
 * interpolation of new vertices, their unfused window coordinates, the fan
 * of the clipped polygon; then the setup and interpolation models
 * (ORACLE-NOTES.md "Clipping").  Float colour buffer, exact compare. */
#include "probe.h"
#define W 60
#define H 60
static float buf[W*H*4];
static float ref[W*H*4];
typedef struct { float clip[4]; float win[4]; float c[4]; unsigned mask; } CV;
static int g_fused_new;
static const float planes[6][4] = { {-1,0,0,1},{1,0,0,1},{0,-1,0,1},{0,1,0,1},{0,0,1,1},{0,0,-1,1} };
static float SX = W/2.0f, TX = W/2.0f, SY = -H/2.0f, TY = H - H/2.0f;
static void win_llvm(CV *v) { float oow = 1.0f / v->clip[3];
  v->win[0] = fmaf(v->clip[0]*oow, SX, TX); v->win[1] = fmaf(v->clip[1]*oow, SY, TY); v->win[3] = oow; }
static void win_c(CV *v) { volatile float oow = 1.0f / v->clip[3]; volatile float a = v->clip[0]*oow; volatile float b = a*SX;
  v->win[0] = b + TX; a = v->clip[1]*oow; b = a*SY; v->win[1] = b + TY; v->win[3] = oow; }
/* outcodes: bit 0 x > w, 1 x + w < 0, 2 y > w, 3 y + w < 0, 4 z + w < 0,
 * 5 z > w; on the boundary is inside */
static unsigned cmask(const float *p) {
  return (p[0] > p[3]) | (p[0] + p[3] < 0) << 1 | (p[1] > p[3]) << 2 | (p[1] + p[3] < 0) << 3 |
         (p[2] + p[3] < 0) << 4 | (p[2] > p[3]) << 5; }
static float dot4(const float *a, const float *b) { return a[0]*b[0] + a[1]*b[1] + a[2]*b[2] + a[3]*b[3]; }
static float lint(float t, float out, float in) { return out + t * (in - out); }
static void interp(CV *d, float t, const CV *out, const CV *in) {
  for (int i = 0; i < 4; i++) d->clip[i] = lint(t, out->clip[i], in->clip[i]);
  if (g_fused_new) win_llvm(d); else win_c(d);
  for (int i = 0; i < 4; i++) d->c[i] = lint(t, out->c[i], in->c[i]);
}
/* raster one triangle into ref (llvmpipe setup model, colours perspective-interpolated) */
static void raster(const CV *a, const CV *b, const CV *c) {
  const CV *g[3] = { a, b, c };
  int X[3], Y[3]; for (int i=0;i<3;i++){ X[i]=snap_rne(g[i]->win[0]-0.5f); Y[i]=snap_rne(g[i]->win[1]-0.5f); }
  long long area = (long long)(X[0]-X[1])*(Y[2]-Y[0]) - (long long)(X[2]-X[0])*(Y[0]-Y[1]);
  if (area == 0) return;
  const CV *o[3]; int OX[3], OY[3];
  if (area > 0) { o[0]=g[0]; o[1]=g[1]; o[2]=g[2]; } else { o[0]=g[1]; o[1]=g[0]; o[2]=g[2]; }
  for (int i=0;i<3;i++){ OX[i]=snap_rne(o[i]->win[0]-0.5f); OY[i]=snap_rne(o[i]->win[1]-0.5f); }
  float x0c = o[0]->win[0] - 0.5f, y0c = o[0]->win[1] - 0.5f;
  float dx01 = o[0]->win[0] - o[1]->win[0], dy01 = o[0]->win[1] - o[1]->win[1];
  float dx20 = o[2]->win[0] - o[0]->win[0], dy20 = o[2]->win[1] - o[0]->win[1];
  float e = dx01 * dy20, f = dy01 * dx20; float ooa = 1.0f / (e - f);
  float dx20o = dx20*ooa, dy20o = dy20*ooa, dx01o = dx01*ooa, dy01o = dy01*ooa;
#define COEF(A0,A1,A2,DADX,DADY,AC) { float da01=(A0)-(A1), da20=(A2)-(A0); float t1=da01*dy20o, t2=da20*dy01o; DADX=t1-t2; \
      float t3=da20*dx01o, t4=da01*dx20o; DADY=t3-t4; float s1=DADX*x0c, s2=DADY*y0c; float s=s1+s2; AC=(A0)-s; }
  float wdx, wdy, wac; COEF(o[0]->win[3], o[1]->win[3], o[2]->win[3], wdx, wdy, wac);
  /* edge functions (fixed point, bottom_edge_rule=1) */
  long long cc[3]; int dcdx[3], dcdy[3];
  for (int i = 0; i < 3; i++) { int j = (i+1)%3; dcdx[i] = OY[i]-OY[j]; dcdy[i] = OX[i]-OX[j];
    cc[i] = (long long)dcdx[i]*OX[i] - (long long)dcdy[i]*OY[i];
    if (dcdx[i] < 0) cc[i]++; else if (dcdx[i] == 0 && dcdy[i] < 0) cc[i]++; }
  for (int py = 0; py < H; py++) for (int px = 0; px < W; px++) {
    int in = 1;
    for (int i = 0; i < 3; i++) { long long v = cc[i] - (long long)dcdx[i]*(px*256) + (long long)dcdy[i]*(py*256); if (v <= 0) in = 0; }
    if (!in) continue;
    float wi = fmaf(wdy, (float)py, fmaf(wdx, (float)px, wac)); float rw = 1.0f / wi;
    float *r = &ref[4*((H-1-py)*W + px)];
    for (int k = 0; k < 4; k++) { float A0 = o[0]->c[k]*o[0]->win[3], A1 = o[1]->c[k]*o[1]->win[3], A2 = o[2]->c[k]*o[2]->win[3];
      float dadx, dady, ac; COEF(A0, A1, A2, dadx, dady, ac); r[k] = fmaf(dady, (float)py, fmaf(dadx, (float)px, ac)) * rw; }
  }
}
static CV tmp[32];
static void clip_tri(CV *v0, CV *v1, CV *v2) {
  unsigned m = v0->mask | v1->mask | v2->mask;
  if (!m) { raster(v0, v1, v2); return; }
  if (v0->mask & v1->mask & v2->mask) return;
  CV *A[32], *B[32]; CV **inl = A, **outl = B; int n = 3, tn = 0;
  inl[0] = v0; inl[1] = v1; inl[2] = v2;
  while (m && n >= 3) {
    int pi = __builtin_ctz(m); m &= ~(1u << pi);
    CV *vp = inl[0]; float dpp = dot4(vp->clip, planes[pi]); int oc = 0;
    inl[n] = inl[0];
    for (int i = 1; i <= n; i++) {
      CV *v = inl[i]; float dp = dot4(v->clip, planes[pi]); int diff;
      if (dpp >= 0.0f) { outl[oc++] = vp; diff = dp < 0.0f; } else diff = !(dp < 0.0f);
      if (diff) { CV *nv = &tmp[tn++]; outl[oc++] = nv; float den = dp - dpp;
        if (dp < 0.0f) { if (-dp < dpp) interp(nv, dp/den, v, vp); else interp(nv, -dpp/den, vp, v); }
        else { if (-dpp < dp) interp(nv, -dpp/den, vp, v); else interp(nv, dp/den, v, vp); } }
      vp = v; dpp = dp;
    }
    CV **t = inl; inl = outl; outl = t; n = oc;
  }
  for (int i = 2; i < n; i++) raster(inl[i-1], inl[i], inl[0]);   /* emit_poly, flatshade last */
}
static void run(int seed, int fused_new, long *tot, long *bad, long *nclipped)
{
  g_fused_new = fused_new;
  srand(seed);
  for (int iter = 0; iter < 150; iter++) {
    CV v[3];
    for (int i = 0; i < 3; i++) {
      float w = 0.5f + (rand()%3000)/1000.0f;
      v[i].clip[0] = ((rand()%4000)/1000.0f - 2.0f) * w; v[i].clip[1] = ((rand()%4000)/1000.0f - 2.0f) * w;
      v[i].clip[2] = 0; v[i].clip[3] = w;
      for (int k = 0; k < 4; k++) v[i].c[k] = (rand()%100000)/100000.0f;
      v[i].mask = cmask(v[i].clip); win_llvm(&v[i]);
    }
    if (v[0].mask | v[1].mask | v[2].mask) (*nclipped)++;
    for (int i = 0; i < W*H*4; i++) ref[i] = -1.0f;
    glClearColor(-1,-1,-1,-1); glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES); for (int i = 0; i < 3; i++) { glColor4fv(v[i].c); glVertex4fv(v[i].clip); } glEnd(); glFinish();
    clip_tri(&v[0], &v[1], &v[2]);
    for (int i = 0; i < W*H*4; i++) { if (buf[i] == -1.0f && ref[i] == -1.0f) continue; (*tot)++; if (buf[i] != ref[i]) (*bad)++; }
  }
}
int main(void) {
  probe_init_float(buf, W, H);
  long tot = 0, bad = 0, nclipped = 0;
  run(9, 0, &tot, &bad, &nclipped);
  run(4, 0, &tot, &bad, &nclipped);
  printf("     %ld triangles clipped, %ld channels\n", nclipped, tot);
  probe_expect("clipped triangles: misses", bad, 0);
  long tot2 = 0, bad2 = 0, n2 = 0;
  run(9, 1, &tot2, &bad2, &n2);
  probe_expect("a model with fused window coordinates for new vertices misses some", bad2 > 0, 1);
  return probe_result();
}
