//! The header's sines and cosines: `dynamics_sin`, `dynamics_cos` and `dynamics_sincos` (and
//! their `_f32` forms), which call `<math.h>`, or, where `DYNAMICS_OWN_SINCOS` is defined, run
//! the runtime's own kernels (`dynamics-runtime/src/trig/`) written in C, so that a target
//! without a libm still builds.
//!
//! The kernels are the runtime's operation for operation: the same Cody-Waite reduction (π/2 in
//! parts, `k·P` exact, the rounding errors recovered by Fast2Sum and TwoSum), the same fdlibm
//! and FreeBSD polynomials in the same Estrin form, the same coefficients (the `float` ones as
//! `(float)` of the same `double` literals, as the runtime's `f64 as f32`), the parts of π/2 as
//! hexadecimal literals, exact. Where the runtime fuses a multiply-add the C writes `a * b + c`,
//! which a compiler fuses under `-ffp-contract=fast`; the products the runtime fuses with their
//! subtractions are exact, so the two forms agree there. Not ported: the runtime's `libm` call
//! beyond the fast range (|x| > 2^16, 2^12 in `float`), where these lose accuracy (and give NaN
//! from 2^51, 2^22 in `float`, where `x·2/π` no longer rounds to an integer), and its four
//! arguments in vector lanes.
//!
//! The definitions are shared by every robot's header (one guard, `DYNAMICS_TRIG_H`), so that
//! two robots' headers in one file define them once.

/// The C text, after `#include <math.h>`.
pub(super) const TRIG: &str = r"#ifndef DYNAMICS_TRIG_H
#define DYNAMICS_TRIG_H
#ifdef DYNAMICS_OWN_SINCOS
/* The runtime's sine and cosine (dynamics-runtime/src/trig/): within an ulp for |x| <= 2^16
 * (2^12 in float), less accurate beyond, NaN from 2^51 (2^22) on. Not under -ffast-math,
 * whose reassociation undoes the rounding steps. */
static inline void dynamics_sincos(double x, double *s, double *c) {
    const double shift = 6755399441055744.0; /* 1.5 * 2^52: x * 2/pi rounded to an integer */
    const double ax = x < 0.0 ? -x : x;
    if (ax < 0x1p-27) {
        *s = x;
        *c = 1.0;
        return;
    }
    if (!(ax < 0x1p51)) {
        /* Beyond the rounding to an integer, infinite or NaN: NaN. */
        *s = *c = (ax - ax) / (ax - ax);
        return;
    }
    {
        /* x = n pi/2 + (r + r_lo), pi/2 in three parts whose products with n are exact. */
        const double shifted = x * 0x1.45f306dc9c883p-1 + shift;
        const double n = shifted - shift;
        const double a = x - n * 0x1.921fb5444p+0;
        const double b = n * 0x1.68c234c4cp-39;
        const double cc = n * 0x1.98a2e03707345p-77;
        const double t = a - n * 0x1.68c234c4cp-39;
        const double e = (a - t) - b;
        const double r = t - cc;
        const double r_lo = ((t - r) - cc) + e;
        /* fdlibm's k_sin.c and k_cos.c in Estrin form. */
        const double z = t * t;
        const double z2 = z * z;
        const double z4 = z2 * z2;
        const double sin_poly = z4 * (z * 1.58969099521155010221e-10 + -2.50507602534068634195e-8)
            + (z2 * (z * 2.75573137070700676789e-6 + -1.98412698298579493134e-4)
                + (z * 8.33333333332248946124e-3 + -1.66666666666666324348e-1));
        const double cos_poly = z4 * (z * -1.13596475577881948265e-11 + 2.08757232129817482790e-9)
            + (z2 * (z * -2.75573143513906633035e-7 + 2.48015872894767294178e-5)
                + (z * -1.38888888888741095749e-3 + 4.16666666666666019037e-2));
        const double half_z = 0.5 * z;
        const double w = 1.0 - half_z;
        const double sin_r = r + ((r * z) * sin_poly + r_lo * w);
        const double cos_r = w + ((z2 * cos_poly + ((1.0 - w) - half_z)) - r * r_lo);
        /* The quadrant, n mod 4. */
        const unsigned k = (unsigned)(long long)n & 3u;
        const double p = (k & 1u) ? cos_r : sin_r;
        const double q = (k & 1u) ? sin_r : cos_r;
        *s = (k & 2u) ? -p : p;
        *c = ((k + 1u) & 2u) ? -q : q;
    }
}

static inline void dynamics_sincos_f32(float x, float *s, float *c) {
    const float shift = 12582912.0f; /* 1.5 * 2^23 */
    const float ax = x < 0.0f ? -x : x;
    if (ax < 0x1p-12f) {
        *s = x;
        *c = 1.0f;
        return;
    }
    if (!(ax < 0x1p22f)) {
        *s = *c = (ax - ax) / (ax - ax);
        return;
    }
    {
        /* pi/2 in four parts; Fast2Sum, TwoSum and Fast2Sum recover the roundings. */
        const float shifted = x * 0x1.45f306p-1f + shift;
        const float n = shifted - shift;
        const float a = x - n * 0x1.922p+0f;
        const float b = n * -0x1.2aep-18f;
        const float cc = n * -0x1.deap-31f;
        const float d = n * 0x1.184698p-44f;
        const float t0 = a - n * -0x1.2aep-18f;
        const float e1 = (a - t0) - b;
        const float t = t0 - n * -0x1.deap-31f;
        const float t_s = t - t0;
        const float e2 = (t0 - (t - t_s)) - (cc + t_s);
        const float r = t - d;
        const float r_lo = ((t - r) - d) + (e1 + e2);
        /* FreeBSD's k_sinf.c and k_cosf.c, rounded to float. */
        const float z = t * t;
        const float z2 = z * z;
        const float sin_poly = z2 * (z * (float)0.0000027183114939898219064 + (float)-0.000198393348360966317347)
            + (z * (float)0.0083333293858894631756 + (float)-0.166666666416265235595);
        const float cos_poly = z2 * (float)0.0000243904487962774090654
            + (z * (float)-0.00138867637746099294692 + (float)0.0416666233237390631894);
        const float half_z = 0.5f * z;
        const float w = 1.0f - half_z;
        const float sin_r = r + ((r * z) * sin_poly + r_lo * w);
        const float cos_r = w + ((z2 * cos_poly + ((1.0f - w) - half_z)) - r * r_lo);
        const unsigned k = (unsigned)(long long)n & 3u;
        const float p = (k & 1u) ? cos_r : sin_r;
        const float q = (k & 1u) ? sin_r : cos_r;
        *s = (k & 2u) ? -p : p;
        *c = ((k + 1u) & 2u) ? -q : q;
    }
}
#else
static inline void dynamics_sincos(double x, double *s, double *c) {
    *s = sin(x);
    *c = cos(x);
}

static inline void dynamics_sincos_f32(float x, float *s, float *c) {
    *s = sinf(x);
    *c = cosf(x);
}
#endif

static inline double dynamics_sin(double x) {
    double s, c;
    dynamics_sincos(x, &s, &c);
    (void)c;
    return s;
}

static inline double dynamics_cos(double x) {
    double s, c;
    dynamics_sincos(x, &s, &c);
    (void)s;
    return c;
}

static inline float dynamics_sin_f32(float x) {
    float s, c;
    dynamics_sincos_f32(x, &s, &c);
    (void)c;
    return s;
}

static inline float dynamics_cos_f32(float x) {
    float s, c;
    dynamics_sincos_f32(x, &s, &c);
    (void)s;
    return c;
}
#endif /* DYNAMICS_TRIG_H */
";
