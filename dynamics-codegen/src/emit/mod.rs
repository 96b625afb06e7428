//! Emission: the graph's outputs become straight-line Rust.
//!
//! Everything that depends on the parameters and `q` alone (constants, struct fields, the
//! sines and cosines, the kinematics, `M`, `g`, the `Γ_ijk`) is written once, in a shared
//! *configuration* function returning a struct; each method calls it, binds the fields it reads
//! under their names (`let Configuration { s2, c2, k9, .. } = configuration(p_, q_);`), and adds
//! only its terms in `q̇` and `q̈`. The configuration function is `#[inline(always)]`, so each
//! method compiles to just the operations it needs, as if written alone, while the source holds
//! each expression once. Terms in `q̇` that two methods or more compute (the velocities and
//! Coriolis accelerations of Newton-Euler, which `C q̇`, `C q̇ + g`, `τ` and the kinetic energy
//! all need) go the same way into a *motion* function, which also computes the configuration
//! and hands both over: `let (Configuration { s2, .. }, Motion { v3, .. }) = motion(p_, q_,
//! qd_);`. A product is left to each method that reads it, which may fuse it into a
//! multiply-add.
//!
//! Within a function, only the nodes the outputs need are emitted, in the arena's order
//! (children first): the constants (`let k1: T = T::from_f64(0.42);`), the struct fields read
//! (`let [p_m1, _, p_cx1, …] = *p_;`) and the nodes that depend on them alone; then each needed
//! joint's sine and cosine, computed once, four joints side by side
//! (`let ([s1, s2, s3, s4], [c1, c2, c3, c4]) = T::sin_cos_4([q_[0], q_[1], q_[2], q_[3]]);`);
//! then the rest.
//! A node used once is written inline in its user; a node used more often gets a `let tN`
//! (`uN` in the configuration, whose names the methods bind too), numbered in order of
//! appearance; each output element gets a name saying what it is
//! (`m1_2` for M₁₂, `g3` for g₃, `tau3` for τ₃). `a + (−b)` is written `a − b`, `x·y + z` is
//! `x.mul_add(y, z)` (the runtime's `Real::mul_add`: one fused instruction where the target
//! has FMA), and parentheses appear only where precedence or the order of evaluation needs
//! them. The
//! arguments are `q_`, `qd_` and `qdd_` (a pattern cannot shadow a constant, and the trait's
//! methods, in the user's scope, take the same names); each function names the components it
//! reads as the book numbers them, `let [qd1, _, qd3] = *qd_;`.
//!
//! By job: `depends` (what each node depends on, hence which function computes it),
//! `emitter` (one function's state), `plan` (an expression as both languages write it: its
//! forms, their precedence and parentheses, the inputs' names), `expr` (its Rust printer),
//! `sum_order` (the
//! order of a sum's additions), `inputs` (joint variables, sines and cosines), `shared` (the
//! configuration and motion functions), `body` (a method's body), `names` (output elements),
//! `count` (operation counts), `items` (the derive's items: the families' modules, the
//! parameters' reader), `impls` (the trait impls: signatures, calls into the modules),
//! `fallback` (the expansion of a failed derive), `equations` (the readable equations'
//! constants).

mod body;
mod count;
mod depends;
mod emitter;
mod equations;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod expr;
mod fallback;
mod floating;
mod floating_contacts;
mod floating_kinematics;
mod impls;
mod in_place;
mod inputs;
mod items;
pub(crate) mod lanes;
mod names;
mod parts;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod plan;
mod program;
mod rows;
mod shared;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod sum_order;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod sums;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod tip_names;

pub use count::count;
pub(crate) use equations::readable;
pub use equations::simplified_doc;
pub(crate) use fallback::{fallback, unreachable_family};
pub use floating::floating_items;
pub use floating_contacts::{
    floating_contacts_at_run_time, floating_contacts_count, floating_contacts_items,
};
pub use floating_kinematics::floating_kinematics_items;
pub(crate) use impls::runtime_path;
pub use impls::{method, Counts};
pub(crate) use items::generate_uncounted;
pub use items::{generate, Generated, Items, MethodCode, Module};
pub(crate) use names::output_names;
pub use names::{
    local, CONFIGURATION_FN, CONFIGURATION_LOCAL, CONFIGURATION_STRUCT, MOTION_FN, MOTION_STRUCT,
    PARAMETERS,
};
pub use parts::{Body, Context, OpCount, Output, Part, Shared};
pub use program::{emit, Emission};
pub(crate) use sums::Sums;
