/* p_fog.c - fog: the fog coordinate |z_eye| per vertex, interpolated like
 * a colour, the factor from the CPU-computed parameters, gallivm's exp2,
 * the blend fogcolor * (1 - f) + c * f in separate operations
 * (ORACLE-NOTES.md "Fog: coordinate and factor").  Float colour buffer,
 * exact compare. */
#include "probe.h"
#include "gallivm_math.h"

#define W 48
#define H 48
static float buf[W * H * 4];

static float rnd(void) { return (rand() % 10000) / 10000.0f; }

int main(void)
{
   probe_init_float(buf, W, H);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, W, 0, H, -1, 100);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   glEnable(GL_FOG);
   const GLenum modes[3] = { GL_LINEAR, GL_EXP, GL_EXP2 };
   const char *names[3] = { "GL_LINEAR", "GL_EXP", "GL_EXP2" };
   srand(12);
   for (int m = 0; m < 3; m++) {
      long tot = 0, bad = 0;
      glFogi(GL_FOG_MODE, modes[m]);
      for (int iter = 0; iter < 40; iter++) {
         float start = rnd() * 20.0f, end = start + 1.0f + rnd() * 80.0f, density = rnd() * 0.2f;
         float fogc[4] = { rnd(), rnd(), rnd(), rnd() }, col[4] = { rnd(), rnd(), rnd(), rnd() };
         glFogf(GL_FOG_START, start);
         glFogf(GL_FOG_END, end);
         glFogf(GL_FOG_DENSITY, density);
         glFogfv(GL_FOG_COLOR, fogc);
         float vx[3], vy[3], vz[3], gx[3], gy[3], fc[3];
         for (int i = 0; i < 3; i++) {
            vx[i] = (rand() % (W * 16)) / 16.0f;
            vy[i] = (rand() % (H * 16)) / 16.0f;
            vz[i] = -(rnd() * 99.0f);
            win_from_ortho(vx[i], vy[i], W, H, &gx[i], &gy[i]);
            /* z_eye: DP4 with the modelview's row 2 from the last
             * component, here ((1*0 + z*1) + y*0) + x*0 */
            float ze = ((1.0f * 0.0f + vz[i] * 1.0f) + vy[i] * 0.0f) + vx[i] * 0.0f;
            fc[i] = fabsf(ze);
         }
         glClearColor(-1, -1, -1, -1);
         glClear(GL_COLOR_BUFFER_BIT);
         glColor4fv(col);
         glBegin(GL_TRIANGLES);
         for (int i = 0; i < 3; i++) glVertex3f(vx[i], vy[i], vz[i]);
         glEnd();
         glFinish();
         int o[3];
         if (setup_order(gx, gy, o) == 0) continue;
         struct plane_setup s = plane_init(gx, gy, o);
         float r[3], rw[3];
         plane_coef(&s, fc[o[0]] * 1.0f, fc[o[1]] * 1.0f, fc[o[2]] * 1.0f, r);
         plane_coef(&s, 1.0f, 1.0f, 1.0f, rw);
         /* STATE_FOG_PARAMS_OPTIMIZED, on the CPU */
         float val = -1.0f / (end - start), p1 = end * -val;
         float p2 = (float)(density * 1.4426950408889634074);
         float p3 = (float)(density * 1.201122408786449815);
         for (int py = 0; py < H; py++)
            for (int x = 0; x < W; x++) {
               const float *p = &buf[4 * ((H - 1 - py) * W + x)];
               if (p[0] == -1.0f) continue;
               float c = plane_eval(r, x, py) * (1.0f / plane_eval(rw, x, py));
               float f;
               if (m == 0) f = c * val + p1;
               else if (m == 1) f = gv_exp2(-(c * p2));
               else { float t = c * p3; f = gv_exp2(-(t * t)); }
               f = f > 0.0f ? f : 0.0f;
               f = f < 1.0f ? f : 1.0f;
               float g = 1.0f + -f;
               for (int k = 0; k < 3; k++) {
                  tot++;
                  if (p[k] != fogc[k] * g + col[k] * f) bad++;
               }
               tot++;
               if (p[3] != col[3]) bad++; /* alpha untouched */
            }
      }
      char what[64];
      snprintf(what, sizeof what, "fog %s: %ld channels, misses", names[m], tot);
      probe_expect(what, bad, 0);
   }
   return probe_result();
}
