//! What `dynamics excite` reports: the motion's form, the search, the condition number reached
//! and the first guess's, and per joint its limits (and where they came from), how near the
//! motion comes to each, and its series' coefficients.

use dynamics_identification::excite::design::{Design, Problem, SEARCH_SAMPLES};
use dynamics_identification::excite::fourier::State;
use dynamics_identification::excite::limits::{JointLimits, Origin};
use serde_json::{json, Value};
use std::fmt::Write as _;

/// Everything the report states.
pub struct Report<'a> {
    pub robot: &'a str,
    /// The joint terms, in words.
    pub model: &'a str,
    pub problem: &'a Problem<'a>,
    pub limits: &'a [JointLimits],
    pub design: &'a Design,
    pub periods: u64,
    pub seed: u64,
    /// Per coordinate (every joint but the mimic ones), its joint's number and unit, `rad` or
    /// `m`.
    pub rows: Vec<(usize, &'static str)>,
    pub seconds: f64,
}

/// Four numbers in columns of 11.
fn numbers(values: [f64; 4]) -> String {
    values
        .iter()
        .fold(String::new(), |s, v| s + &format!("{v:>11.4}"))
}

/// Per joint over a period: the lowest and highest position, the largest speed and
/// acceleration.
struct Reached {
    low: f64,
    high: f64,
    speed: f64,
    acceleration: f64,
}

impl Report<'_> {
    fn reached(&self) -> Vec<Reached> {
        let p = self.problem;
        let mut out: Vec<Reached> = (0..self.design.series.len())
            .map(|_| Reached {
                low: f64::MAX,
                high: f64::MIN,
                speed: 0.0,
                acceleration: 0.0,
            })
            .collect();
        for k in 0..p.grid.samples() {
            for (r, s) in out.iter_mut().zip(p.states(&self.design.series, k)) {
                r.low = r.low.min(s.q);
                r.high = r.high.max(s.q);
                r.speed = r.speed.max(s.qd.abs());
                r.acceleration = r.acceleration.max(s.qdd.abs());
            }
        }
        out
    }

    /// The form of the motion, in words.
    fn motion(&self) -> String {
        let g = &self.problem.grid;
        let m = g.samples();
        format!(
            "per joint q(t) = q0 + Σ_{{l=1..{}}} (a_l/(ω l)) sin(ω l t) − (b_l/(ω l)) cos(ω l t), \
             ω = 2π/T, T = {} s, at rest at t = 0 (and at the end of each period); {} period{} \
             of {m} samples ({} Hz)",
            g.harmonics,
            g.period,
            self.periods,
            if self.periods == 1 { "" } else { "s" },
            crate::plot::number(m as f64 / g.period),
        )
    }

    fn method(&self) -> String {
        let o = &self.design.outcome;
        let converged = if o.step < dynamics_identification::excite::search::SMALLEST_STEP {
            "converged"
        } else {
            "stopped by the budget"
        };
        format!(
            "{} random restarts (seed {}), then a compass search of {} evaluations from the best \
             (final step {:.2e}, {converged}); the cost: cond(Y_B) over {} samples of the period; \
             each joint's series scaled to the largest motion within its limits",
            o.restarts,
            self.seed,
            o.compass,
            o.step,
            SEARCH_SAMPLES.min(self.problem.grid.samples())
        )
    }

    /// The table.
    #[must_use]
    pub fn text(&self) -> String {
        let d = self.design;
        let mut out = String::new();
        let _ = writeln!(
            out,
            "{}: exciting trajectory for {} base parameters (joint terms: {})",
            self.robot,
            self.problem.model.names.len(),
            self.model
        );
        let _ = writeln!(out, "motion: {}", self.motion());
        let _ = writeln!(out, "method: {}", self.method());
        let _ = writeln!(
            out,
            "condition number of the stacked base regressor over a period: {:.4e} (the initial \
             guess's: {:.4e}); {:.1} s",
            d.condition, d.initial_condition, self.seconds
        );
        let heads = |names: [&str; 4]| {
            names
                .iter()
                .fold(String::new(), |s, h| s + &format!("{h:>11}"))
        };
        let over = format!("{:>5}{:^44}  {:^44}", "", "limits", "reached");
        let _ = writeln!(
            out,
            "\n{}\n{:>5}{}  {}  unit  limits from (lower, upper, speed, accel.)",
            over.trim_end(),
            "joint",
            heads(["lower", "upper", "speed", "accel."]),
            heads(["low", "high", "speed", "accel."]),
        );
        for (j, (l, r)) in self.limits.iter().zip(self.reached()).enumerate() {
            let x = l.limits;
            let origins = l.origins.map(Origin::word).join(", ");
            let columns = numbers([x.lower, x.upper, x.velocity, x.acceleration]);
            let reached = numbers([r.low, r.high, r.speed, r.acceleration]);
            let _ = writeln!(
                out,
                "{:>5}{columns}  {reached}  {:<4}  {origins}",
                self.rows[j].0, self.rows[j].1
            );
        }
        let start: Vec<String> = self.start().iter().map(|s| format!("{:.6}", s.q)).collect();
        let _ = writeln!(out, "\nstart (t = 0, at rest): q = [{}]", start.join(", "));
        out
    }

    /// Every joint's state at t = 0.
    fn start(&self) -> Vec<State> {
        self.problem.states(&self.design.series, 0)
    }

    /// The same as JSON, with each joint's coefficients.
    #[must_use]
    pub fn json(&self) -> String {
        let d = self.design;
        let g = &self.problem.grid;
        let joints: Vec<Value> = self
            .limits
            .iter()
            .zip(self.reached())
            .zip(&d.series)
            .enumerate()
            .map(|(j, ((l, r), s))| {
                let o = l.origins.map(Origin::word);
                json!({
                    "joint": self.rows[j].0,
                    "unit": self.rows[j].1,
                    "limits": { "lower": l.limits.lower, "upper": l.limits.upper,
                                "velocity": l.limits.velocity,
                                "acceleration": l.limits.acceleration },
                    "limits_from": { "lower": o[0], "upper": o[1], "velocity": o[2],
                                     "acceleration": o[3] },
                    "reached": { "lower": r.low, "upper": r.high, "velocity": r.speed,
                                 "acceleration": r.acceleration },
                    "q0": s.q0, "a": s.a, "b": s.b,
                })
            })
            .collect();
        let o = &d.outcome;
        let report = json!({
            "robot": self.robot,
            "base_parameters": self.problem.model.names.len(),
            "joint_terms": self.model,
            "motion": self.motion(),
            "period": g.period,
            "harmonics": g.harmonics,
            "samples_per_period": g.samples(),
            "periods": self.periods,
            "method": self.method(),
            "seed": self.seed,
            "evaluations": { "restarts": o.restarts, "compass": o.compass, "final_step": o.step },
            "condition_number": d.condition,
            "initial_condition_number": d.initial_condition,
            "seconds": self.seconds,
            "start": self.start().iter().map(|s| s.q).collect::<Vec<f64>>(),
            "joints": joints,
        });
        format!("{report:#}\n")
    }
}
