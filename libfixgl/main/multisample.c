/*
 * GL_MULTISAMPLE_BIT: glSampleCoverage (GL 1.3, and its ARB alias).  The
 * enables (GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE,
 * GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE) are in main/enable.c.  The
 * oracle's OSMesa buffers have no samples, so none of this state changes
 * a pixel: it is stored, compiled into lists, pushed, popped and queried
 * as Mesa does [S: main/multisample.c, main/mtypes.h
 * gl_multisample_attrib].
 */
#define GL_GLEXT_PROTOTYPES 1
#include "main/groups.h"
#include "main/dlist.h"

/* [S: main/multisample.c:_mesa_SampleCoverage] the value saturated with
 * Mesa's CLAMP (X > MIN ? ... : MIN: a NaN becomes 0), the invert flag
 * kept as the byte given; nothing when unchanged */
void GLAPIENTRY glSampleCoverage(GLclampf value, GLboolean invert)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, SampleCoverage, value, invert);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   value = value > 0.0f ? (value > 1.0f ? 1.0f : value) : 0.0f;
   struct fgl_multisample_attrib *ms = &ctx->Multisample;
   if (ms->SampleCoverageInvert == invert && ms->SampleCoverageValue == value)
      return;
   FGL_FLUSH_VERTICES(ctx, 0);
   ms->SampleCoverageValue = value;
   ms->SampleCoverageInvert = invert;
}

void GLAPIENTRY glSampleCoverageARB(GLclampf value, GLboolean invert)
{
   glSampleCoverage(value, invert);
}
