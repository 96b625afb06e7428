//! The figure of an identification: per joint, the measured torque and the torque the
//! estimate predicts, `Y(q, q̇, q̈) π̂` (left), and their difference (right).

use super::identify::Row;
use crate::plot::{Envelope, Figure, Line, Panel};

/// Series per joint in the envelope: measured, predicted, residual.
pub const SERIES: usize = 3;

const MEASURED: &str = "#000000";
const PREDICTED: &str = "#d62728";
const RESIDUAL: &str = "#1f77b4";

/// The values of one sample's series: per joint, measured, predicted and their difference.
pub fn values(measured: &[f64], predicted: &[f64], out: &mut [f64]) {
    for (i, (m, p)) in measured.iter().zip(predicted).enumerate() {
        out[SERIES * i..SERIES * (i + 1)].copy_from_slice(&[*m, *p, m - p]);
    }
}

/// The figure of `envelope` (filled with [`values`]) for these rows of τ (a coordinate's row i
/// is its joint's, `joint 5: τ4` past a mimic joint; a floating base's `base fx: τ1`); `filtered`
/// when the measured torques were low-passed (the figure says so: it shows them filtered).
#[must_use]
pub fn figure<'e>(
    title: String,
    rows: &[Row],
    filtered: bool,
    envelope: &'e Envelope,
) -> Figure<'e> {
    let measured = if filtered {
        "measured τ (filtered)"
    } else {
        "measured τ"
    };
    let line = |label: &str, color, series, bold| Line {
        label: label.into(),
        color,
        series,
        bold,
    };
    let rows = rows
        .iter()
        .enumerate()
        .map(|(i, row)| {
            let (name, unit) = (row.name(), row.unit);
            let base = SERIES * i;
            vec![
                Panel {
                    title: format!("{name}: τ{} ({unit})", row.tau),
                    lines: vec![
                        line("measured", MEASURED, base, false),
                        line("predicted", PREDICTED, base + 1, false),
                    ],
                },
                Panel {
                    title: format!("{name}: measured − predicted ({unit})"),
                    lines: vec![line("residual", RESIDUAL, base + 2, false)],
                },
            ]
        })
        .collect();
    Figure {
        title,
        legend: vec![
            (measured.into(), MEASURED),
            ("predicted Y π̂".into(), PREDICTED),
            ("residual".into(), RESIDUAL),
        ],
        rows,
        widths: vec![520.0, 360.0],
        envelope,
    }
}
