/*
 * bvh_vec4.h - four floats at a time for the hierarchy's builder
 * (bvh_build.c): SSE2 where the compiler targets it, plain C elsewhere.
 *
 * Why: binning reads every box at every level; with a box as two
 * vectors (three axes and a zero lane) one instruction grows a bin on
 * all three axes.  Why the two versions build the same tree: every
 * operation here is one IEEE single-precision operation per lane (add,
 * subtract, multiply, a truncating conversion of a value already clamped
 * to [0, 15]) or a selection, and the plain C selections are written as
 * SSE defines minps and maxps (a < b ? a : b, a > b ? a : b: the second
 * operand when either is a NaN).  Private to src/accel.
 */
#ifndef RAYO_ACCEL_BVH_VEC4_H
#define RAYO_ACCEL_BVH_VEC4_H

#include <stdint.h>

#if defined(__SSE2__)
#include <emmintrin.h>

typedef __m128 vec4f;

static inline vec4f v4_load(const float *p) { return _mm_loadu_ps(p); }
static inline void v4_store(float *p, vec4f v) { _mm_storeu_ps(p, v); }
static inline vec4f v4_set1(float x) { return _mm_set1_ps(x); }
static inline vec4f v4_add(vec4f a, vec4f b) { return _mm_add_ps(a, b); }
static inline vec4f v4_sub(vec4f a, vec4f b) { return _mm_sub_ps(a, b); }
static inline vec4f v4_mul(vec4f a, vec4f b) { return _mm_mul_ps(a, b); }
/* a < b ? a : b, a > b ? a : b, lane by lane */
static inline vec4f v4_min(vec4f a, vec4f b) { return _mm_min_ps(a, b); }
static inline vec4f v4_max(vec4f a, vec4f b) { return _mm_max_ps(a, b); }
/* Truncated towards zero; lanes must lie in the int32 range. */
static inline void v4_to_int(vec4f v, int32_t out[4])
{
    _mm_storeu_si128((__m128i *)(void *)out, _mm_cvttps_epi32(v));
}
/* Half the surface area of the box lo..hi (lanes 0-2):
 * (dx dy + dy dz) + dz dx. */
static inline float v4_half_area(vec4f lo, vec4f hi)
{
    vec4f d = _mm_sub_ps(hi, lo);
    vec4f e = _mm_shuffle_ps(d, d, _MM_SHUFFLE(3, 0, 2, 1));
    vec4f p = _mm_mul_ps(d, e); /* dx dy, dy dz, dz dx */
    float p0 = _mm_cvtss_f32(p);
    float p1 = _mm_cvtss_f32(_mm_shuffle_ps(p, p, _MM_SHUFFLE(1, 1, 1, 1)));
    float p2 = _mm_cvtss_f32(_mm_shuffle_ps(p, p, _MM_SHUFFLE(2, 2, 2, 2)));
    return (p0 + p1) + p2;
}

#else

typedef struct vec4f {
    float f[4];
} vec4f;

static inline vec4f v4_load(const float *p)
{
    vec4f v;
    int i;
    for (i = 0; i < 4; i++)
        v.f[i] = p[i];
    return v;
}
static inline void v4_store(float *p, vec4f v)
{
    int i;
    for (i = 0; i < 4; i++)
        p[i] = v.f[i];
}
static inline vec4f v4_set1(float x)
{
    vec4f v;
    int i;
    for (i = 0; i < 4; i++)
        v.f[i] = x;
    return v;
}
#define RAYO_V4_LANES(name, expr)                                            \
    static inline vec4f name(vec4f a, vec4f b)                               \
    {                                                                        \
        vec4f v;                                                             \
        int i;                                                               \
        for (i = 0; i < 4; i++)                                              \
            v.f[i] = expr;                                                   \
        return v;                                                            \
    }
RAYO_V4_LANES(v4_add, a.f[i] + b.f[i])
RAYO_V4_LANES(v4_sub, a.f[i] - b.f[i])
RAYO_V4_LANES(v4_mul, a.f[i] * b.f[i])
RAYO_V4_LANES(v4_min, a.f[i] < b.f[i] ? a.f[i] : b.f[i])
RAYO_V4_LANES(v4_max, a.f[i] > b.f[i] ? a.f[i] : b.f[i])
#undef RAYO_V4_LANES
static inline void v4_to_int(vec4f v, int32_t out[4])
{
    int i;
    for (i = 0; i < 4; i++)
        out[i] = (int32_t)v.f[i];
}
static inline float v4_half_area(vec4f lo, vec4f hi)
{
    float dx = hi.f[0] - lo.f[0], dy = hi.f[1] - lo.f[1],
          dz = hi.f[2] - lo.f[2];
    float p0 = dx * dy, p1 = dy * dz, p2 = dz * dx;
    return (p0 + p1) + p2;
}

#endif

#endif
