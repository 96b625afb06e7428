//! The pieces one emission hands between its steps: where the parameters are, the outputs
//! to emit, the shared functions and the bodies written, with their operation counts.

use crate::method::Method;
use crate::trace::Shape;
use proc_macro2::TokenStream;

/// Operation counts of an emitted function.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OpCount {
    /// Multiplications.
    pub mul: usize,
    /// Additions and subtractions.
    pub add: usize,
    /// Negations.
    pub neg: usize,
    /// Divisions.
    pub div: usize,
    /// Sine and cosine evaluations (a `sin_cos` pair counts 2), and the `sign` and `tanh` of
    /// friction.
    pub trig: usize,
    /// The longest chain of dependent multiplications, additions and divisions from the inputs
    /// (the joint variables, their sines and cosines, the parameters) to a result, each sum
    /// added in the order the emitted code adds it: the operations that cannot overlap, which
    /// bound the time of a call from below as the count bounds its throughput.
    pub depth: usize,
    /// Operations on lanes of tangents ([`crate::symbolic::Tangents`]), one per term of each
    /// lane written: each one vector instruction (or two, three-eighths of it wasted, on
    /// four-lane registers) on top of the scalar counts.
    pub lanes: usize,
}

impl OpCount {
    /// Multiplications, additions and negations together.
    #[must_use]
    pub fn flops(&self) -> usize {
        self.mul + self.add + self.neg + self.div
    }
}

/// An emitted function body.
pub struct Body {
    /// The statements and the result expression.
    pub tokens: TokenStream,
    /// Its operations, shared code included (zeros where [`Context::counted`] is false).
    pub ops: OpCount,
    /// For a body that writes its result into `y_` rather than returning it, the result's
    /// value of zeros, which the function returning the result fills with it.
    pub zeros: Option<TokenStream>,
    /// Whether it computes in lanes of tangents (`Tangent`, which its module imports).
    pub lanes: bool,
}

/// The function of one group of a tree's rows (`emit/rows.rs`), which the method's body calls:
/// `inverse_dynamics_derivatives_rows1(p_, q_, qd_, qdd_, &mut y_)`.
pub struct Part {
    /// The method whose rows it stores.
    pub method: Method,
    /// The group's number, from 1.
    pub index: usize,
    /// Its statements, storing into `y_`.
    pub tokens: TokenStream,
    /// Whether it is a group of `∂q̈`'s rows: it stores its `q̈` into `x_` too and returns
    /// whether its pivots are positive.
    pub solved: bool,
    /// The number of matrices of the result.
    pub matrices: usize,
}

/// Where emitted code finds the robot's parameters.
pub struct Context {
    /// The array `[T; N]` of the parameters, in the order of [`crate::trace::Equations::fields`] (`p_`).
    pub parameters: proc_macro2::Ident,
    /// Whether each body's operations are counted ([`Body::ops`]): the derive reads no
    /// counts, and counting walks each function's nodes again.
    pub counted: bool,
}

/// One output of [`super::emit`]: the method returning it, which names its elements (`m1_2`,
/// `tau3`), and its shape.
pub struct Output<'a> {
    /// The method.
    pub method: Method,
    /// Shape.
    pub shape: Shape<'a>,
}

/// Code shared by several functions, computed by one inlined function and handed over as a
/// struct: the configuration (what depends on the parameters and `q` alone) and the motion
/// (what several methods compute from `q̇` too).
pub struct Shared {
    /// The struct's fields, in order.
    pub fields: Vec<proc_macro2::Ident>,
    /// The function's body, ending in the struct literal.
    pub tokens: TokenStream,
}
