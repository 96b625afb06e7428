//! The header's sines and cosines: `dynamics_sin`, `dynamics_cos`, `dynamics_sincos` and
//! `dynamics_sincos4` (and their `_f32` forms). By default they run the runtime's kernels
//! (`dynamics-runtime/src/trig/`) written in C, on the runtime's fast range (|x| ≤ 2^16,
//! 2^-12 to 2^12 in `float`; `(x, 1)` below 2^-27, which the runtime's kernel gives there), and
//! call `<math.h>` beyond it, as the runtime calls `libm`:
//! the Rust code's results, and in vector lanes. With `DYNAMICS_OWN_SINCOS` the kernels alone,
//! so that a target without a libm still builds; with `DYNAMICS_LIBM_SINCOS`, or under
//! `-ffast-math` (which would reassociate the kernels' rounding steps away, `__FAST_MATH__`),
//! `<math.h>`'s everywhere.
//!
//! The kernels are the runtime's operation for operation: the same Cody-Waite reduction (π/2 in
//! parts, `k·P` exact; for `float` the rounding errors recovered by Fast2Sum and TwoSum), the
//! same fdlibm and FreeBSD polynomials in the same form, the same constants, read from the runtime's
//! own table (`kernels.rs`: the coefficients as published, the `float` ones as `(float)` of the
//! same `double` literals, as the runtime's `f64 as f32`, the parts of π/2 and the bounds of the
//! fast range as hexadecimal literals, exact). Where the runtime fuses a multiply-add the C writes `a * b + c`,
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

use super::kernels::{lane_f32, lane_f64, BOUND_F32, BOUND_F64, TINY_F32, TINY_F64};

/// `kernel` indented by `indent` more spaces.
fn lane(kernel: &str, indent: usize) -> String {
    let pad = " ".repeat(indent);
    kernel
        .lines()
        .map(|line| format!("{pad}{line}\n"))
        .collect()
}

/// The C text, after `#include <math.h>`: `TRIG` with the kernels (`kernels.rs`) and the
/// runtime's bounds of their range written in.
pub(super) fn trig() -> String {
    let bounds = [
        ("{TINY_F64}", TINY_F64.hex()),
        ("{BOUND_F64}", BOUND_F64.hex()),
        ("{TINY_F32}", TINY_F32.hex()),
        ("{BOUND_F32}", BOUND_F32.hex()),
    ];
    let kernels = [
        (
            "    /* lane f64 scalar */\n",
            lane(&lane_f64("x", "*s", "*c"), 4),
        ),
        (
            "    /* lane f64 four */\n",
            lane(&lane_f64("xs[i]", "ss[i]", "cs[i]"), 8),
        ),
        (
            "    /* lane f32 scalar */\n",
            lane(&lane_f32("x", "*s", "*c"), 4),
        ),
        (
            "    /* lane f32 four */\n",
            lane(&lane_f32("xs[i]", "ss[i]", "cs[i]"), 8),
        ),
    ];
    bounds
        .into_iter()
        .chain(kernels)
        .fold(TRIG.to_owned(), |text, (placeholder, value)| {
            debug_assert!(text.contains(placeholder), "{placeholder}");
            text.replace(placeholder, &value)
        })
}

/// The C text around the kernels.
const TRIG: &str = r##"#ifndef DYNAMICS_TRIG_H
#define DYNAMICS_TRIG_H
/* Sines and cosines: by default the runtime's kernels (dynamics-runtime/src/trig/), within two
 * ulps (one in float), the Rust code's results, and <math.h>'s beyond |x| = 2^16 (2^12 in
 * float), as the runtime does; with DYNAMICS_OWN_SINCOS the kernels alone (no libm: less
 * accurate beyond 2^16, NaN from 2^51, 2^22 in float); with DYNAMICS_LIBM_SINCOS, or under
 * -ffast-math (whose reassociation undoes the kernels' rounding steps), <math.h>'s. */
#if defined(__FAST_MATH__) && defined(DYNAMICS_OWN_SINCOS)
#error "DYNAMICS_OWN_SINCOS: -ffast-math undoes the rounding steps of the header's sines and cosines"
#endif
#if !defined(DYNAMICS_LIBM_SINCOS) && !defined(__FAST_MATH__)
#ifdef DYNAMICS_OWN_SINCOS
#define DYNAMICS_SINCOS_IN_RANGE(ax) ((ax) < 0x1p51)
#define DYNAMICS_SINCOS_IN_RANGE_F32(ax) ((ax) < 0x1p22f)
#else
#define DYNAMICS_SINCOS_IN_RANGE(ax) ((ax) <= {BOUND_F64})
#define DYNAMICS_SINCOS_IN_RANGE_F32(ax) ((ax) <= {BOUND_F32})
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
    if (ax < {TINY_F64}) {
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
        fast += (ax >= {TINY_F64}) & DYNAMICS_SINCOS_IN_RANGE(ax);
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
    if (ax < {TINY_F32}) {
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
        fast += (ax >= {TINY_F32}) & DYNAMICS_SINCOS_IN_RANGE_F32(ax);
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
