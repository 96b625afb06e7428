//! The header's sines and cosines: `dynamics_sin`, `dynamics_cos`, `dynamics_sincos` and
//! `dynamics_sincos4` (and their `_f32` forms). By default they run the runtime's kernels
//! (`dynamics-runtime/src/trig/`) written in C, on the runtime's fast range (2^-27 ≤ |x| ≤
//! 2^16, 2^-12 to 2^12 in `float`), and call `<math.h>` beyond it, as the runtime calls `libm`:
//! the Rust code's results, and in vector lanes. With `DYNAMICS_OWN_SINCOS` the kernels alone,
//! so that a target without a libm still builds; with `DYNAMICS_LIBM_SINCOS`, or under
//! `-ffast-math` (which would reassociate the kernels' rounding steps away, `__FAST_MATH__`),
//! `<math.h>`'s everywhere.
//!
//! The kernels are the runtime's operation for operation: the same Cody-Waite reduction (π/2 in
//! parts, `k·P` exact, the rounding errors recovered by Fast2Sum and TwoSum), the same fdlibm
//! and FreeBSD polynomials in the same Estrin form, the same coefficients (the `float` ones as
//! `(float)` of the same `double` literals, as the runtime's `f64 as f32`), the parts of π/2 as
//! hexadecimal literals, exact. Where the runtime fuses a multiply-add the C writes `a * b + c`,
//! which a compiler fuses under `-ffp-contract=fast`; the products the runtime fuses with their
//! subtractions are exact, so the two forms agree there. The quadrant is chosen by comparisons
//! (`n/4 − round(n/4)`, exact) rather than the runtime's table, so that the body has no
//! branch and no table: `dynamics_sincos4` runs it on four arguments in a loop that compilers
//! vectorize (gcc at `-O2` with `-march=native` on an AVX2 machine), the runtime's `sin_cos_4`
//! without its intrinsics, its results those of one argument at a time, inlined by gcc and
//! clang (`always_inline`) but at `-Os`. With `DYNAMICS_OWN_SINCOS` they run beyond the fast
//! range too, less accurate there, NaN from 2^51 (2^22 in `float`, where `x·2/π` no longer
//! rounds to an integer).
//!
//! With `<math.h>`'s, `dynamics_sincos4` is four calls of `sin` and `cos`.
//!
//! The definitions are shared by every robot's header (one guard, `DYNAMICS_TRIG_H`), so that
//! two robots' headers in one file define them once.

/// The kernel of `double`, one argument `{x}` of the fast range to `{s}` and `{c}`, without a
/// branch: written out in `dynamics_sincos` and in `dynamics_sincos4`'s loop, where a compiler
/// vectorizes it only if it is written there, not called (gcc at `-O2` does not inline it).
const LANE_F64: &str = "
    const double shift = 6755399441055744.0; /* 1.5 * 2^52: x * 2/pi rounded to an integer */
    /* x = n pi/2 + (r + r_lo), pi/2 in three parts whose products with n are exact. */
    const double shifted = {x} * 0x1.45f306dc9c883p-1 + shift;
    const double n = shifted - shift;
    const double a = {x} - n * 0x1.921fb5444p+0;
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
    /* The quadrant n mod 4 from d = n/4 - round(n/4), exactly 0, 1/4, +-1/2 or -1/4. */
    const double m = n * 0.25;
    const double d = m - ((m + shift) - shift);
    const double p = d * d == 0.0625 ? cos_r : sin_r;
    const double q = d * d == 0.0625 ? sin_r : cos_r;
    {s} = d * d == 0.25 || d == -0.25 ? -p : p;
    {c} = d * d == 0.25 || d == 0.25 ? -q : q;
";

/// The kernel of `float`, as [`LANE_F64`].
const LANE_F32: &str = "
    const float shift = 12582912.0f; /* 1.5 * 2^23 */
    /* pi/2 in four parts; Fast2Sum, TwoSum and Fast2Sum recover the roundings. */
    const float shifted = {x} * 0x1.45f306p-1f + shift;
    const float n = shifted - shift;
    const float a = {x} - n * 0x1.922p+0f;
    const float b = n * -0x1.2aep-18f;
    const float cc = n * -0x1.deap-31f;
    const float d4 = n * 0x1.184698p-44f;
    const float t0 = a - n * -0x1.2aep-18f;
    const float e1 = (a - t0) - b;
    const float t = t0 - n * -0x1.deap-31f;
    const float t_s = t - t0;
    const float e2 = (t0 - (t - t_s)) - (cc + t_s);
    const float r = t - d4;
    const float r_lo = ((t - r) - d4) + (e1 + e2);
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
    const float m = n * 0.25f;
    const float d = m - ((m + shift) - shift);
    const float p = d * d == 0.0625f ? cos_r : sin_r;
    const float q = d * d == 0.0625f ? sin_r : cos_r;
    {s} = d * d == 0.25f || d == -0.25f ? -p : p;
    {c} = d * d == 0.25f || d == 0.25f ? -q : q;
";

/// `kernel` for the argument `x` into `s` and `c`, indented by `indent` more spaces.
fn lane(kernel: &str, x: &str, s: &str, c: &str, indent: usize) -> String {
    let text = kernel.trim_start_matches('\n');
    let text = text.replace("{x}", x).replace("{s}", s).replace("{c}", c);
    let pad = " ".repeat(indent);
    text.lines().map(|line| format!("{pad}{line}\n")).collect()
}

/// The C text, after `#include <math.h>`: `TRIG` with its kernels written in.
pub(super) fn trig() -> String {
    TRIG.replace(
        "    /* lane f64 scalar */\n",
        &lane(LANE_F64, "x", "*s", "*c", 4),
    )
    .replace(
        "    /* lane f64 four */\n",
        &lane(LANE_F64, "xs[i]", "ss[i]", "cs[i]", 8),
    )
    .replace(
        "    /* lane f32 scalar */\n",
        &lane(LANE_F32, "x", "*s", "*c", 4),
    )
    .replace(
        "    /* lane f32 four */\n",
        &lane(LANE_F32, "xs[i]", "ss[i]", "cs[i]", 8),
    )
}

/// The C text around the kernels.
const TRIG: &str = r##"#ifndef DYNAMICS_TRIG_H
#define DYNAMICS_TRIG_H
/* Sines and cosines: by default the runtime's kernels (dynamics-runtime/src/trig/), within an
 * ulp, the Rust code's results, and <math.h>'s beyond |x| = 2^16 (2^12 in float), as the runtime
 * does; with DYNAMICS_OWN_SINCOS the kernels alone (no libm: less accurate beyond 2^16, NaN from
 * 2^51, 2^22 in float); with DYNAMICS_LIBM_SINCOS, or under -ffast-math (whose reassociation
 * undoes the kernels' rounding steps), <math.h>'s. */
#if defined(__FAST_MATH__) && defined(DYNAMICS_OWN_SINCOS)
#error "DYNAMICS_OWN_SINCOS: -ffast-math undoes the rounding steps of the header's sines and cosines"
#endif
#if !defined(DYNAMICS_LIBM_SINCOS) && !defined(__FAST_MATH__)
#ifdef DYNAMICS_OWN_SINCOS
#define DYNAMICS_SINCOS_IN_RANGE(ax) ((ax) < 0x1p51)
#define DYNAMICS_SINCOS_IN_RANGE_F32(ax) ((ax) < 0x1p22f)
#else
#define DYNAMICS_SINCOS_IN_RANGE(ax) ((ax) <= 0x1p16)
#define DYNAMICS_SINCOS_IN_RANGE_F32(ax) ((ax) <= 0x1p12f)
#endif

/* The four-argument kernels inlined where gcc or clang would call them (passing the angles
 * through memory), but where the code is built for size. */
#if defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__)
#define DYNAMICS_SINCOS4_INLINE static inline __attribute__((always_inline))
#else
#define DYNAMICS_SINCOS4_INLINE static inline
#endif

/* Beyond the kernels' range: <math.h>'s, or without a libm, NaN (infinite or NaN arguments, and
 * beyond 2^51 where x * 2/pi no longer rounds to an integer) or the kernels' own result. */
static inline void dynamics_sincos_beyond(double x, double *s, double *c) {
#ifdef DYNAMICS_OWN_SINCOS
    const double ax = x < 0.0 ? -x : x;
    *s = *c = (ax - ax) / (ax - ax);
#else
    *s = sin(x);
    *c = cos(x);
#endif
}

static inline void dynamics_sincos_beyond_f32(float x, float *s, float *c) {
#ifdef DYNAMICS_OWN_SINCOS
    const float ax = x < 0.0f ? -x : x;
    *s = *c = (ax - ax) / (ax - ax);
#else
    *s = sinf(x);
    *c = cosf(x);
#endif
}

static inline void dynamics_sincos(double x, double *s, double *c) {
    const double ax = x < 0.0 ? -x : x;
    if (ax < 0x1p-27) {
        *s = x;
        *c = 1.0;
    } else if (!DYNAMICS_SINCOS_IN_RANGE(ax)) {
        dynamics_sincos_beyond(x, s, c);
    } else {
    /* lane f64 scalar */
    }
}

/* Four arguments side by side (in vector lanes where the compiler vectorizes the loop, as
 * gcc does at -O2 for AVX2), the same results as one at a time. */
DYNAMICS_SINCOS4_INLINE void dynamics_sincos4(const double x[4], double s[4], double c[4]) {
    int i;
    /* Copies that alias nothing, so that the loops vectorize without run-time checks; the
     * range test a loop too, which compilers turn into vector comparisons (four scalar tests
     * and their branches took a fifth of a small function's time). */
    double xs[4], ss[4], cs[4];
    long long fast = 0;
    for (i = 0; i < 4; ++i) {
        xs[i] = x[i];
    }
    for (i = 0; i < 4; ++i) {
        const double ax = xs[i] < 0.0 ? -xs[i] : xs[i];
        fast += (ax >= 0x1p-27) & DYNAMICS_SINCOS_IN_RANGE(ax);
    }
    if (fast == 4) {
        for (i = 0; i < 4; ++i) {
    /* lane f64 four */
        }
        for (i = 0; i < 4; ++i) {
            s[i] = ss[i];
            c[i] = cs[i];
        }
    } else {
        for (i = 0; i < 4; ++i) {
            dynamics_sincos(x[i], &s[i], &c[i]);
        }
    }
}

static inline void dynamics_sincos_f32(float x, float *s, float *c) {
    const float ax = x < 0.0f ? -x : x;
    if (ax < 0x1p-12f) {
        *s = x;
        *c = 1.0f;
    } else if (!DYNAMICS_SINCOS_IN_RANGE_F32(ax)) {
        dynamics_sincos_beyond_f32(x, s, c);
    } else {
    /* lane f32 scalar */
    }
}

DYNAMICS_SINCOS4_INLINE void dynamics_sincos4_f32(const float x[4], float s[4], float c[4]) {
    int i;
    float xs[4], ss[4], cs[4];
    int fast = 0;
    for (i = 0; i < 4; ++i) {
        xs[i] = x[i];
    }
    for (i = 0; i < 4; ++i) {
        const float ax = xs[i] < 0.0f ? -xs[i] : xs[i];
        fast += (ax >= 0x1p-12f) & DYNAMICS_SINCOS_IN_RANGE_F32(ax);
    }
    if (fast == 4) {
        for (i = 0; i < 4; ++i) {
    /* lane f32 four */
        }
        for (i = 0; i < 4; ++i) {
            s[i] = ss[i];
            c[i] = cs[i];
        }
    } else {
        for (i = 0; i < 4; ++i) {
            dynamics_sincos_f32(x[i], &s[i], &c[i]);
        }
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

static inline void dynamics_sincos4(const double x[4], double s[4], double c[4]) {
    int i;
    for (i = 0; i < 4; ++i) {
        dynamics_sincos(x[i], &s[i], &c[i]);
    }
}

static inline void dynamics_sincos4_f32(const float x[4], float s[4], float c[4]) {
    int i;
    for (i = 0; i < 4; ++i) {
        dynamics_sincos_f32(x[i], &s[i], &c[i]);
    }
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
"##;
