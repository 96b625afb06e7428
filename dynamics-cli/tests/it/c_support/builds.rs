//! Which C compilers build the drivers, and how: each compiler's language flags, and the
//! builds of one header (its sines and cosines from `<math.h>`, the header's default or its own
//! kernels, the multiply-adds fused, the derivatives' tangents in lanes).

use std::process::Command;

/// Whether this machine runs code compiled with `-mfma` (x86-64 with FMA).
fn fused_here() -> bool {
    #[cfg(target_arch = "x86_64")]
    return std::arch::is_x86_feature_detected!("fma");
    #[cfg(not(target_arch = "x86_64"))]
    return false;
}

/// The compilers found, each with its language flags and whether to build it also with the
/// header's default and own sines and cosines (beside `<math.h>`'s).
pub fn compilers() -> Vec<(&'static str, &'static [&'static str], bool)> {
    let candidates: [(&str, &[&str], bool); 3] = [
        ("gcc", &["-std=c99", "-x", "c", "-Wdouble-promotion"], true),
        (
            "clang",
            &["-std=c99", "-x", "c", "-Wdouble-promotion"],
            true,
        ),
        ("g++", &["-std=c++17", "-x", "c++"], false),
    ];
    candidates
        .into_iter()
        .filter(|(cc, _, _)| Command::new(cc).arg("--version").output().is_ok())
        .collect()
}

/// The builds of `header` by one compiler, each a name and its extra flags: `<math.h>`'s sines
/// and cosines; with `kernels`, the default (the runtime's kernels, `<math.h>`'s beyond their
/// range), the kernels alone and the multiply-adds fused (as the Rust's are on a CPU with FMA);
/// and the derivatives' tangents in lanes (by default only where gcc targets AVX-512), as
/// portable loops on any CPU.
pub fn builds(header: &str, kernels: bool) -> Vec<(&'static str, &'static [&'static str])> {
    let mut builds: Vec<(&str, &[&str])> = vec![("libm", &["-DDYNAMICS_LIBM_SINCOS", "-lm"])];
    if kernels {
        builds.push(("default", &["-lm"]));
        // Smoothed friction's tanh is the one function the header's own trigonometry leaves
        // to the math library.
        if header.contains("tanh") {
            builds.push(("own", &["-DDYNAMICS_OWN_SINCOS", "-lm"]));
        } else {
            builds.push(("own", &["-DDYNAMICS_OWN_SINCOS"]));
        }
        if fused_here() {
            builds.push(("fused", &["-mfma", "-lm"]));
        }
    }
    if header.contains("#if DYNAMICS_TANGENT_LANES") {
        let lanes: &[&str] = &[
            "-DDYNAMICS_TANGENT_LANES=1",
            "-DDYNAMICS_LIBM_SINCOS",
            "-lm",
        ];
        builds.push(("lanes", lanes));
    }
    builds
}
