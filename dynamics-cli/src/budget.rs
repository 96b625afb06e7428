//! Runs whose length the user's numbers set (the steps of a simulation, the samples of a move,
//! the evaluations of a search, the rows written): their cost counted before they start, in
//! what costs (steps of a group of lanes, samples of the regressor, bytes written), and refused
//! past a limit with what they would cost and the option that allows them (`--no-limits`);
//! once under way, a run longer than a few seconds shows its progress on stderr.

use std::time::{Duration, Instant};

/// The most bytes a command writes without `--no-limits`.
pub const MAX_OUTPUT_BYTES: f64 = 1e9;

/// The bytes a number takes in a CSV row, with its comma: about what `f64::to_string` writes
/// for a double of 17 significant digits.
pub const BYTES_PER_NUMBER: f64 = 20.0;

/// Counts past this are refused even with `--no-limits`: no run could finish them, and they
/// no longer count exactly in `f64`.
const UNREACHABLE: f64 = 9.007_199_254_740_992e15;

/// The cost of a run before it starts.
pub struct Cost<'a> {
    /// The options that set the cost, as the user would change them: `--duration / --dt`.
    pub options: &'a str,
    /// What the count counts, plural, and how the count was made: `RK4 steps (2 states in 1
    /// group of 4 lanes)`.
    pub unit: String,
    pub count: f64,
    /// The most of `count` a run takes without `--no-limits`.
    pub limit: f64,
    /// The bytes the run writes.
    pub bytes: f64,
}

impl Cost<'_> {
    /// `Ok` within the limits, or past them with `allowed` (`--no-limits`); else the message
    /// of the usage error, which says what the run would cost (its rough time from `seconds_per_unit`, which
    /// times a little of the work) and how to allow it.
    pub fn check(
        &self,
        allowed: bool,
        seconds_per_unit: impl FnOnce() -> f64,
    ) -> Result<(), String> {
        let within = self.count <= self.limit && self.bytes <= MAX_OUTPUT_BYTES;
        let reachable = self.count <= UNREACHABLE && self.bytes <= UNREACHABLE;
        if reachable && (within || allowed) {
            return Ok(());
        }
        let mut cost = format!("{} {}", count(self.count), self.unit);
        if self.count.is_finite() {
            let seconds = self.count * seconds_per_unit();
            cost += &format!(", about {}", duration(seconds));
        }
        if self.bytes > 0.0 && self.bytes.is_finite() {
            cost += &format!(", and about {} of output", bytes(self.bytes));
        }
        let message = if reachable {
            let mut over = Vec::new();
            if self.count > self.limit {
                over.push(format!("{} {}", count(self.limit), first_word(&self.unit)));
            }
            if self.bytes > MAX_OUTPUT_BYTES {
                over.push(format!("{} of output", bytes(MAX_OUTPUT_BYTES)));
            }
            format!(
                "{}: {cost}; a run takes at most {} without --no-limits (with it, the run \
                 shows its progress on stderr)",
                self.options,
                over.join(" and ")
            )
        } else {
            format!(
                "{}: {cost}; no run can take more than {} {}",
                self.options,
                count(UNREACHABLE),
                first_word(&self.unit)
            )
        };
        Err(message)
    }
}

/// The seconds one unit of `work` takes: `work` run until a few milliseconds have passed (at
/// most 1000 times).
pub fn time_per_unit(mut work: impl FnMut()) -> f64 {
    let start = Instant::now();
    let mut runs = 0_u32;
    while runs == 0 || (start.elapsed() < Duration::from_millis(5) && runs < 1000) {
        work();
        runs += 1;
    }
    start.elapsed().as_secs_f64() / f64::from(runs)
}

/// A count as people read it: `1200`, `3.5e8`.
fn count(x: f64) -> String {
    if x < 1e6 {
        format!("{x}")
    } else {
        format!("{x:.2e}").replace(".00e", "e")
    }
}

/// A unit without its parenthesis: `RK4 steps` of `RK4 steps (2 states ...)`.
fn first_word(unit: &str) -> &str {
    unit.split(" (").next().unwrap_or(unit)
}

/// A duration as people read it: `40 s`, `12 min`, `7.6 h`, `3 days`.
fn duration(seconds: f64) -> String {
    match seconds {
        s if s < 1.0 => "a second".to_string(),
        s if s < 100.0 => format!("{s:.0} s"),
        s if s < 6000.0 => format!("{:.0} min", s / 60.0),
        s if s < 48.0 * 3600.0 => format!("{:.1} h", s / 3600.0),
        s if s < 1e3 * 86400.0 * 365.0 => format!("{:.0} days", s / 86400.0),
        s => format!("{:.0e} years", s / (86400.0 * 365.0)),
    }
}

/// A size in bytes as people read it: `350 bytes`, `3.5 GB`.
fn bytes(b: f64) -> String {
    match b {
        b if b < 1e3 => format!("{b:.0} bytes"),
        b if b < 1e6 => format!("{:.1} kB", b / 1e3),
        b if b < 1e9 => format!("{:.1} MB", b / 1e6),
        b if b < 1e12 => format!("{:.1} GB", b / 1e9),
        b => format!("{:.1e} bytes", b),
    }
}

/// The progress of a long run on stderr: nothing for the first [`Progress::FIRST`], then a line
/// every [`Progress::EVERY`] with the share done and the time left at the rate so far.
pub struct Progress {
    what: String,
    unit: &'static str,
    total: f64,
    start: Instant,
    next: Duration,
}

impl Progress {
    /// When the first line is shown.
    pub const FIRST: Duration = Duration::from_secs(2);
    /// How often the next ones are.
    pub const EVERY: Duration = Duration::from_secs(5);

    /// The progress of `total` units of `what` (`dynamics simulate`).
    #[must_use]
    pub fn new(what: impl Into<String>, unit: &'static str, total: f64) -> Progress {
        Progress {
            what: what.into(),
            unit,
            total,
            start: Instant::now(),
            next: Self::FIRST,
        }
    }

    /// `done` units of the total are done: a line on stderr if it is time for one.
    pub fn update(&mut self, done: f64) {
        if let Some(line) = self.due(done, self.start.elapsed()) {
            eprintln!("{line}");
        }
    }

    /// The line to show `elapsed` after the start with `done` units done, if one is due.
    fn due(&mut self, done: f64, elapsed: Duration) -> Option<String> {
        (elapsed >= self.next).then(|| {
            self.next = elapsed + Self::EVERY;
            self.line(done, elapsed)
        })
    }

    /// The line shown after `elapsed` with `done` units done.
    fn line(&self, done: f64, elapsed: Duration) -> String {
        let share = done / self.total.max(1.0);
        let seconds = elapsed.as_secs_f64();
        let left = if share > 0.0 {
            format!(", about {} left", duration(seconds * (1.0 - share) / share))
        } else {
            String::new()
        };
        format!(
            "{}: {} of {} {} ({:.0} %) in {}{left}",
            self.what,
            count(done),
            count(self.total),
            self.unit,
            100.0 * share,
            duration(seconds)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn costs_within_the_limits_pass_and_others_say_what_they_would_cost() {
        let cost = |count: f64, bytes: f64| Cost {
            options: "--duration / --dt",
            unit: "RK4 steps (2 states in 1 group of 4 lanes)".to_string(),
            count,
            limit: 1e6,
            bytes,
        };
        assert!(cost(1e6, 1e9).check(false, || unreachable!()).is_ok());
        let message = |c: Cost, allowed: bool| match c.check(allowed, || 1e-4) {
            Err(message) => message,
            Ok(()) => panic!("refused"),
        };
        let steps = message(cost(5e8, 100.0), false);
        assert!(
            steps.contains(
                "--duration / --dt: 5e8 RK4 steps (2 states in 1 group of 4 lanes), about \
                 13.9 h, and about 100 bytes of output; a run takes at most 1e6 RK4 steps \
                 without --no-limits"
            ),
            "{steps}"
        );
        let output = message(cost(10.0, 3.5e9), false);
        assert!(
            output.contains("at most 1.0 GB of output without --no-limits"),
            "{output}"
        );
        assert!(cost(5e8, 3.5e9).check(true, || unreachable!()).is_ok());
        let never = message(cost(f64::INFINITY, 0.0), true);
        assert!(
            never.contains("inf RK4 steps (2 states in 1 group of 4 lanes); no run can take more than 9.01e15 RK4 steps"),
            "{never}"
        );
    }

    #[test]
    fn progress_lines() {
        let mut p = Progress::new("dynamics simulate", "RK4 steps", 4e6);
        let at = |s: f64| Duration::from_secs_f64(s);
        // Nothing for a short run; then a line every few seconds.
        assert_eq!(p.due(1e5, at(1.9)), None);
        assert!(p.due(2e5, at(2.0)).is_some());
        assert_eq!(p.due(3e5, at(6.9)), None);
        assert!(p.due(4e5, at(7.0)).is_some());
        assert_eq!(
            p.line(1e6, Duration::from_secs(30)),
            "dynamics simulate: 1e6 of 4e6 RK4 steps (25 %) in 30 s, about 90 s left"
        );
        assert_eq!(
            p.line(0.0, Duration::from_secs(3)),
            "dynamics simulate: 0 of 4e6 RK4 steps (0 %) in 3 s"
        );
        assert_eq!(duration(7.6 * 3600.0), "7.6 h");
        assert_eq!(bytes(3.5e9), "3.5 GB");
    }
}
