//! What `dynamics identify` prints: a table, or the same as JSON.

use crate::format::unsigned_zero;
use crate::plot::number;
use dynamics_identification::identify::consistent::Consistent;
use dynamics_identification::identify::decimate;
use dynamics_identification::identify::estimate::Estimate;
use dynamics_identification::identify::filter::ORDER;
use dynamics_identification::identify::model::LinearModel;
use dynamics_identification::identify::predict::Prediction;
use dynamics_identification::identify::rank::Unidentified;
use dynamics_identification::Filter;
use serde_json::{json, Value};
use std::fmt::Write as _;

/// Everything the report states.
pub struct Report<'a> {
    pub robot: &'a str,
    pub csv: &'a str,
    /// How q̇ and q̈ were had.
    pub method: &'a str,
    pub filter: Option<Filter>,
    /// The parameters identified, in words.
    pub model: &'a str,
    pub springs: bool,
    pub tolerance: f64,
    pub start: f64,
    pub end: f64,
    /// Per row of τ (a coordinate: every joint but the mimic ones; a floating base's six and
    /// its joints'), which it is and its unit.
    pub rows: Vec<Row>,
    /// Which rows of τ were fitted, in words, where not every joint's (a floating base).
    pub rows_used: Option<String>,
    pub linear: &'a LinearModel,
    pub estimate: &'a Estimate,
    /// The consistent estimate and its standard parameters' names, if asked for.
    pub consistent: Option<(&'a Consistent, Vec<String>)>,
    /// Other measurements' file and their torques predicted, if asked for.
    pub validation: Option<(&'a str, Prediction)>,
}

/// A row of τ: its number in τ (1-based), its joint's number or, on a floating base, the
/// component of the wrench on the base it is (`fx` … `mz`, in the base frame), and its unit.
#[derive(Clone, Copy, Debug)]
pub struct Row {
    pub tau: usize,
    pub joint: Option<usize>,
    pub base: &'static str,
    pub unit: &'static str,
}

/// A floating base's six rows of τ, the wrench on the base in its frame, and their units.
pub const BASE_ROWS: [(&str, &str); 6] = [
    ("fx", "N"),
    ("fy", "N"),
    ("fz", "N"),
    ("mx", "N m"),
    ("my", "N m"),
    ("mz", "N m"),
];

impl Row {
    /// The table's label: the joint's number, or the base's component.
    #[must_use]
    pub fn label(&self) -> String {
        self.joint.map_or(self.base.to_string(), |j| j.to_string())
    }

    /// The figure's: `joint 3`, `base fx`.
    #[must_use]
    pub fn name(&self) -> String {
        self.joint
            .map_or(format!("base {}", self.base), |j| format!("joint {j}"))
    }
}

const METHOD: &str = "two-step weighted least squares (Gautier): an ordinary fit, then each \
                      joint's rows weighted by 1/σ_i, σ_i its residual's standard deviation";

impl Report<'_> {
    /// The table.
    #[must_use]
    pub fn text(&self) -> String {
        let e = self.estimate;
        let mut out = String::new();
        let _ = writeln!(
            out,
            "{}: {} samples, t = {} to {} s ({}, {})",
            self.robot, e.samples, self.start, self.end, self.csv, self.method
        );
        let filter = self.filter.map_or("none".into(), |f| describe(&f));
        let _ = writeln!(out, "filter: {filter}");
        let _ = writeln!(out, "model: {}", self.model);
        if let Some(rows) = &self.rows_used {
            let _ = writeln!(out, "rows: {rows}");
        }
        if self.springs {
            let _ = writeln!(out, "springs: the description's, subtracted from τ");
        }
        let method = if e.weighted {
            METHOD
        } else {
            "ordinary least squares (every joint fitted exactly: no weights)"
        };
        let _ = writeln!(out, "method: {method}{}", reweighted(e.reweighted));
        let _ = writeln!(
            out,
            "condition number of the weighted stacked regressor: {}\n",
            short(e.condition)
        );
        let _ = writeln!(
            out,
            "{:<10} {:>14} {:>12} {:>9}  {:>14}",
            "parameter", "estimate", "std dev", "rel std", "described"
        );
        for k in (0..self.linear.names.len()).filter(|&k| !e.values[k].is_nan()) {
            let _ = writeln!(
                out,
                "{:<10} {:>14.6e} {:>12.3e} {:>9}  {:>14.6e}",
                self.linear.names[k],
                unsigned_zero(e.values[k]),
                e.deviations[k],
                relative(e.values[k], e.deviations[k]).map_or("-".into(), |r| format!("{r:.2} %")),
                unsigned_zero(self.linear.described[k])
            );
        }
        if !e.unidentified.is_empty() {
            let _ = writeln!(
                out,
                "\nnot identifiable from these data (tolerance {:e}), not estimated:",
                self.tolerance
            );
            for u in &e.unidentified {
                let _ = writeln!(out, "  {}", self.unidentified(u));
            }
        }
        let _ = writeln!(
            out,
            "\n{:>5} {:>14} {:>14}",
            self.head(),
            "σ_i",
            "residual RMS"
        );
        for (i, (s, r)) in e.sigma.iter().zip(&e.rms).enumerate() {
            let (joint, unit) = (self.rows[i].label(), self.rows[i].unit);
            let _ = writeln!(out, "{joint:>5} {s:>10.3e} {unit:<3} {r:>10.3e} {unit}");
        }
        if let Some((c, names)) = &self.consistent {
            self.consistent_text(&mut out, c, names);
        }
        if let Some((csv, p)) = &self.validation {
            self.validation_text(&mut out, csv, p);
        }
        out
    }

    /// The validation's table: per row, the RMS of τ and of the prediction's error.
    fn validation_text(&self, out: &mut String, csv: &str, p: &Prediction) {
        let _ = writeln!(
            out,
            "\nvalidation: the torques of {csv} ({} samples, not in the fit) predicted by \
             the estimate\n{:>5} {:>14} {:>14} {:>9}",
            p.samples,
            self.head(),
            "RMS of τ",
            "RMS error",
            "relative"
        );
        for (i, (m, e)) in p.measured_rms.iter().zip(&p.error_rms).enumerate() {
            let (joint, unit) = (self.rows[i].label(), self.rows[i].unit);
            let relative = relative(*m, *e).map_or("-".into(), |r| format!("{r:.2} %"));
            let _ = writeln!(
                out,
                "{joint:>5} {m:>10.3e} {unit:<3} {e:>10.3e} {unit:<3} {relative:>9}"
            );
        }
    }

    /// The rows' column's heading: `joint`, or `row` where a floating base's are among them.
    fn head(&self) -> &'static str {
        if self.rows.iter().any(|r| r.joint.is_none()) {
            "row"
        } else {
            "joint"
        }
    }

    /// The consistent estimate beside the plain one.
    fn consistent_text(&self, out: &mut String, c: &Consistent, names: &[String]) {
        let e = self.estimate;
        let _ = writeln!(
            out,
            "\nphysically consistent estimate: {CONSISTENT} ({} rounds of cuts)",
            c.rounds
        );
        let verdict = if c.plain_is_consistent { "yes" } else { "no" };
        let _ = writeln!(
            out,
            "the plain estimate is consistent: {verdict} (weighted squared residual: plain {:.6e}, \
             consistent {:.6e})",
            c.plain_residual, c.residual
        );
        let _ = writeln!(
            out,
            "{:<10} {:>14} {:>14}",
            "parameter", "consistent", "plain"
        );
        for (k, name) in self.linear.names.iter().enumerate() {
            let plain = if e.values[k].is_nan() {
                0.0
            } else {
                e.values[k]
            };
            let _ = writeln!(
                out,
                "{name:<10} {:>14.6e} {:>14.6e}",
                unsigned_zero(c.base[k]),
                unsigned_zero(plain)
            );
        }
        let _ = writeln!(
            out,
            "\n{:>5} {:>12} {:>32} {:>14}",
            "link", "mass", "centre of mass", "smallest eig J"
        );
        for (l, link) in c.links.iter().enumerate() {
            let com: Vec<String> = link.com.iter().map(|x| format!("{x:+.4e}")).collect();
            let _ = writeln!(
                out,
                "{:>5} {:>12.6e} {:>32} {:>14.3e}",
                l + 1,
                unsigned_zero(link.mass),
                com.join(" "),
                link.smallest_eigenvalue
            );
        }
        let _ = writeln!(
            out,
            "\nstandard parameters (the links' about their frame's origin):"
        );
        for (name, value) in names.iter().zip(&c.standard) {
            let _ = writeln!(out, "  {name:<6} {:>14.6e}", unsigned_zero(*value));
        }
        let _ = writeln!(
            out,
            "\n{:>5} {:>18} {:>18}",
            self.head(),
            "residual RMS plain",
            "consistent"
        );
        for (i, (p, r)) in e.rms.iter().zip(&c.rms).enumerate() {
            let (joint, unit) = (self.rows[i].label(), self.rows[i].unit);
            let _ = writeln!(out, "{joint:>5} {p:>14.3e} {unit:<3} {r:>14.3e} {unit}");
        }
    }

    /// Why parameter `u` is not identified.
    fn unidentified(&self, u: &Unidentified) -> String {
        let name = &self.linear.names[u.parameter];
        if u.combination.is_empty() {
            return format!("{name}: its column is zero (the motion does not excite it)");
        }
        let terms: Vec<String> = u
            .combination
            .iter()
            .take(4)
            .map(|&(j, c)| format!("{:+.4e} {}", c, self.linear.names[j]))
            .collect();
        let more = if u.combination.len() > 4 { " …" } else { "" };
        format!(
            "{name}: its column is {}{more} (their estimates include it)",
            terms.join(" ")
        )
    }

    /// The same as JSON.
    #[must_use]
    pub fn json(&self) -> String {
        let e = self.estimate;
        let names = &self.linear.names;
        let parameters: Vec<Value> = (0..names.len())
            .filter(|&k| !e.values[k].is_nan())
            .map(|k| {
                json!({
                    "name": names[k],
                    "estimate": unsigned_zero(e.values[k]),
                    "std_dev": e.deviations[k],
                    "relative_std_percent": relative(e.values[k], e.deviations[k]),
                    "described": unsigned_zero(self.linear.described[k]),
                })
            })
            .collect();
        let unidentifiable: Vec<Value> = e
            .unidentified
            .iter()
            .map(|u| {
                let combination: Vec<Value> = u
                    .combination
                    .iter()
                    .map(|&(j, c)| json!({ "name": names[j], "coefficient": c }))
                    .collect();
                json!({ "name": names[u.parameter], "combination": combination })
            })
            .collect();
        let joints: Vec<Value> = (0..e.rms.len())
            .map(
                |i| json!({ "joint": self.rows[i].joint, "row": self.rows[i].label(), "tau": self.rows[i].tau, "unit": self.rows[i].unit, "sigma": e.sigma[i], "residual_rms": e.rms[i] }),
            )
            .collect();
        let filter = self.filter.map(|f| {
            // The positions' filter, then the torques' and regressor's (parallel) one.
            json!({ "kind": "butterworth", "order": ORDER, "cutoff_hz": f.cutoff,
                    "rate_hz": f.rate, "zero_phase": true, "decimation": f.decimation,
                    "parallel_fir_taps": decimate::length(f.decimation), "samples_read": f.read })
        });
        let report = json!({
            "robot": self.robot,
            "csv": self.csv,
            "derivatives": self.method,
            "samples": e.samples,
            "start": self.start,
            "end": self.end,
            "filter": filter,
            "model": self.model,
            "rows": self.rows_used,
            "springs_subtracted": self.springs,
            "method": if e.weighted { "weighted least squares" } else { "ordinary least squares" },
            "weights_reestimated": e.reweighted,
            "condition_number": e.condition,
            "tolerance": self.tolerance,
            "parameters": parameters,
            "unidentifiable": unidentifiable,
            "joints": joints,
            "consistent": self.consistent.as_ref().map(|(c, names)| consistent_json(c, names, names_of(self.linear))),
            "validation": self.validation.as_ref().map(|(csv, p)| json!({
                "csv": csv,
                "samples": p.samples,
                "joints": p.measured_rms.iter().zip(&p.error_rms)
                    .map(|(m, e)| json!({ "rms": m, "error_rms": e }))
                    .collect::<Vec<Value>>(),
            })),
        });
        format!("{report:#}\n")
    }
}

/// What the consistent estimate is.
const CONSISTENT: &str = "every link's pseudo-inertia J = [[½ tr(I) 1 − I, m c], [m cᵀ, m]] \
                          positive semidefinite, actuator inertia, viscous and Coulomb friction \
                          nonnegative, minimising the weighted residual plus 10⁻⁸ (relative) \
                          times the squared distance to the description's standard parameters";

fn names_of(linear: &LinearModel) -> &[String] {
    &linear.names
}

/// The consistent estimate as JSON.
fn consistent_json(c: &Consistent, standard: &[String], base: &[String]) -> Value {
    let links: Vec<Value> = c
        .links
        .iter()
        .map(|l| {
            let com = l
                .com
                .iter()
                .map(|x| x.is_finite().then_some(*x))
                .collect::<Vec<_>>();
            json!({ "mass": l.mass, "com": com, "smallest_eigenvalue": l.smallest_eigenvalue })
        })
        .collect();
    json!({
        "method": CONSISTENT,
        "rounds": c.rounds,
        "plain_is_consistent": c.plain_is_consistent,
        "plain_weighted_residual": c.plain_residual,
        "weighted_residual": c.residual,
        "parameters": base.iter().zip(&c.base)
            .map(|(n, v)| json!({ "name": n, "estimate": unsigned_zero(*v) }))
            .collect::<Vec<Value>>(),
        "standard": standard.iter().zip(&c.standard)
            .map(|(n, v)| json!({ "name": n, "value": unsigned_zero(*v) }))
            .collect::<Vec<Value>>(),
        "links": links,
        "residual_rms": c.rms,
    })
}

/// `; σ_i re-estimated k times …` when the weights were iterated.
fn reweighted(times: usize) -> String {
    match times {
        0 => String::new(),
        1 => "; σ_i re-estimated once from the weighted fit's residuals".into(),
        _ => format!("; σ_i re-estimated {times} times from the weighted fit's residuals"),
    }
}

/// `100 σ / |x|` %, where x is not zero.
fn relative(x: f64, deviation: f64) -> Option<f64> {
    (x != 0.0).then(|| 100.0 * deviation / x.abs())
}

/// Four significant digits.
fn short(x: f64) -> String {
    if x.is_finite() {
        format!("{x:.4e}")
    } else {
        "infinite".into()
    }
}

/// The filter in words.
fn describe(f: &Filter) -> String {
    format!(
        "q (and any q̇, q̈ given): {ORDER}th-order Butterworth low-pass at {} Hz (samples at {} \
         Hz), forward and backward (zero phase, −6 dB at the cutoff), before differentiation; τ \
         and every column of the regressor alike: a zero-phase FIR low-pass ({} taps) at {} Hz, \
         then one sample in {} kept, {} of {} (parallel filtering and decimation)",
        f.cutoff,
        number(f.rate),
        decimate::length(f.decimation),
        number(f.rate / (2.0 * f.decimation as f64)),
        f.decimation,
        f.kept(),
        f.read
    )
}
