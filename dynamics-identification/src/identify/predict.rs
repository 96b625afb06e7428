//! The torques an estimate predicts, `τ̂_i = Σ_k Y_ik(q, q̇, q̈) π̂_k`, against those measured,
//! over the samples of a file: the figure of measured against predicted torque (`--plot`, on
//! the data of the fit) and the validation on other data (`--validate`, motions the fit never
//! saw), whose per-joint root mean square error `√(Σ_t (τ_i − τ̂_i)² / N)` is the honest
//! measure of the model: on the data of the fit the residual is as small as least squares could
//! make it.
//!
//! A parameter that was not identified counts as zero (its effect is in the estimates of the
//! parameters it is a combination of). The torques are the measured ones less the
//! description's springs, as in the fit; through a filter, both sides are filtered alike.

use super::estimate::Estimate;
use super::model::LinearModel;
use super::rows::{each_row, Springs};
use super::source::Source;
use crate::Error;

/// Told each sample's time, measured torques and predicted torques (for a figure).
pub type EachSample<'a> = &'a mut dyn FnMut(f64, &[f64], &[f64]);

/// The prediction's errors over a file.
#[derive(Clone, Debug)]
pub struct Prediction {
    pub samples: usize,
    /// Per joint: the root mean square of the measured torque, and of the prediction's error.
    pub measured_rms: Vec<f64>,
    pub error_rms: Vec<f64>,
}

/// One pass over `source`: the estimate's predictions against the measured torques, each
/// sample's told `each(t, measured, predicted)` if given (for a figure).
///
/// # Errors
/// Reading the samples ([`Error::Samples`]); errors too large to square ([`Error::Estimate`]).
pub fn predict(
    model: &LinearModel,
    source: &Source,
    springs: &Springs,
    estimate: &Estimate,
    mut each: Option<EachSample<'_>>,
) -> Result<Prediction, Error> {
    let n = model.joints();
    let pi: Vec<f64> = estimate
        .values
        .iter()
        .map(|v| if v.is_nan() { 0.0 } else { *v })
        .collect();
    let mut predicted = vec![0.0; n];
    let (mut measured_sq, mut error_sq, mut samples) = (vec![0.0; n], vec![0.0; n], 0);
    // The first time whose error's square is not finite.
    let mut overflow = None;
    each_row(model, source, springs, |t, entries, torques| {
        let mut start = 0;
        for (i, columns) in model.columns.iter().enumerate() {
            let row = &entries[start..start + columns.len()];
            predicted[i] = columns.iter().zip(row).map(|(&k, y)| y * pi[k]).sum();
            start += columns.len();
            measured_sq[i] += torques[i] * torques[i];
            error_sq[i] += (torques[i] - predicted[i]).powi(2);
            if !error_sq[i].is_finite() {
                overflow = overflow.or(Some(t));
            }
        }
        samples += 1;
        if let Some(each) = each.as_deref_mut() {
            each(t, torques, &predicted);
        }
    })
    .map_err(Error::Samples)?;
    if let Some(t) = overflow {
        return Err(Error::Estimate(format!(
            "{}: at t = {} s the squared error of the predicted torques is not a finite \
             number: the values are too large for the estimate",
            source.path(),
            crate::trajectory::decimal(t)
        )));
    }
    let rms = |sums: Vec<f64>| -> Vec<f64> {
        sums.into_iter()
            .map(|s| (s / samples.max(1) as f64).sqrt())
            .collect()
    };
    Ok(Prediction {
        samples,
        measured_rms: rms(measured_sq),
        error_rms: rms(error_sq),
    })
}
