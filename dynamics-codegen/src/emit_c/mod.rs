//! C emission: the graph's outputs become one header-only C99 file (`dynamics emit --lang c`).
//!
//! The header has a `#define` guard, includes `<math.h>` (sine, cosine, and the `tanh` of
//! smoothed friction; not where `DYNAMICS_OWN_SINCOS` leaves it nothing to declare), and holds
//! `static inline` functions only: no allocation, no globals, no other header. Its sines and
//! cosines go through `dynamics_sincos` (`trig`): the runtime's kernels with `<math.h>`'s beyond
//! their range, as the Rust code computes them; the kernels alone with `DYNAMICS_OWN_SINCOS`,
//! for targets without a libm; `<math.h>`'s with `DYNAMICS_LIBM_SINCOS`. For every method of
//! the families the equations hold (the method table,
//! `crate::method`; a robot's opt-in families where it asked for them) it has a function
//! `{robot}_{method}` in `double` and `{robot}_{method}_f32` in `float`, whose inputs are
//! `const` arrays (`q`, `qd`, `qdd`, `tau`, a wrench; first, `params` where the robot has
//! struct fields) and whose result goes into arrays after them (`double m[6][6]`), named as
//! the elements are (`m` for `m1_2`), or is returned (a scalar; the `int` status of a solve with
//! the LDLᵀ of M).
//!
//! It reads the same traced graph as the Rust emission (`crate::emit`) and names what it
//! computes as that does: the joint variables and parameters read (`qd2`, `p_payload`), each
//! joint's sine and cosine (`s2`, `c2`) computed once, the output elements (`m1_2`, `tau3`,
//! with what they are in the book's terms as a comment). Each function is straight-line code
//! over its own outputs' nodes only ([`crate::symbolic::Graph::live`], as marking reads them),
//! in the graph's order: a node read more than once is a `const` local (`t4`), a node read once
//! is written where it is read, and every constant is an exact literal (`0.4318`, `0.4318f`).
//! Each sum is written as the Rust emission writes it, from the same plan
//! (`emit::Sums::plan`): its terms added in the order that waits least, a product
//! fused with the partial sum it meets into `dynamics_fma(x, y, a)`, one instruction where the
//! Rust runtime's `mul_add` is (FMA on x86-64, aarch64). The Rust emission's shared
//! configuration functions are not reproduced (a C function stands alone), so a node that the
//! Rust code reads from the configuration may be written in place here: the same terms, not
//! always the same bits.
//!
//! The header is ASCII: the method table's summaries, its comments, are spelled out (`q̇` as
//! `qd`), as the element descriptions already are.
//!
//! With `DYNAMICS_BATCH` defined, each function also has a `_batch` twin over `n` states in
//! flat row-major arrays (`batch`).
//!
//! By job: `expr` (expressions, literals, precisions), `body` (one function's statements),
//! `function` (the functions and their signatures), `batch` (the functions over many states),
//! `trig` (the sines and cosines), `kernels` (their kernels, from the runtime's constants), this
//! file (the header around them).

#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod batch;
mod body;
mod configuration;
mod configuration_jacobians;
mod expr;
mod floating_batch;
mod floating_contacts;
mod floating_extras;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod function;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod kernels;
mod lanes;
mod trig;

pub use expr::Precision;
pub use floating_extras::FloatingExtras;
pub use function::{functions, Array, Function, Returns};

use crate::method::{Family, Method};
use crate::symbolic::Node;
use crate::trace::Equations;
use function::comment_safe;

/// The prefix of a robot's C functions, [`crate::identifiers::c_prefix`]: its name in lower
/// case, each run of other characters than ASCII letters and digits one underscore (`UR5e` →
/// `ur5e`, `arm-a` → `arm_a`), `robot_` before a leading digit.
#[must_use]
pub fn prefix(robot: &str) -> String {
    crate::identifiers::c_prefix(robot)
}

/// The header of `eq`, the equations of the robot named `robot`, its functions named
/// `{prefix}_{method}` (a prefix without [`crate::identifiers::c_prefix_problem`]); `command`
/// is the command that wrote it (for its first line).
///
/// Its guard, `DYNAMICS_ROBOT_{prefix}_H`, is defined to a hash of the code it guards: the
/// same header included twice is read once, and a different one with the same prefix (two
/// robots whose names give one prefix, `arm-a` and `arm_a`) stops the compiler with an
/// `#error` that names the prefix, rather than define the first one's functions only.
#[must_use]
pub fn header(eq: &Equations, robot: &str, prefix: &str, command: &str) -> String {
    header_with(eq, &FloatingExtras::default(), robot, prefix, command)
}

/// [`header`] with a floating base's functions beyond the method table's, `extras`
/// (`floating_extras.rs`), after the table's and their batch twins; the same text where
/// there are none.
#[must_use]
pub fn header_with(
    eq: &Equations,
    extras: &FloatingExtras,
    robot: &str,
    prefix: &str,
    command: &str,
) -> String {
    let code = code(eq, extras, prefix);
    let guard = format!("DYNAMICS_ROBOT_{prefix}_H");
    let hash = format!("{:#018x}u", fnv1a(code.as_bytes()));
    // Only the printable ASCII an #error's string may hold as it is.
    let name: String = robot
        .chars()
        .map(|c| match c {
            'a'..='z' | 'A'..='Z' | '0'..='9' | ' ' | '_' | '-' | '.' => c,
            _ => '?',
        })
        .collect();
    let mut text = preamble(eq, extras, robot, prefix, command);
    text.push_str(&format!(
        "/* A different header whose functions are also {prefix}_*, included before: refused,\n \
         * rather than one robot's functions silently standing for the other's. */\n\
         #ifdef {guard}\n#if {guard} + 0 != {hash}\n\
         #error \"another header included before this one also names its functions {prefix}_*: \
         emit this one (robot {name}) or the other with `dynamics emit --lang c --prefix NAME`\"\n\
         #endif\n#endif\n\
         #ifndef {guard}\n#define {guard} {hash}\n\n"
    ));
    text.push_str(&code);
    text.push_str(&format!("#endif /* {guard} */\n"));
    text
}

/// How far past a coordinate's index its entry of `q` is: 1 on a floating base, whose `q`
/// holds the base's `x` before the graph's coordinates `[y, z, qx, qy, qz, qw, q_1 …]`
/// (`crate::trace::derive_floating`; nothing reads `x`), else 0.
pub(super) fn q_shift(eq: &Equations) -> usize {
    usize::from(eq.families.contains(Family::Floating))
}

/// The 64-bit FNV-1a hash of `bytes`: the same on every machine, unlike `std`'s hashers.
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |hash, &b| {
        (hash ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// What the guard of the header of `eq` holds: `<math.h>` where needed, the shared helpers and
/// the functions named `{prefix}_{method}`.
fn code(eq: &Equations, extras: &FloatingExtras, prefix: &str) -> String {
    let functions = functions(eq, prefix);
    let extra_outputs = extras.outputs(eq);
    // <math.h> for what the functions call besides sines and cosines (the tanh of smoothed
    // friction, a non-finite constant); without those, for `<math.h>`'s sines and cosines
    // only, so that with DYNAMICS_OWN_SINCOS the header builds where there is no C library
    // (a bare-metal compiler without newlib).
    // The configuration's functions call <math.h>'s square roots and arc tangents.
    let math = if extras.configuration
        || reads(eq, &functions, &extra_outputs, |node| match node {
            Node::Tanh(_) => true,
            Node::Const(c) => !c.to_f64().is_finite(),
            _ => false,
        }) {
        "#include <math.h>\n"
    } else {
        "#ifndef DYNAMICS_OWN_SINCOS\n#include <math.h>\n#endif\n"
    };
    let mut text = format!("{math}\n");
    text.push_str(&trig::trig());
    text.push('\n');
    text.push_str(FMA);
    text.push('\n');
    if functions.iter().any(|f| f.plans_lanes(eq)) {
        text.push_str(&tangent_lanes(eq.dof));
        text.push('\n');
    }
    let sign = |p: Precision| format!("{prefix}_sign{}", p.suffix());
    if reads(eq, &functions, &extra_outputs, |node| {
        matches!(node, Node::Sign(_))
    }) {
        for p in Precision::ALL {
            let (ty, zero) = (p.c_type(), p.literal(0.0));
            text.push_str(&format!(
                "/* sign(x): -1, 0 or 1, 0 at 0 (Coulomb friction: no torque at rest). */\n\
                 static inline {ty} {}({ty} x) {{\n    \
                 return ({ty})((x > {zero}) - (x < {zero}));\n}}\n\n",
                sign(p)
            ));
        }
    }
    text.push_str(&joint_rows(eq, prefix));
    for f in &functions {
        text.push_str(&f.definition(eq, &sign(f.precision)));
        text.push('\n');
    }
    text.push_str(&batch::section(&functions));
    text.push_str(&floating_extras::extras(eq, extras, prefix, sign));
    text
}

/// The multiply-add the functions' sums end in, fused where the Rust runtime's `mul_add` is
/// (FMA on x86-64, aarch64): the same operations in the same order, hence the same results.
const FMA: &str = "#ifndef DYNAMICS_FMA_H
#define DYNAMICS_FMA_H
/* x * y + a: one fused instruction, rounded once, where the target has one (as the Rust code's
 * mul_add), else a product and a sum. */
#if defined(__GNUC__) && (defined(__FMA__) || defined(__aarch64__))
#define DYNAMICS_FUSED(f, x, y, a) f(x, y, a)
#else
#define DYNAMICS_FUSED(f, x, y, a) (x) * (y) + (a)
#endif
static inline double dynamics_fma(double x, double y, double a) {
    return DYNAMICS_FUSED(__builtin_fma, x, y, a);
}
static inline float dynamics_fma_f32(float x, float y, float a) {
    return DYNAMICS_FUSED(__builtin_fmaf, x, y, a);
}
#endif /* DYNAMICS_FMA_H */
";

/// Where the derivatives compute their tangents in lanes, eight directions a vector: as the
/// Rust code does, where the target has AVX-512 (32 registers of eight `double`s); with AVX2
/// alone the 6-joint arms' took more instructions in Rust. `lanes.rs` writes them, with the
/// rows of the identity its unit vectors are read from: as wide as a serial robot's widest
/// lanes in every header (the same table, which headers included together share), a tree's
/// wider lanes (`dof` past [`crate::check::MAX_JOINTS`]) from a table of their own width.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn tangent_lanes(dof: usize) -> String {
    let width = unit_width(dof);
    let table = |p: Precision| {
        let (one, zero) = (p.literal(1.0), p.literal(0.0));
        let rows: Vec<String> = (0..width)
            .map(|j| {
                let row: Vec<&str> = (0..=j)
                    .map(|k| if k == j { &*one } else { &*zero })
                    .collect();
                format!("{{{}}}", row.join(", "))
            })
            .collect();
        format!(
            "static const {} {}[{width}][{width}] = {{\n    {}}};\n",
            p.c_type(),
            unit_table(dof, p),
            rows.join(",\n    ")
        )
    };
    let guard = format!("{}_H", unit_table(dof, Precision::Double).to_uppercase());
    format!(
        "#ifndef DYNAMICS_TANGENT_LANES
/* The derivatives' tangents in lanes (arrays of eight directions, one loop each, which the
 * compiler vectorizes) where gcc targets AVX-512, as the Rust code's; column by column
 * elsewhere (clang's loops ran slower than its columns). Define it 0 or 1 before the header
 * to choose. */
#if defined(__AVX512F__) && defined(__GNUC__) && !defined(__clang__)
#define DYNAMICS_TANGENT_LANES 1
#else
#define DYNAMICS_TANGENT_LANES 0
#endif
#endif
#ifndef DYNAMICS_LANES_WIDE
/* Eight doubles a vector in the functions with lanes (gcc's default is four on AVX-512). */
#if DYNAMICS_TANGENT_LANES && defined(__AVX512F__) && defined(__GNUC__) && __GNUC__ >= 8 && !defined(__clang__)
#define DYNAMICS_LANES_WIDE __attribute__((target(\"prefer-vector-width=512\")))
#else
#define DYNAMICS_LANES_WIDE
#endif
#endif
#if DYNAMICS_TANGENT_LANES && !defined({guard})
#define {guard}
/* Row j: the unit vector of direction j. */
{}{}#endif
",
        table(Precision::Double),
        table(Precision::Single)
    )
}

/// The width of the identity table the lanes of a robot of `dof` joints read their unit vectors
/// from: a serial robot's widest lanes' at least.
fn unit_width(dof: usize) -> usize {
    use crate::emit::lanes::width;
    width(crate::check::MAX_JOINTS).max(width(dof))
}

/// The name of that table: `dynamics_unit` (`_f32`) for serial robots' width, `dynamics_unit24`
/// for a wider one.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn unit_table(dof: usize, precision: Precision) -> String {
    let width = unit_width(dof);
    let wider = if width > crate::emit::lanes::width(crate::check::MAX_JOINTS) {
        width.to_string()
    } else {
        String::new()
    };
    format!("dynamics_unit{wider}{}", precision.suffix())
}

/// For the regressor of a robot with mimic joints, the row of τ each joint's columns of
/// `{prefix}_joint_regressor` add to (the Rust trait's `JOINT_ROWS`); nothing where each is its
/// own joint's.
fn joint_rows(eq: &Equations, prefix: &str) -> String {
    let Some(rows) = eq.regressor.as_ref().map(|r| &r.rows) else {
        return String::new();
    };
    if rows.iter().enumerate().all(|(i, &row)| row == i) {
        return String::new();
    }
    let list: Vec<String> = rows.iter().map(ToString::to_string).collect();
    format!(
        "/* A robot with mimic joints: the regressor has a row per coordinate and a block per \
         link\n * (per joint). Per joint, the row of tau its columns of {prefix}_joint_regressor \
         add to: a\n * mimic joint's add to the row of the joint it follows. */\n\
         static const int {prefix}_joint_rows[{}] = {{{}}};\n\n",
        rows.len(),
        list.join(", ")
    )
}

/// Whether a function (of the table's, or one reading the nodes `extra`) reads a node that
/// `wanted` picks (`Sign`: Coulomb friction).
fn reads(
    eq: &Equations,
    functions: &[Function],
    extra: &[crate::symbolic::NodeId],
    wanted: impl Fn(Node) -> bool,
) -> bool {
    let outputs: Vec<_> = functions
        .iter()
        .flat_map(|f| f.method.shape(eq).outputs())
        .chain(extra.iter().copied())
        .collect();
    let live = eq.graph.live(&outputs);
    eq.graph
        .nodes()
        .any(|(id, node)| live[id.index()] && wanted(node))
}

/// The header's opening comment: where it comes from, and the conventions of its functions.
fn preamble(
    eq: &Equations,
    extras: &FloatingExtras,
    robot: &str,
    prefix: &str,
    command: &str,
) -> String {
    let mut lines = vec![
        format!("Generated by `{command}`; do not edit:"),
        "change the description file and run it again.".to_owned(),
        String::new(),
    ];
    lines.extend(conventions(eq, robot));
    lines.extend(floating_extras::preamble(extras, prefix));
    lines.extend([
        String::new(),
        format!("The functions are {prefix}_*. A different header whose functions have the same"),
        "prefix (another robot's) is refused in the same file (#error): choose another with"
            .to_owned(),
        "`dynamics emit --lang c --prefix NAME`.".to_owned(),
    ]);
    if !eq.fields.is_empty() {
        lines.push(String::new());
        lines.push(format!(
            "The robot's parameters are each function's first argument, `params[{}]`:",
            eq.fields.len()
        ));
        for (k, field) in eq.fields.iter().enumerate() {
            lines.push(format!("  params[{k}] = {field}"));
        }
    }
    let mut text = "/*\n".to_owned();
    for line in lines {
        let line = comment_safe(&line);
        text.push_str(if line.is_empty() { " *" } else { " * " });
        text.push_str(&line);
        text.push('\n');
    }
    text.push_str(" */\n");
    text
}

/// What the preamble says the equations are of, how the derive generates them, and the lines
/// on the inputs' lengths (ending with "... Each"): a floating base's in Pinocchio's terms.
fn opening(eq: &Equations, robot: &str) -> (String, Vec<String>, Vec<String>) {
    let n = eq.dof;
    if q_shift(eq) == 0 {
        return (
            format!("`{robot}` ({n} joints)"),
            vec![
                "`#[derive(Dynamics)]` generates them in Rust: one `static inline` function per method"
                    .to_owned(),
            ],
            vec![
                format!("q, qd, qdd and tau have {n} elements (rad or m, per s, per s^2; N m or N), a"),
                "wrench 6 ([fx, fy, fz, mx, my, mz]). Matrices are arrays of rows, m[i][j]. Each"
                    .to_owned(),
            ],
        );
    }
    let lines = |text: &[&str]| text.iter().map(|&l| l.to_owned()).collect::<Vec<_>>();
    let mut elements = vec![format!(
        "q has {} elements, [x, y, z, qx, qy, qz, qw, q_1 ...]: the base origin in",
        n + 1
    )];
    elements.extend(lines(&[
        "world axes, the base's orientation as a quaternion (read as given: not normalised),",
    ]));
    elements.push(format!(
        "then the joints. qd (Pinocchio's v), qdd (a) and tau have {n}: [vx, vy, vz, wx,"
    ));
    elements.extend(lines(&[
        "wy, wz, ...], the base origin's velocity and the base's angular velocity in base",
        "axes, then the joint rates; a generalized force's first six are the wrench on the",
        "base, [fx, fy, fz, mx, my, mz] in base axes, its moment about the base origin.",
        "Matrices are arrays of rows, m[i][j]. Each",
    ]));
    (
        format!(
            "`{robot}` on a free-flying base ({} joints and the base's 6)",
            n - 6
        ),
        lines(&[
            "`#[derive(Dynamics)]` generates them in Rust with `base = floating`, in Pinocchio's",
            "free-flyer conventions: one `static inline` function per method",
        ]),
        elements,
    )
}

/// The preamble's paragraph on what the functions compute and how they are called.
fn conventions(eq: &Equations, robot: &str) -> Vec<String> {
    let families: Vec<&str> = Family::ALL
        .iter()
        .filter(|&&f| {
            Method::ALL
                .iter()
                .any(|&m| m.family() == f && eq.families.has(m))
        })
        .map(|f| f.name())
        .collect();
    let (what, derive, elements) = opening(eq, robot);
    let mut lines = vec![format!(
        "The closed-form equations of motion of {what} in C99, as"
    )];
    lines.extend(derive);
    lines.extend([
        format!(
            "of the families {}, in `double`, and in `float` with",
            families.join(", ")
        ),
        "`_f32` appended. No allocation, no globals; link with the math library (-lm).".to_owned(),
        String::new(),
    ]);
    lines.extend(elements);
    lines.extend([
        "function reads all its inputs before it writes its outputs, which may therefore"
            .to_owned(),
        "alias its inputs. A function that solves with the LDL^T of M returns 0 where every"
            .to_owned(),
        "pivot is positive, 1 where one is not (a singular M, or NaN in the inputs).".to_owned(),
        "Multiply-adds are fused where the target has FMA (x86-64 with -mfma or".to_owned(),
        "-march=native, aarch64), as the Rust code's are; compile with -ffp-contract=fast for"
            .to_owned(),
        "the sine and cosine kernels' too.".to_owned(),
        "Sines and cosines are the Rust runtime's kernels (the Rust code's results, four joints"
            .to_owned(),
        "at a time in vector lanes where the compiler vectorizes them, as gcc -O2".to_owned(),
        "-march=native does on AVX2), <math.h>'s beyond |x| = 2^16. Defined before the first"
            .to_owned(),
        "such header, DYNAMICS_OWN_SINCOS takes the kernels alone (no libm needed but for the"
            .to_owned(),
        "tanh of smoothed friction), DYNAMICS_LIBM_SINCOS <math.h>'s (also under -ffast-math)."
            .to_owned(),
        "With DYNAMICS_BATCH defined, each function has a twin `{name}_batch(size_t n, ...)`"
            .to_owned(),
        "over n states: flat arrays of n rows, each row one state's array.".to_owned(),
    ]);
    lines
        .into_iter()
        .chain(eq.tips.iter().flat_map(|tips| {
            [
                format!(
                    "The tips' functions take `wrenches`, 6 per tip one after the other; tips: {}.",
                    tips.names.join(", ")
                ),
                "Their results have one block per tip, in that order.".to_owned(),
            ]
        }))
        .collect()
}
