//! Time plots as SVG, written by hand (no plotting dependency), from a streamed decimation.
//!
//! [`Envelope`] keeps, for every series, the minimum and the maximum over each of at most
//! [`COLUMNS`] equal time buckets; when a sample falls past the last bucket, neighbouring buckets
//! merge in pairs and the width doubles. Memory is bounded whatever the length of the input, and
//! a line drawn through each bucket's minimum and maximum shows every peak of the full series.

pub use dynamics_identification::text::number;
use std::fmt::Write as _;
use std::io::{self, Write};

/// The most buckets an envelope holds: about one per pixel column of a panel.
pub const COLUMNS: usize = 480;

/// The minimum and maximum of each series per time bucket.
pub struct Envelope {
    series: usize,
    start: f64,
    end: f64,
    width: f64,
    /// `[min, max, first, last]` per series, bucket after bucket.
    buckets: Vec<[f64; 4]>,
}

impl Envelope {
    #[must_use]
    pub fn new(series: usize) -> Envelope {
        Envelope {
            series,
            start: f64::NAN,
            end: f64::NAN,
            width: f64::NAN,
            buckets: Vec::new(),
        }
    }

    /// Adds the values of every series at time `t` (after the previous sample's time).
    pub fn push(&mut self, t: f64, values: &[f64]) {
        if self.start.is_nan() {
            self.start = t;
        } else if self.width.is_nan() {
            self.width = t - self.start;
        }
        self.end = t;
        let mut index = self.index(t);
        while index >= COLUMNS {
            self.merge();
            index = self.index(t);
        }
        let first = index * self.series;
        if self.buckets.len() < first + self.series {
            self.buckets.resize(
                first + self.series,
                [f64::INFINITY, f64::NEG_INFINITY, f64::NAN, f64::NAN],
            );
        }
        for (b, &v) in self.buckets[first..].iter_mut().zip(values) {
            if b[2].is_nan() {
                b[2] = v;
            }
            *b = [b[0].min(v), b[1].max(v), b[2], v];
        }
    }

    fn index(&self, t: f64) -> usize {
        if self.width.is_nan() {
            0
        } else {
            // Truncation: a bucket is [start + k w, start + (k + 1) w).
            ((t - self.start) / self.width) as usize
        }
    }

    fn merge(&mut self) {
        let s = self.series;
        let count = self.buckets.len() / s;
        let mut merged = Vec::with_capacity(self.buckets.len() / 2 + s);
        for pair in 0..count.div_ceil(2) {
            for k in 0..s {
                let a = self.buckets[2 * pair * s + k];
                let b = self
                    .buckets
                    .get((2 * pair + 1) * s + k)
                    .copied()
                    .unwrap_or(a);
                merged.push(if b[2].is_nan() {
                    a
                } else if a[2].is_nan() {
                    b
                } else {
                    [a[0].min(b[0]), a[1].max(b[1]), a[2], b[3]]
                });
            }
        }
        self.buckets = merged;
        self.width *= 2.0;
    }

    fn columns(&self) -> usize {
        self.buckets.len() / self.series.max(1)
    }

    /// The time at the middle of bucket `k`, clamped to the samples' span.
    fn time(&self, k: usize) -> f64 {
        if self.width.is_nan() {
            return self.start;
        }
        (self.start + (k as f64 + 0.5) * self.width).min(self.end)
    }

    /// The range of series `k` over every bucket.
    pub fn range(&self, k: usize) -> (f64, f64) {
        (0..self.columns())
            .map(|c| self.buckets[c * self.series + k])
            .filter(|b| b[0] <= b[1])
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), b| {
                (lo.min(b[0]), hi.max(b[1]))
            })
    }
}

/// One line of a panel: a series of the envelope.
pub struct Line {
    pub label: String,
    pub color: &'static str,
    pub series: usize,
    pub bold: bool,
}

/// One plot: a title (with the unit) and its lines.
pub struct Panel {
    pub title: String,
    pub lines: Vec<Line>,
}

/// A figure: a title, a legend (label, color), and rows of panels sharing the time axis.
pub struct Figure<'a> {
    pub title: String,
    pub legend: Vec<(String, &'static str)>,
    pub rows: Vec<Vec<Panel>>,
    /// The width of each column of panels, px.
    pub widths: Vec<f64>,
    pub envelope: &'a Envelope,
}

const ROW: f64 = 110.0;
const TOP: f64 = 58.0;
const LEFT: f64 = 64.0;
const GAP: f64 = 76.0;

/// Writes `figure` as an SVG document.
///
/// # Errors
/// Writing to `out`.
pub fn write_svg(out: &mut impl Write, figure: &Figure<'_>) -> io::Result<()> {
    let width = LEFT + figure.widths.iter().map(|w| w + GAP).sum::<f64>();
    let height = TOP + ROW * figure.rows.len() as f64 + 30.0;
    writeln!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}\" height=\"{height}\" \
         viewBox=\"0 0 {width} {height}\" font-family=\"sans-serif\" font-size=\"11\">"
    )?;
    writeln!(
        out,
        "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n\
         <text x=\"{LEFT}\" y=\"20\" font-size=\"15\" font-weight=\"bold\">{}</text>",
        escape(&figure.title)
    )?;
    let mut x = LEFT;
    for (label, color) in &figure.legend {
        writeln!(
            out,
            "<rect x=\"{x}\" y=\"31\" width=\"14\" height=\"4\" fill=\"{color}\"/>\
             <text x=\"{}\" y=\"37\">{}</text>",
            x + 18.0,
            escape(label)
        )?;
        x += 30.0 + 7.0 * label.chars().count() as f64;
    }
    let last = figure.rows.len().saturating_sub(1);
    for (r, row) in figure.rows.iter().enumerate() {
        let mut x = LEFT;
        for (panel, &w) in row.iter().zip(&figure.widths) {
            let area = Area {
                x,
                y: TOP + ROW * r as f64,
                w,
                h: ROW - 34.0,
            };
            draw_panel(out, panel, figure.envelope, &area, r == last)?;
            x += w + GAP;
        }
    }
    writeln!(out, "</svg>")
}

struct Area {
    x: f64,
    y: f64,
    w: f64,
    h: f64,
}

fn draw_panel(
    out: &mut impl Write,
    panel: &Panel,
    env: &Envelope,
    area: &Area,
    time_axis: bool,
) -> io::Result<()> {
    let (lo, hi) = panel
        .lines
        .iter()
        .map(|l| env.range(l.series))
        .fold((0.0f64, 0.0f64), |(a, b), (lo, hi)| (a.min(lo), b.max(hi)));
    let span = if hi > lo { hi - lo } else { 1.0 };
    let (lo, hi) = (lo - 0.05 * span, hi + 0.05 * span);
    let (t0, t1) = (env.start, env.end);
    let duration = if t1 > t0 { t1 - t0 } else { 1.0 };
    let px = |t: f64| area.x + (t - t0) / duration * area.w;
    let py = |v: f64| area.y + (hi - v) / (hi - lo) * area.h;
    let Area { x, y, w, h } = *area;
    writeln!(
        out,
        "<text x=\"{x}\" y=\"{}\" font-weight=\"bold\">{}</text>\n\
         <rect x=\"{x}\" y=\"{y}\" width=\"{w}\" height=\"{h}\" fill=\"none\" stroke=\"#999\"/>\n\
         <line x1=\"{x}\" x2=\"{}\" y1=\"{z:.1}\" y2=\"{z:.1}\" stroke=\"#bbb\" stroke-dasharray=\"3,3\"/>",
        y - 4.0,
        escape(&panel.title),
        x + w,
        z = py(0.0)
    )?;
    for v in [hi - 0.05 * span, lo + 0.05 * span] {
        writeln!(
            out,
            "<text x=\"{}\" y=\"{:.1}\" text-anchor=\"end\">{}</text>",
            x - 4.0,
            py(v) + 4.0,
            number(v)
        )?;
    }
    if time_axis {
        for t in [t0, 0.5 * (t0 + t1), t1] {
            writeln!(
                out,
                "<text x=\"{:.1}\" y=\"{}\" text-anchor=\"middle\">{} s</text>",
                px(t),
                y + h + 14.0,
                short(&number(t))
            )?;
        }
    }
    for line in &panel.lines {
        let mut points = String::new();
        for c in 0..env.columns() {
            let [min, max, first, last] = env.buckets[c * env.series + line.series];
            if min > max {
                continue;
            }
            let x = px(env.time(c));
            // The extremes in the order the series passes them, so a monotonic stretch draws
            // no zigzag; points of a column less than half a pixel apart are one.
            let extremes = if first <= last {
                [min, max]
            } else {
                [max, min]
            };
            let mut previous = f64::NAN;
            for v in [first, extremes[0], extremes[1], last] {
                let y = py(v);
                if (y - previous).abs() >= 0.5 || previous.is_nan() {
                    let _ = write!(points, "{x:.1},{y:.1} ");
                    previous = y;
                }
            }
        }
        writeln!(
            out,
            "<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" points=\"{}\"><title>{}</title></polyline>",
            line.color,
            if line.bold { 1.8 } else { 1.2 },
            points.trim_end(),
            escape(&line.label)
        )?;
    }
    Ok(())
}

/// `0.7500` as `0.75`.
fn short(number: &str) -> &str {
    if number.contains('.') && !number.contains('e') {
        number.trim_end_matches('0').trim_end_matches('.')
    } else {
        number
    }
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_series_keeps_its_extremes_in_few_buckets() {
        let mut env = Envelope::new(2);
        let n = 100_000;
        for k in 0..n {
            let t = f64::from(k) * 1e-3;
            // A spike at one sample only.
            let spike = if k == 77_777 { 50.0 } else { 0.0 };
            env.push(t, &[t.sin() + spike, -t]);
        }
        assert!(env.columns() <= COLUMNS && env.columns() > COLUMNS / 2);
        let (lo, hi) = env.range(0);
        assert!((hi - (77.777f64.sin() + 50.0)).abs() < 1e-12 && (lo + 1.0).abs() < 1e-6);
        assert_eq!(env.range(1), (-99.999, 0.0));
        let mut svg = Vec::new();
        let figure = Figure {
            title: "t".into(),
            legend: vec![],
            rows: vec![vec![Panel {
                title: "x".into(),
                lines: vec![Line {
                    label: "a".into(),
                    color: "red",
                    series: 0,
                    bold: false,
                }],
            }]],
            widths: vec![400.0],
            envelope: &env,
        };
        write_svg(&mut svg, &figure).unwrap();
        assert!(svg.len() < 30_000, "{}", svg.len());
    }

    #[test]
    fn numbers_are_short() {
        assert_eq!(number(123.456), "123.5");
        assert_eq!(number(-0.5), "-0.5000");
        assert_eq!(number(0.0), "0.000");
        assert_eq!(number(2.5e6), "2.50e6");
        assert_eq!(
            [short("0.7500"), short("1000"), short("0.000")],
            ["0.75", "1000", "0"]
        );
    }
}
