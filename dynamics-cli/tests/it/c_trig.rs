//! The header's own sines and cosines (`-DDYNAMICS_OWN_SINCOS`, linked without the math
//! library): the runtime's kernels ported to C, so they give the runtime's results,
//! `Real::sin_cos` bit for bit where neither fuses multiply-adds (the default build) and within
//! an ulp where the runtime does (a build for a CPU with FMA); and within an ulp of the
//! platform's `sin` and `cos` (`f64`), or of the correctly rounded `f32` (`float`), on the fast
//! range. NaN in, NaN out.

use crate::c_support;

use c_support::{compilers, robot};
use dynamics_runtime::Real;
use std::path::Path;
use std::process::Command;

/// The arguments: a dense sweep of joint angles, the fast range's extremes, the hardest
/// reductions, near multiples of π/2, tiny and signed zeros.
fn arguments() -> Vec<f64> {
    let mut xs: Vec<f64> = (0..=2000).map(|k| -10.0 + 0.01 * f64::from(k)).collect();
    xs.extend((0..=200).map(|k| -65_536.0 + 655.36 * f64::from(k)));
    xs.extend((1..=40).map(|k| f64::from(k) * std::f64::consts::FRAC_PI_2 * (1.0 + 1e-15)));
    xs.extend([
        45.553_093_477_052,
        252.898_823_928,
        1e-10,
        -3e-9,
        0.0,
        -0.0,
        4096.0,
        -4095.9,
    ]);
    xs
}

/// How many ulps apart `a` and `b` are (same sign assumed near the results compared).
fn ulps(a: f64, b: f64) -> u64 {
    if a == b {
        return 0;
    }
    let key = |x: f64| {
        let bits = x.to_bits();
        if bits >> 63 == 1 {
            !bits
        } else {
            bits | (1 << 63)
        }
    };
    key(a).abs_diff(key(b))
}

fn ulps_f32(a: f32, b: f32) -> u64 {
    if a == b {
        return 0;
    }
    let key = |x: f32| {
        let bits = x.to_bits();
        u64::from(if bits >> 31 == 1 {
            !bits
        } else {
            bits | (1 << 31)
        })
    };
    key(a).abs_diff(key(b))
}

/// The program: `sin cos sinf cosf` of each argument, how many results of `dynamics_sincos4`
/// differ from one at a time's, the special values' NaN-ness last.
fn program(header: &str, xs: &[f64]) -> String {
    let items: Vec<String> = xs.iter().map(|x| format!("{x:?}")).collect();
    format!(
        "#include <stdio.h>\n#include \"{header}\"\n\n\
         int main(void) {{\n    static const double xs[] = {{{}}};\n    \
         volatile double zero = 0.0;\n    \
         const double specials[3] = {{zero / zero, 1.0 / zero, -1.0 / zero}};\n    \
         unsigned i, mismatches = 0;\n    \
         for (i = 0; i < sizeof xs / sizeof xs[0]; ++i) {{\n        \
         double s, c;\n        float sf, cf;\n        dynamics_sincos(xs[i], &s, &c);\n        \
         dynamics_sincos_f32((float)xs[i], &sf, &cf);\n        \
         printf(\"%.17g %.17g %.9g %.9g\\n\", s, c, (double)sf, (double)cf);\n    }}\n    \
         for (i = 0; i + 4 <= sizeof xs / sizeof xs[0]; ++i) {{\n        \
         double s4[4], c4[4], s, c;\n        float xf[4], sf4[4], cf4[4], sf, cf;\n        \
         unsigned k;\n        dynamics_sincos4(&xs[i], s4, c4);\n        \
         for (k = 0; k < 4; ++k) xf[k] = (float)xs[i + k];\n        \
         dynamics_sincos4_f32(xf, sf4, cf4);\n        for (k = 0; k < 4; ++k) {{\n            \
         dynamics_sincos(xs[i + k], &s, &c);\n            dynamics_sincos_f32(xf[k], &sf, &cf);\n            \
         mismatches += s4[k] != s || c4[k] != c || sf4[k] != sf || cf4[k] != cf;\n        }}\n    }}\n    \
         printf(\"sincos4 mismatches %u\\n\", mismatches);\n    \
         for (i = 0; i < 3; ++i) {{\n        double s, c;\n        float sf, cf;\n        \
         dynamics_sincos(specials[i], &s, &c);\n        \
         dynamics_sincos_f32((float)specials[i], &sf, &cf);\n        \
         printf(\"special %d %d %d %d\\n\", s != s, c != c, sf != sf, cf != cf);\n    }}\n    \
         return 0;\n}}\n",
        items.join(", ")
    )
}

/// `source` compiled by `cc` with its language `flags`, the warnings as errors, at -O2, and
/// `extra` after the source (macros, libraries), into `trig` beside it.
fn build(cc: &str, flags: &[&str], source: &Path, extra: &[&str]) -> std::path::PathBuf {
    let binary = source.with_file_name("trig");
    let out = Command::new(cc)
        .args(flags)
        .args(["-Wall", "-Wextra", "-Wpedantic", "-Werror", "-O2", "-o"])
        .arg(&binary)
        .arg(source)
        .args(extra)
        .output()
        .expect("run the compiler");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    binary
}

#[test]
fn the_headers_own_sines_and_cosines_are_the_runtimes() {
    let Some((cc, flags, _)) = compilers().into_iter().find(|c| c.2) else {
        eprintln!("no C compiler (gcc, clang) found: the header's own sines are not checked");
        return;
    };
    let robot = robot("robots/puma560.toml");
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("c_trig");
    std::fs::create_dir_all(&dir).expect("a scratch directory");
    std::fs::write(dir.join("robot.h"), &robot.header).expect("write");
    let xs = arguments();
    let source = dir.join("trig.c");
    std::fs::write(&source, program("robot.h", &xs)).expect("write");
    // Without -lm: nothing in it may call the math library.
    let binary = build(
        cc,
        flags,
        &source,
        &["-ffp-contract=off", "-DDYNAMICS_OWN_SINCOS"],
    );
    let run = Command::new(&binary).output().expect("run");
    let text = String::from_utf8(run.stdout).expect("UTF-8");
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), xs.len() + 4);
    // The runtime fuses its multiply-adds in a build for a CPU with FMA; C here does not.
    let exact = !cfg!(target_feature = "fma");
    for (x, line) in xs.iter().zip(&lines) {
        let v: Vec<f64> = line
            .split(' ')
            .map(|w| w.parse().expect("a number"))
            .collect();
        let (s, c) = x.sin_cos();
        let (runtime_s, runtime_c) = Real::sin_cos(*x);
        let limit = u64::from(!exact);
        assert!(
            ulps(v[0], runtime_s) <= limit,
            "sin {x}: {} against {runtime_s}",
            v[0]
        );
        assert!(
            ulps(v[1], runtime_c) <= limit,
            "cos {x}: {} against {runtime_c}",
            v[1]
        );
        assert!(ulps(v[0], s) <= 1 && ulps(v[1], c) <= 1, "{x}: against std");
        #[allow(clippy::cast_possible_truncation)]
        let xf = *x as f32;
        if xf.abs() > 4096.0 {
            continue; // the float kernels' fast range
        }
        #[allow(clippy::cast_possible_truncation)]
        let (sf, cf) = (v[2] as f32, v[3] as f32);
        let (runtime_sf, runtime_cf) = Real::sin_cos(xf);
        assert!(
            ulps_f32(sf, runtime_sf) <= limit,
            "sinf {xf}: {sf} against {runtime_sf}"
        );
        assert!(
            ulps_f32(cf, runtime_cf) <= limit,
            "cosf {xf}: {cf} against {runtime_cf}"
        );
        #[allow(clippy::cast_possible_truncation)]
        let (rounded_s, rounded_c) = (f64::from(xf).sin() as f32, f64::from(xf).cos() as f32);
        assert!(
            ulps_f32(sf, rounded_s) <= 1 && ulps_f32(cf, rounded_c) <= 1,
            "{xf}"
        );
    }
    // Four at a time, in vector lanes or (a tiny or huge argument among them) one by one: the
    // results of one at a time, on every window of four consecutive arguments.
    assert_eq!(lines[xs.len()], "sincos4 mismatches 0");
    for line in &lines[xs.len() + 1..] {
        assert_eq!(*line, "special 1 1 1 1", "NaN and infinities give NaN");
    }
}

/// By default (neither macro), the header runs the kernels on the fast range and calls
/// `<math.h>` beyond it, as the runtime calls `libm`: the platform's `sin` and `cos` there, to
/// the bit (Rust's `f64::sin` is the same libm's).
#[test]
fn the_default_header_calls_the_math_library_beyond_the_fast_range() {
    let Some((cc, flags, _)) = compilers().into_iter().find(|c| c.2) else {
        eprintln!("no C compiler (gcc, clang) found: the default sines are not checked");
        return;
    };
    let robot = robot("robots/puma560.toml");
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("c_trig_default");
    std::fs::create_dir_all(&dir).expect("a scratch directory");
    std::fs::write(dir.join("robot.h"), &robot.header).expect("write");
    let xs = [65_537.0, -70_000.5, 1.0e6, -3.0e15, 2.5e30];
    let source = dir.join("trig.c");
    std::fs::write(&source, program("robot.h", &xs)).expect("write");
    let binary = build(cc, flags, &source, &["-lm"]);
    let run = Command::new(&binary).output().expect("run");
    let text = String::from_utf8(run.stdout).expect("UTF-8");
    for (x, line) in xs.iter().zip(text.lines()) {
        let v: Vec<f64> = line
            .split(' ')
            .map(|w| w.parse().expect("a number"))
            .collect();
        assert_eq!((v[0], v[1]), x.sin_cos(), "{x}");
        #[allow(clippy::cast_possible_truncation)]
        let xf = *x as f32;
        #[allow(clippy::cast_possible_truncation)]
        let (sf, cf) = (v[2] as f32, v[3] as f32);
        assert_eq!((sf, cf), xf.sin_cos(), "{xf}");
    }
    assert!(text.contains("sincos4 mismatches 0"), "{text}");
}
