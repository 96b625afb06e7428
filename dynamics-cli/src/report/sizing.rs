//! The figure of `dynamics size --svg`: per joint, τ and its terms (left) and the power (right),
//! from the decimated series of a sizing ([`dynamics_identification::sizing`]).

use crate::plot::{Envelope, Figure, Line, Panel};
use dynamics_codegen::model::JointKind;
use dynamics_identification::sizing::{unit, Series, SERIES, TERMS};

/// The colours of the terms of τ, in the order of [`TERMS`].
const COLORS: [&str; 5] = ["#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#d62728"];

/// The envelope decimates the sizing's series for the figure.
impl Series for Envelope {
    fn push(&mut self, t: f64, values: &[f64]) {
        Envelope::push(self, t, values);
    }
}

/// The figure of a sizing: per joint, τ and its terms (left) and the power (right). Terms that
/// are zero all along are left out.
#[must_use]
pub fn figure<'e>(title: String, kinds: &[JointKind], envelope: &'e Envelope) -> Figure<'e> {
    let zero = |series: usize| envelope_is_zero(envelope, series);
    let present: Vec<bool> = (0..5)
        .map(|k| (0..kinds.len()).any(|j| !zero(SERIES * j + 1 + k)))
        .collect();
    let mut legend = vec![("τ".to_string(), "#000000")];
    legend.extend(
        TERMS
            .iter()
            .zip(COLORS)
            .zip(&present)
            .filter(|(_, &p)| p)
            .map(|((name, color), _)| ((*name).to_string(), color)),
    );
    legend.push(("power τ q̇".to_string(), "#17becf"));
    let rows = kinds
        .iter()
        .enumerate()
        .map(|(j, &kind)| {
            let base = SERIES * j;
            let mut lines: Vec<Line> = TERMS
                .iter()
                .zip(COLORS)
                .enumerate()
                .filter(|&(k, _)| present[k] && !zero(base + 1 + k))
                .map(|(k, (name, color))| Line {
                    label: (*name).to_string(),
                    color,
                    series: base + 1 + k,
                    bold: false,
                })
                .collect();
            lines.push(Line {
                label: "τ".into(),
                color: "#000000",
                series: base,
                bold: true,
            });
            vec![
                Panel {
                    title: format!("joint {}: τ{} ({})", j + 1, j + 1, unit(kind)),
                    lines,
                },
                Panel {
                    title: format!("joint {}: power (W)", j + 1),
                    lines: vec![Line {
                        label: "power".into(),
                        color: "#17becf",
                        series: base + 6,
                        bold: false,
                    }],
                },
            ]
        })
        .collect();
    Figure {
        title,
        legend,
        rows,
        widths: vec![560.0, 300.0],
        envelope,
    }
}

fn envelope_is_zero(envelope: &Envelope, series: usize) -> bool {
    envelope.range(series) == (0.0, 0.0)
}
