/* p_materialf_vector.c - an oracle defect: Mesa's glMaterialf hands
 * glMaterialfv a four-float array of which only the first element is set,
 * so glMaterialf with a vector pname (GL_DIFFUSE here: GL raises no error
 * in either library) stores whatever the stack held in components 1-3
 * (ORACLE-NOTES.md "OSMesa defects kept visible"; the API fuzzer's seed 59).
 * fixgl stores (param, 0, 0, 0).  The probe fills the stack below the
 * caller with a pattern first and expects to read some of it back.
 * glMateriali does the same with a one-float variable (api_loopback.c:
 * `GLfloat p = (GLfloat) param; MATERIALFV(face, pname, &p)`): three
 * floats past it are read (the API fuzzer's seed 189). */
#include "probe.h"

static volatile float sink;

/* Leaves 4 KB of stack below the caller's frame holding v. */
static __attribute__((noinline)) void poison_stack(float v)
{
   volatile float pad[1024];
   for (int i = 0; i < 1024; i++)
      pad[i] = v;
   sink = pad[511];
}

int main(void)
{
   probe_init_ub(16, 16);
   int garbage = 0;
   for (int t = 0; t < 8; t++) {
      float v[4] = { -1, -1, -1, -1 };
      poison_stack(1000.0f + (float)t);
      glMaterialf(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.25f);
      glGetMaterialfv(GL_BACK, GL_DIFFUSE, v);
      probe_expect("glMaterialf(GL_DIFFUSE): component 0 is the parameter", v[0] == 0.25f, 1);
      garbage |= v[1] != 0.0f || v[2] != 0.0f || v[3] != 0.0f;
   }
   probe_expect("glMaterialf(GL_DIFFUSE): no error", glGetError(), GL_NO_ERROR);
   probe_expect("glMaterialf(GL_DIFFUSE): components 1-3 not zero (defect: 1)", garbage, 1);
   garbage = 0;
   for (int t = 0; t < 8; t++) {
      float v[4] = { -1, -1, -1, -1 };
      poison_stack(2000.0f + (float)t);
      glMateriali(GL_FRONT_AND_BACK, GL_EMISSION, 3);
      glGetMaterialfv(GL_FRONT, GL_EMISSION, v);
      probe_expect("glMateriali(GL_EMISSION): component 0 is the parameter", v[0] == 3.0f, 1);
      garbage |= v[1] != 0.0f || v[2] != 0.0f || v[3] != 0.0f;
   }
   probe_expect("glMateriali(GL_EMISSION): no error", glGetError(), GL_NO_ERROR);
   probe_expect("glMateriali(GL_EMISSION): components 1-3 not zero (defect: 1)", garbage, 1);
   /* glMaterialfv with the four values is exact */
   const float d[4] = { 0.1f, 0.2f, 0.3f, 0.4f };
   float v[4] = { 0 };
   glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, d);
   glGetMaterialfv(GL_BACK, GL_DIFFUSE, v);
   probe_expect("glMaterialfv(GL_DIFFUSE) stores its four values",
                v[0] == d[0] && v[1] == d[1] && v[2] == d[2] && v[3] == d[3], 1);
   return probe_result();
}
