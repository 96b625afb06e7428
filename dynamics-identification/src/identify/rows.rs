//! The equations of each sample: the regressor's entries at the sample's state and the joint
//! torques less the description's springs (`τ_i − k_i (q_i − rest_i)`: springs are known, not
//! identified). From a filtered source, both pass the same decimating low-pass
//! ([`super::decimate`]) before they are used.

use super::decimate::Decimator;
use super::model::{JointValues, LinearModel, Work};
use super::source::Source;
use crate::lanes::LANES;
use crate::trajectory::Sample;

/// Per joint, its spring `(k, rest)`, if any.
pub type Springs = [Option<(f64, f64)>];

/// Passes `each(t, entries, torques)` for every equation of the samples of `source`: the
/// entries in [`LinearModel::rows`]' order, one torque per joint. How q̇ and q̈ were had.
///
/// # Errors
/// Reading the samples; a sample whose equations are not finite numbers.
pub fn each_row(
    model: &LinearModel,
    source: &Source,
    springs: &Springs,
    mut each: impl FnMut(f64, &[f64], &[f64]),
) -> Result<&'static str, String> {
    let (entries, n) = (model.entries(), model.joints());
    let mut work = Work::default();
    let mut rows = vec![0.0; LANES * entries];
    let mut row = vec![0.0; entries + n];
    let mut decimator = source
        .filter()
        .map(|f| Decimator::new(f.decimation, entries + n));
    // The samples wait in groups of `LANES`, whose regressor is evaluated at once (the group's
    // buffers reused from one group to the next).
    let mut group: Vec<Sample> = Vec::with_capacity(LANES);
    let mut filled = 0;
    // The first sample whose equations are not finite: its line and time.
    let mut failed = None;
    let mut flush = |group: &[Sample]| {
        let states: Vec<JointValues> = group
            .iter()
            .map(|s| JointValues {
                q: &s.q,
                qd: &s.qd,
                qdd: &s.qdd,
            })
            .collect();
        model.rows(&states, &mut work, &mut rows);
        for (k, s) in group.iter().enumerate() {
            row[..entries].copy_from_slice(&rows[k * entries..(k + 1) * entries]);
            // The file's last torques: a floating base's file may give the base's six before
            // the joints' rows alone.
            let measured = &s.tau[s.tau.len() - n..];
            for (i, tau) in row[entries..].iter_mut().enumerate() {
                *tau =
                    springs[i].map_or(measured[i], |(k, rest)| measured[i] - k * (s.q[i] - rest));
            }
            if failed.is_some() {
                return;
            }
            // Squares are summed: the fit's factors, the RMS of the residuals.
            if !row.iter().all(|x| (x * x).is_finite()) {
                failed = Some((s.line, s.t, s.largest()));
                return;
            }
            match &mut decimator {
                None => each(s.t, &row[..entries], &row[entries..]),
                Some(d) => {
                    if let Some((t, filtered)) = d.push(s.t, &row) {
                        each(t, &filtered[..entries], &filtered[entries..]);
                    }
                }
            }
        }
    };
    let how = source.each(|s| {
        match group.get_mut(filled) {
            Some(waiting) => waiting.clone_from(s),
            None => group.push(s.clone()),
        }
        filled += 1;
        if filled == LANES {
            flush(&group);
            filled = 0;
        }
    })?;
    if filled > 0 {
        flush(&group[..filled]);
    }
    match failed {
        None => Ok(how),
        Some((line, t, (column, name, value))) => Err(format!(
            "{}: line {line}, column {column} ({name}): at t = {} s a torque (less its \
             spring) or an entry of the regressor is too large to square; the sample's largest \
             value is {value:e}, of this column (or of its differences)",
            source.path(),
            crate::trajectory::decimal(t)
        )),
    }
}
