//! The physically consistent estimate (`identify --consistent`): standard parameters π that
//! a real body could have, whose base parameters fit the measurements as well as such
//! parameters can.
//!
//! π holds, per link, `[m, h_x, h_y, h_z, I_xx, I_xy, I_yy, I_xz, I_yz, I_zz]` about the link
//! frame's origin (`h = m c`; the products of inertia as the matrix's entries, `I_xy = −∫xy dm`;
//! Pinocchio's `toDynamicParameters` order), then the joint terms taken. The base parameters
//! are `π_B = P π`, P the constant map of the grouping (`BaseParameters::parameters[b].terms`).
//! A link's parameters are those of a mass distribution exactly when its pseudo-inertia
//!
//! ```text
//! J = [ Σ   h ]     Σ = ∫ r rᵀ dm = ½ tr(I) 1 − I
//!     [ hᵀ  m ]
//! ```
//!
//! is positive semidefinite (Wensing, Kim and Slotine, 2017: J = ∫ [r; 1][r; 1]ᵀ dm). The
//! estimate solves
//!
//! ```text
//! min_π ‖R_w (P π) − z_w‖² + λ ‖π − π_0‖²   subject to  J_i(π) ⪰ 0 for every link,
//!                                             IA_i ≥ 0, FV_i ≥ 0, FC_i ≥ 0
//! ```
//!
//! with `(R_w, z_w)` the factor of the weighted stacked problem over every base parameter
//! (`Σ_i w_i² ‖Y_i π_B − τ_i‖² = ‖R_w π_B − z_w‖² + ρ²`, the weights of the plain estimate), and
//! `λ = 10⁻⁸ tr(MᵀM) / s` (`M = R_w P`, s standard parameters) pulling π towards the
//! description's `π_0` in the directions the torques do not determine: π itself is not
//! identifiable, only `P π` is, and the regulariser makes the minimiser unique.
//!
//! `clarabel` (an interior-point conic solver in pure Rust) solves it as the second-order cone
//! program `min t` subject to `‖[M π − z_w; √λ (π − π_0)]‖ ≤ t`, so that `MᵀM`, whose condition
//! number is the square of M's, is never formed. Its semidefinite cones need a system BLAS and
//! LAPACK, so the 4 × 4 constraints are imposed by cutting planes instead (Kelley): the program
//! is solved with linear constraints `vᵀ J_i(π) v ≥ 0`, starting with the unit vectors
//! (`m ≥ 0`, `∫x² dm ≥ 0`, …); then each `J_i` with an eigenvalue below `−10⁻¹¹ max(1, |J_i|)`
//! gets that eigenvalue's eigenvector as a new cut, and the program is solved again, until no
//! J_i has one. Each cut holds for every feasible π, so the feasible set is never cut into: the
//! solutions approach the constrained minimiser from outside, and the last is feasible to that
//! tolerance; its remaining negative eigenvalues are then set to zero (`J ← V max(Λ, 0) Vᵀ`,
//! a change of π below the tolerance), and so are the joint terms that must be nonnegative but
//! that the solver left below zero within its own tolerance.

use super::estimate::Estimate;
use super::measured::Measured;
use super::pseudo_inertia::{clipped, pseudo_inertia, smallest_eigenvalue};
use crate::linear_algebra::eigen4 as eigen;
use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSettings, DefaultSolver, IPSolver, NonnegativeConeT, SecondOrderConeT, SolverStatus,
    SupportedConeT,
};

/// The regulariser's weight, relative to the mean diagonal of `MᵀM`.
const REGULARISER: f64 = 1e-8;
/// Eigenvalues of J above `−EIGEN_TOLERANCE max(1, |J|)` count as nonnegative.
pub const EIGEN_TOLERANCE: f64 = 1e-11;
/// Rounds of cuts before giving up.
pub const ROUNDS: usize = 200;

/// What the consistent problem is posed with.
pub struct Problem<'a> {
    /// Links of the robot (each with ten standard parameters first in π).
    pub links: usize,
    /// Per standard parameter after the links': `Some(true)` for a coefficient that must be
    /// nonnegative (actuator inertia, viscous, Coulomb), `Some(false)` for one that need not
    /// (offset).
    pub joint_terms: &'a [bool],
    /// `map[b][k]`: base parameter b's coefficient on standard parameter k.
    pub map: &'a [Vec<f64>],
    /// The description's standard parameters.
    pub described: &'a [f64],
}

/// A link of the consistent estimate.
#[derive(Clone, Debug)]
pub struct Link {
    pub mass: f64,
    /// The centre of mass in the link frame (NaN for a massless link).
    pub com: [f64; 3],
    /// The smallest eigenvalue of the pseudo-inertia J.
    pub smallest_eigenvalue: f64,
}

/// The consistent estimate.
#[derive(Clone, Debug)]
pub struct Consistent {
    /// The standard parameters, in π's order.
    pub standard: Vec<f64>,
    /// Its base parameters `P π`.
    pub base: Vec<f64>,
    pub links: Vec<Link>,
    /// Per joint: the residual's RMS with these base parameters.
    pub rms: Vec<f64>,
    /// The weighted squared residuals `Σ_i w_i² ‖Y_i π_B − τ_i‖²` of the plain estimate and of
    /// this one.
    pub plain_residual: f64,
    pub residual: f64,
    /// Whether the plain estimate's base parameters are those of consistent parameters: this
    /// one fits them as well, to 10⁻⁶ of the plain weighted residual (10⁻¹² of the weighted
    /// torques' for data fitted exactly).
    pub plain_is_consistent: bool,
    /// Quadratic programs solved (one per round of cuts).
    pub rounds: usize,
}

/// The consistent estimate for `measured`, beside the plain `estimate`.
///
/// # Errors
/// The solver fails, or the cuts do not converge.
pub fn consistent(
    measured: &mut Measured,
    estimate: &Estimate,
    problem: &Problem<'_>,
) -> Result<Consistent, String> {
    let p = measured.parameters;
    let s = problem.described.len();
    let all: Vec<usize> = (0..p).collect();
    let (r, z, _) = measured.stacked(&all, &estimate.weights);
    // M = R_w P, p × s.
    let m: Vec<Vec<f64>> = (0..p)
        .map(|i| {
            (0..s)
                .map(|k| (i..p).map(|j| r[i * p + j] * problem.map[j][k]).sum())
                .collect()
        })
        .collect();
    let (rows, b) = objective(&m, &z, problem.described);
    let mut cuts: Vec<Vec<f64>> = Vec::new();
    for link in 0..problem.links {
        for e in 0..4 {
            let mut v = [0.0; 4];
            v[e] = 1.0;
            cuts.push(cut(link, s, &v));
        }
    }
    for (k, &nonnegative) in problem.joint_terms.iter().enumerate() {
        if nonnegative {
            let mut row = vec![0.0; s];
            row[10 * problem.links + k] = 1.0;
            cuts.push(row);
        }
    }
    for round in 1..=ROUNDS {
        let x = solve(&rows, &b, &cuts)?;
        let mut added = false;
        for link in 0..problem.links {
            let j = pseudo_inertia(&x[10 * link..10 * link + 10]);
            let scale = j.iter().flatten().fold(1.0f64, |a, b| a.max(b.abs()));
            let (values, vectors) = eigen(j);
            for (value, vector) in values.iter().zip(&vectors) {
                if *value < -EIGEN_TOLERANCE * scale {
                    cuts.push(cut(link, s, vector));
                    added = true;
                }
            }
        }
        if !added {
            let x = onto_bounds(clipped(x, problem.links), problem);
            return Ok(finish(measured, estimate, problem, x, round));
        }
    }
    Err(format!(
        "the consistent estimate did not converge in {ROUNDS} rounds of cuts"
    ))
}

/// `x` with the joint terms that must be nonnegative raised to zero where the solver left them
/// below it, within its tolerance: a friction coefficient of −10⁻¹⁶ is one the description's
/// checks refuse.
fn onto_bounds(mut x: Vec<f64>, problem: &Problem<'_>) -> Vec<f64> {
    let terms = &mut x[10 * problem.links..];
    for (value, &nonnegative) in terms.iter_mut().zip(problem.joint_terms) {
        if nonnegative {
            *value = value.max(0.0);
        }
    }
    x
}

/// The objective as a second-order cone: the rows of `[M x − z; √λ (x − π_0)]`, as `(A, b)`
/// with the vector `b − A x`, scaled so that M's mean squared column norm is 1 (the scale
/// does not move the minimiser). `λ = REGULARISER · tr(MᵀM) / s`.
#[must_use]
#[doc(hidden)] // For the cuts' test, on exactly its inputs (a `Measured` rounds them).
pub fn objective(m: &[Vec<f64>], z: &[f64], described: &[f64]) -> (Vec<Vec<f64>>, Vec<f64>) {
    let s = described.len();
    let trace: f64 = m.iter().flatten().map(|x| x * x).sum::<f64>() / s as f64;
    let scale = if trace > 0.0 { 1.0 / trace.sqrt() } else { 1.0 };
    let root = REGULARISER.sqrt();
    let mut rows: Vec<Vec<f64>> = m
        .iter()
        .map(|row| row.iter().map(|x| -x * scale).collect())
        .collect();
    let mut b: Vec<f64> = z.iter().map(|x| -x * scale).collect();
    for (k, &value) in described.iter().enumerate() {
        let mut row = vec![0.0; s];
        row[k] = -root;
        rows.push(row);
        b.push(-root * value);
    }
    (rows, b)
}

/// The minimiser of `‖b − A x‖` (the objective's rows) subject to `cut · x ≥ 0` for every cut,
/// as the conic program `min t` subject to `(t, b − A x) ∈ SOC`, `cut · x ≥ 0`: the squared
/// residual is not formed, whose condition number would be the square of M's.
///
/// # Errors
/// The solver's, or a status other than solved.
#[doc(hidden)] // For the cuts' test, on exactly its inputs (a `Measured` rounds them).
pub fn solve(rows: &[Vec<f64>], b: &[f64], cuts: &[Vec<f64>]) -> Result<Vec<f64>, String> {
    let s = rows.first().map_or(0, Vec::len);
    // Variables [x; t]; constraints `A [x; t] + slack = b`: the cuts as `−cut · x + slack = 0`,
    // slack ≥ 0; then `−t + slack_0 = 0` and the objective's rows, slack in the cone.
    let mut a: Vec<Vec<f64>> = cuts
        .iter()
        .map(|row| row.iter().map(|x| -x).chain([0.0]).collect())
        .collect();
    let mut rhs = vec![0.0; cuts.len()];
    let mut t = vec![0.0; s + 1];
    t[s] = -1.0;
    a.push(t);
    rhs.push(0.0);
    a.extend(
        rows.iter()
            .map(|row| row.iter().copied().chain([0.0]).collect()),
    );
    rhs.extend_from_slice(b);
    let a = CscMatrix::from(a.iter().map(|row| row.iter()));
    let p = CscMatrix::zeros((s + 1, s + 1));
    let mut c = vec![0.0; s + 1];
    c[s] = 1.0;
    let cones: [SupportedConeT<f64>; 2] = [
        NonnegativeConeT(cuts.len()),
        SecondOrderConeT(rows.len() + 1),
    ];
    let settings = DefaultSettings {
        verbose: false,
        tol_gap_abs: 1e-13,
        tol_gap_rel: 1e-13,
        tol_feas: 1e-13,
        tol_ktratio: 1e-10,
        max_iter: 500,
        ..DefaultSettings::default()
    };
    let mut solver = DefaultSolver::new(&p, &c, &a, &rhs, &cones, settings)
        .map_err(|e| format!("the consistent estimate's conic program: {e:?}"))?;
    solver.solve();
    match solver.solution.status {
        SolverStatus::Solved | SolverStatus::AlmostSolved => Ok(solver.solution.x[..s].to_vec()),
        status => Err(format!(
            "the consistent estimate's conic program: {status:?}"
        )),
    }
}

/// The cut `vᵀ J_link(π) v ≥ 0`, as coefficients on all `s` standard parameters.
#[must_use]
#[doc(hidden)] // For the cuts' test, on exactly its inputs (a `Measured` rounds them).
pub fn cut(link: usize, s: usize, v: &[f64; 4]) -> Vec<f64> {
    let mut row = vec![0.0; s];
    for k in 0..10 {
        let mut unit = [0.0; 10];
        unit[k] = 1.0;
        let j = pseudo_inertia(&unit);
        row[10 * link + k] = (0..4)
            .map(|a| (0..4).map(|b| v[a] * j[a][b] * v[b]).sum::<f64>())
            .sum();
    }
    row
}

/// The estimate's report from the standard parameters `x`.
fn finish(
    measured: &mut Measured,
    estimate: &Estimate,
    problem: &Problem<'_>,
    x: Vec<f64>,
    rounds: usize,
) -> Consistent {
    let base: Vec<f64> = problem
        .map
        .iter()
        .map(|row| row.iter().zip(&x).map(|(a, b)| a * b).sum())
        .collect();
    let plain: Vec<f64> = estimate
        .values
        .iter()
        .map(|v| if v.is_nan() { 0.0 } else { *v })
        .collect();
    let samples = estimate.samples as f64;
    let mut weighted = |pi: &[f64]| -> (f64, Vec<f64>) {
        let squares: Vec<f64> = measured
            .joints
            .iter_mut()
            .map(|j| j.squared_residual(pi))
            .collect();
        let total = squares
            .iter()
            .zip(&estimate.weights)
            .map(|(ss, w)| w * w * ss)
            .sum();
        (
            total,
            squares.iter().map(|ss| (ss / samples).sqrt()).collect(),
        )
    };
    let (plain_residual, _) = weighted(&plain);
    let (residual, rms) = weighted(&base);
    let (torques, _) = weighted(&vec![0.0; plain.len()]);
    let plain_is_consistent = residual - plain_residual <= 1e-6 * plain_residual + 1e-12 * torques;
    let links = (0..problem.links)
        .map(|l| {
            let pi = &x[10 * l..10 * l + 10];
            let mass = pi[0];
            let com = if mass > 0.0 {
                [pi[1] / mass, pi[2] / mass, pi[3] / mass]
            } else {
                [f64::NAN; 3]
            };
            Link {
                mass,
                com,
                smallest_eigenvalue: smallest_eigenvalue(pi),
            }
        })
        .collect();
    Consistent {
        standard: x,
        base,
        links,
        rms,
        plain_residual,
        residual,
        plain_is_consistent,
        rounds,
    }
}
