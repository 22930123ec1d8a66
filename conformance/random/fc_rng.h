/* fc_rng.h - the generator's own PRNG (splitmix64): deterministic across
 * platforms and processes, never rand(). */
#ifndef FC_RNG_H
#define FC_RNG_H

#include <stdint.h>

typedef struct fc_rng { uint64_t s; } fc_rng;

static inline uint64_t fc_rng_next(fc_rng *r)
{
    uint64_t z = (r->s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* A stream keyed by (seed, index, purpose). */
static inline fc_rng fc_rng_make(uint64_t seed, uint32_t index, uint32_t purpose)
{
    fc_rng r = { seed };
    fc_rng_next(&r);
    r.s ^= ((uint64_t)index << 32 | purpose) * 0xD6E8FEB86659FD93ull;
    fc_rng_next(&r);
    return r;
}

/* Uniform integer in [0, n). */
static inline uint32_t fc_rng_below(fc_rng *r, uint32_t n)
{
    return (uint32_t)(((fc_rng_next(r) >> 32) * (uint64_t)n) >> 32);
}

/* Uniform integer in [lo, hi]. */
static inline int fc_rng_range(fc_rng *r, int lo, int hi)
{
    return lo + (int)fc_rng_below(r, (uint32_t)(hi - lo + 1));
}

/* Uniform double in [0, 1). */
static inline double fc_rng_unit(fc_rng *r)
{
    return (double)(fc_rng_next(r) >> 11) * (1.0 / 9007199254740992.0);
}

/* Uniform double in [lo, hi). */
static inline double fc_rng_real(fc_rng *r, double lo, double hi)
{
    return lo + (hi - lo) * fc_rng_unit(r);
}

/* True with probability percent/100. */
static inline int fc_rng_chance(fc_rng *r, int percent)
{
    return (int)fc_rng_below(r, 100) < percent;
}

#endif
