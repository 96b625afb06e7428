//! The robots on a free-flying base of `bench/run`'s floating rows (issue 43), derived from their
//! URDFs with `base = floating` (`FloatingDynamics<NQ, NV>`: M, h, τ, g) and `derivatives = true`
//! (`FloatingDynamicsDerivatives`), the quadrupeds with `contacts = true` (the contact terms in
//! closed form), Solo 12 with `regressor = true` (`FloatingDynamicsRegressor`), and their
//! reference samples (`tests/data/floating/`, Pinocchio 4.1's free flyer, joints in the
//! generator's order).

use dynamics_runtime::Dynamics;

/// Solo 12: four legs of three joints on a flying trunk. NQ 19, NV 18; 13 bodies in the
/// regressor.
#[derive(Clone, Copy, Debug, Default, Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/floating/solo12.urdf",
    base = floating,
    derivatives = true,
    contacts = true,
    regressor = true
)]
pub struct Solo12;

/// ANYmal B: four legs of three joints, the trunk carrying ten fixed links. NQ 19, NV 18.
#[derive(Clone, Copy, Debug, Default, Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/floating/anymal_b.urdf",
    base = floating,
    derivatives = true,
    contacts = true
)]
pub struct AnymalB;

/// The Unitree G1 humanoid without hands: two legs of six joints, a waist of three, two arms of
/// seven. NQ 36, NV 35.
#[derive(Clone, Copy, Debug, Default, Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/floating/g1_29dof.urdf",
    base = floating,
    derivatives = true
)]
pub struct G1;

/// The robots on a free-flying base, by their data files' names.
pub const FLOATING: [&str; 3] = ["solo12", "anymal_b", "g1_29dof"];

/// A reference sample of a robot on a free-flying base: `Q` configuration values, `V` velocity
/// values, and Pinocchio's outputs.
#[derive(Clone, Debug)]
pub struct FloatingSample<const Q: usize, const V: usize> {
    /// `[x, y, z, qx, qy, qz, qw, joints]`, the quaternion unit.
    pub q: [f64; Q],
    /// The base's twist in its own frame, then the joint rates.
    pub v: [f64; V],
    /// The time derivative of `v`.
    pub a: [f64; V],
    /// `rnea(q, v, a)`.
    pub tau: [f64; V],
    /// `crba(q)`, both triangles, row-major.
    pub mass: Vec<f64>,
    /// `nonLinearEffects(q, v)`.
    pub bias: [f64; V],
    /// `computeGeneralizedGravity(q)`.
    pub gravity: [f64; V],
}

/// The reference samples of `robot` (one of [`FLOATING`]), from `tests/data/floating/`.
///
/// # Panics
/// If the file is missing or malformed, or its lengths are not `Q` and `V`.
#[must_use]
pub fn floating_samples<const Q: usize, const V: usize>(robot: &str) -> Vec<FloatingSample<Q, V>> {
    let text = super::read(&format!("floating/{robot}.json"));
    let data: serde_json::Value =
        serde_json::from_str(&text).unwrap_or_else(|e| panic!("data of {robot}: {e}"));
    let samples = data["samples"]
        .as_array()
        .unwrap_or_else(|| panic!("data of {robot} has no samples"));
    let rows = |m: &serde_json::Value| -> Vec<f64> {
        let rows = m.as_array().expect("M's rows");
        rows.iter()
            .flat_map(|r| super::vector::<V>(r, "M"))
            .collect()
    };
    samples
        .iter()
        .map(|s| FloatingSample {
            q: super::vector(&s["q"], "q"),
            v: super::vector(&s["v"], "v"),
            a: super::vector(&s["a"], "a"),
            tau: super::vector(&s["tau"], "tau"),
            mass: rows(&s["M"]),
            bias: super::vector(&s["h"], "h"),
            gravity: super::vector(&s["g"], "g"),
        })
        .collect()
}

/// Pinocchio's first derivatives at the state of the [`FloatingSample`] of the same index
/// (`tests/data/floating/<robot>_derivatives.json`), each matrix row-major.
#[derive(Clone, Debug)]
pub struct FloatingDerivativeSample<const V: usize> {
    /// The generalized force `computeABADerivatives` was given.
    pub tau: [f64; V],
    /// `computeRNEADerivatives(q, v, a)`: `dtau_dq` (along the tangent), then `dtau_dv`.
    pub inverse: Vec<f64>,
    /// `computeABADerivatives(q, v, tau)`: `ddq_dq`, `ddq_dv`, then `ddq_dtau` (M⁻¹).
    pub forward: Vec<f64>,
}

/// The first derivatives of `robot` (one of [`FLOATING`]) at its samples' states.
///
/// # Panics
/// If the file is missing or malformed, or its matrices are not `V × V`.
#[must_use]
pub fn floating_derivative_samples<const V: usize>(
    robot: &str,
) -> Vec<FloatingDerivativeSample<V>> {
    let text = super::read(&format!("floating/{robot}_derivatives.json"));
    let data: serde_json::Value =
        serde_json::from_str(&text).unwrap_or_else(|e| panic!("derivatives of {robot}: {e}"));
    let samples = data["samples"]
        .as_array()
        .unwrap_or_else(|| panic!("derivatives of {robot} have no samples"));
    let rows = |s: &serde_json::Value, keys: &[&str]| -> Vec<f64> {
        let matrices = keys
            .iter()
            .map(|k| s[*k].as_array().expect("a matrix's rows"));
        matrices
            .flat_map(|rows| rows.iter().flat_map(|r| super::vector::<V>(r, "a row")))
            .collect()
    };
    samples
        .iter()
        .map(|s| FloatingDerivativeSample {
            tau: super::vector(&s["tau_in"], "tau_in"),
            inverse: rows(s, &["dtau_dq", "dtau_dv"]),
            forward: rows(s, &["ddq_dq", "ddq_dv", "ddq_dtau"]),
        })
        .collect()
}

/// Per state, Pinocchio's `a` and `λ` with every foot held (a row per foot).
pub type HeldSample<const V: usize, const F: usize> = ([f64; V], [[f64; 3]; F]);

/// Pinocchio's `constraintDynamics` with every foot held at the states of the
/// [`FloatingSample`]s of the same index (`tests/data/floating/<robot>_contact_fd.json`): the
/// feet's names, in the order of the robot's `FloatingKinematics` frames, and per state `a`
/// and `λ` (a row per foot, the force on the robot in world axes).
///
/// # Panics
/// If the file is missing or malformed, or its lengths are not `V` and `F`.
#[must_use]
pub fn floating_contact_samples<const V: usize, const F: usize>(
    robot: &str,
) -> ([String; F], Vec<HeldSample<V, F>>) {
    let text = super::read(&format!("floating/{robot}_contact_fd.json"));
    let data: serde_json::Value =
        serde_json::from_str(&text).unwrap_or_else(|e| panic!("contacts of {robot}: {e}"));
    let names: Vec<String> = data["frames"]
        .as_array()
        .unwrap_or_else(|| panic!("contacts of {robot} have no frames"))
        .iter()
        .map(|f| f["name"].as_str().expect("a frame's name").to_owned())
        .collect();
    let samples = data["samples"]
        .as_array()
        .unwrap_or_else(|| panic!("contacts of {robot} have no samples"));
    let samples = samples
        .iter()
        .map(|s| {
            let rows: Vec<[f64; 3]> = s["lambda"]
                .as_array()
                .expect("a row per foot")
                .iter()
                .map(|r| super::vector::<3>(r, "lambda"))
                .collect();
            let rows = rows.try_into().expect("a row per foot");
            (super::vector(&s["a_contact"], "a_contact"), rows)
        })
        .collect();
    (names.try_into().expect("a name per foot"), samples)
}

/// Pinocchio's `computeJointTorqueRegressor` on the free flyer at the states of the
/// [`FloatingSample`]s of the same index (`tests/data/floating/<robot>_regressor.json`), each
/// `V × 10 (n + 1)` row-major, the free flyer's ten columns first.
///
/// # Panics
/// If the file is missing or malformed, or a row is not `C` long.
#[must_use]
pub fn floating_regressor_samples<const V: usize, const C: usize>(robot: &str) -> Vec<Vec<f64>> {
    let text = super::read(&format!("floating/{robot}_regressor.json"));
    let data: serde_json::Value =
        serde_json::from_str(&text).unwrap_or_else(|e| panic!("regressor of {robot}: {e}"));
    let samples = data["samples"]
        .as_array()
        .unwrap_or_else(|| panic!("regressor of {robot} has no samples"));
    samples
        .iter()
        .map(|s| {
            let rows = s["Y"].as_array().expect("Y's rows");
            assert_eq!(rows.len(), V, "regressor of {robot}: rows");
            rows.iter()
                .flat_map(|r| super::vector::<C>(r, "a row of Y"))
                .collect()
        })
        .collect()
}
