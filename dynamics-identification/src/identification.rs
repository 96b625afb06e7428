//! The estimate of a robot's parameters from the samples of a file, and its predictions on
//! others: the steps of [`crate::identify`](mod@crate::identify) in order.

use crate::identify::base::Standard;
use crate::identify::consistent::{consistent, Consistent, Problem};
use crate::identify::estimate::{estimate, Estimate, ITERATIONS};
use crate::identify::measured::Measured;
use crate::identify::predict::{EachSample, Prediction};
use crate::identify::rows::each_row;
use crate::identify::source::Source;
use crate::{Error, Regressor};
use dynamics_codegen::Parameter;

/// How the estimate is made.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// A column of the regressor within this fraction of its norm of the span of the columns
    /// before it is not identifiable: named, not estimated.
    pub tolerance: f64,
    /// The most times the weights are re-estimated from a weighted fit (0: Gautier's two
    /// steps; at most [`ITERATIONS`] is useful).
    pub weight_iterations: usize,
    /// Also the physically consistent standard parameters.
    pub consistent: bool,
}

impl Default for Options {
    /// `dynamics identify`'s defaults: tolerance 10⁻⁴, two steps, no consistent estimate.
    fn default() -> Options {
        Options {
            tolerance: 1e-4,
            weight_iterations: 0,
            consistent: false,
        }
    }
}

/// What [`identify()`] found.
pub struct Identified {
    /// The base parameters' estimate, in [`Regressor::names`]' order.
    pub estimate: Estimate,
    /// With [`Options::consistent`]: the standard parameters and the consistent estimate.
    pub consistent: Option<(Standard, Consistent)>,
    /// How q̇ and q̈ were had (`given`, or by differences).
    pub method: &'static str,
    /// The time of the first and of the last equations used.
    pub span: (f64, f64),
}

/// The base parameters of `regressor` estimated from `samples`.
///
/// # Errors
/// [`Error::Samples`]: reading the samples, or a sample whose equations are not finite;
/// [`Error::Estimate`]: samples that cannot give the estimate; [`Error::Consistent`]: the
/// consistent estimate not found.
pub fn identify(
    regressor: &Regressor,
    samples: &Source,
    options: &Options,
) -> Result<Identified, Error> {
    let (mut measured, method, span) = measure(regressor, samples)?;
    let iterations = options.weight_iterations.min(ITERATIONS);
    let estimate =
        estimate(&mut measured, options.tolerance, iterations).map_err(Error::Estimate)?;
    let consistent = if options.consistent {
        let standard = regressor.standard();
        let found = consistent_estimate(&mut measured, &estimate, &standard)?;
        Some((standard, found))
    } else {
        None
    };
    Ok(Identified {
        estimate,
        consistent,
        method,
        span,
    })
}

/// The torques `estimate` predicts for `samples`, against those measured; `each(t, measured,
/// predicted)` told every sample's, if given (for a figure).
///
/// # Errors
/// [`Error::Samples`]: reading the samples; [`Error::Estimate`]: errors too large to square.
pub fn predict(
    regressor: &Regressor,
    samples: &Source,
    estimate: &Estimate,
    each: Option<EachSample<'_>>,
) -> Result<Prediction, Error> {
    crate::identify::predict::predict(
        regressor.model(),
        samples,
        regressor.springs(),
        estimate,
        each,
    )
}

/// The consistent estimate beside the plain `estimate`.
fn consistent_estimate(
    measured: &mut Measured,
    estimate: &Estimate,
    standard: &Standard,
) -> Result<Consistent, Error> {
    // The bodies' count: the joints' on a fixed base, one more on a floating one (whose rows
    // are more than its links, or fewer with its joints' rows alone).
    let links = standard
        .parameters
        .iter()
        .filter(|p| matches!(p, Parameter::Link { .. }))
        .count()
        / 10;
    // Offset friction may have either sign; the other joint terms dissipate or add inertia.
    let joint_terms: Vec<bool> = standard.parameters[10 * links..]
        .iter()
        .map(|p| !matches!(p, Parameter::Joint { index: 3, .. }))
        .collect();
    let problem = Problem {
        links,
        joint_terms: &joint_terms,
        map: &standard.map,
        described: &standard.described,
    };
    consistent(measured, estimate, &problem).map_err(Error::Consistent)
}

/// One pass over the samples into the joints' factors; how q̇ and q̈ were had, and the time
/// span.
fn measure(
    regressor: &Regressor,
    samples: &Source,
) -> Result<(Measured, &'static str, (f64, f64)), Error> {
    let model = regressor.model();
    let mut measured = Measured::new(model.columns.clone(), model.names.len());
    let mut span = (f64::NAN, f64::NAN);
    let method = each_row(
        model,
        samples,
        regressor.springs(),
        |t, entries, torques| {
            if span.0.is_nan() {
                span.0 = t;
            }
            span.1 = t;
            let mut start = 0;
            for (i, columns) in model.columns.iter().enumerate() {
                measured.push(i, &entries[start..start + columns.len()], torques[i]);
                start += columns.len();
            }
        },
    )
    .map_err(Error::Samples)?;
    Ok((measured, method, span))
}
