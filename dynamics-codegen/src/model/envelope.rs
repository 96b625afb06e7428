//! The states a simplified model is proven over, and what it is asked to keep within: the
//! request of `simplify(...)`, resolved to one value per joint.

/// One joint's part of an [`Envelope`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointEnvelope {
    /// The lowest position (rad or m), without the joint's constant offset.
    pub lower: f64,
    /// The highest position.
    pub upper: f64,
    /// The largest speed `|q̇|`.
    pub speed: f64,
    /// The largest acceleration `|q̈|`.
    pub acceleration: f64,
}

/// The states over which dropped terms are bounded.
#[derive(Clone, Debug, PartialEq)]
pub struct Envelope {
    /// One per joint.
    pub joints: Vec<JointEnvelope>,
}

/// A simplified model asked for: the tolerance of each joint's torque (N·m or N) over an
/// envelope.
#[derive(Clone, Debug, PartialEq)]
pub struct Simplification {
    /// One per joint, absolute.
    pub tolerance: Vec<f64>,
    /// The states the bound holds over.
    pub envelope: Envelope,
}
