//! The equations of each sample: the regressor's entries at the sample's state and the joint
//! torques less the description's springs (`τ_i − k_i (q_i − rest_i)`: springs are known, not
//! identified). From a filtered source, both pass the same decimating low-pass
//! ([`super::decimate`]) before they are used.

use super::decimate::Decimator;
use super::model::{LinearModel, Work};
use super::source::Source;

/// Per joint, its spring `(k, rest)`, if any.
pub type Springs = [Option<(f64, f64)>];

/// Passes `each(t, entries, torques)` for every equation of the samples of `source`: the
/// entries in [`LinearModel::rows`]' order, one torque per joint. How q̇ and q̈ were had.
///
/// # Errors
/// Reading the samples.
pub fn each_row(
    model: &LinearModel,
    source: &Source,
    springs: &Springs,
    mut each: impl FnMut(f64, &[f64], &[f64]),
) -> Result<&'static str, String> {
    let (entries, n) = (model.entries(), model.joints());
    let mut work = Work::default();
    let mut row = vec![0.0; entries + n];
    let mut decimator = source
        .filter()
        .map(|f| Decimator::new(f.decimation, entries + n));
    source.each(|s| {
        model.rows(&s.q, &s.qd, &s.qdd, &mut work, &mut row[..entries]);
        for (i, tau) in row[entries..].iter_mut().enumerate() {
            *tau = springs[i].map_or(s.tau[i], |(k, rest)| s.tau[i] - k * (s.q[i] - rest));
        }
        match &mut decimator {
            None => each(s.t, &row[..entries], &row[entries..]),
            Some(d) => {
                if let Some((t, filtered)) = d.push(s.t, &row) {
                    each(t, &filtered[..entries], &filtered[entries..]);
                }
            }
        }
    })
}
