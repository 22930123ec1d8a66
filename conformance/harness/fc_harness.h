/* fc_harness.h - renderer-side entry point of the harness (fc_harness.c). */
#ifndef FC_HARNESS_H
#define FC_HARNESS_H

#include "fc_case.h"

#include <stdio.h>

/* Runs one case and writes its records (CASE ... END) to out.  perturb is a
 * test-only switch that alters the first byte of every captured frame. */
void fc_run_case(const fc_case *c, FILE *out, int perturb);

/* The fixed case table (cases/fc_registry.c). */
size_t fc_case_count(void);
const fc_case *fc_case_at(size_t i);

#endif
