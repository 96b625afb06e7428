//! The base parameters printed as Khalil and Gautier write them: `ZZR1 = ZZ1 + YY2 + 0.18645 M2`,
//! one line each, then the standard parameters with no effect on the torques.

use super::number::decimal;
use super::print::Format;
use crate::symbolic::Number;
use crate::trace::base_parameters::{BaseParameter, BaseParameters, Parameter};

/// The base parameters of robot `name`, as text or LaTeX.
#[must_use]
pub fn render_base_parameters(name: &str, base: &BaseParameters, format: Format) -> String {
    let mut out = format!(
        "{name}: {} base parameters of {} standard ones, the combinations that the joint \
         torques determine (found exactly from the closed form)\n\
         Per link i, about its frame's origin and in its axes: M mass, MX MY MZ first moments \
         (m c), XX XY XZ YY YZ ZZ inertia; per joint: IA actuator inertia, FV FC FO viscous, \
         Coulomb, offset friction; R where others are grouped in\n",
        base.parameters.len(),
        base.standard,
    );
    for parameter in &base.parameters {
        out.push_str("  ");
        out.push_str(&line(parameter, format));
        out.push('\n');
    }
    let none: Vec<String> = base.no_effect.iter().map(|p| symbol(*p, format)).collect();
    if !none.is_empty() {
        out.push_str(&format!("No effect on the torques: {}\n", none.join(", ")));
    }
    out
}

/// `ZZR1 = ZZ1 + YY2 + 0.18645 M2`.
fn line(parameter: &BaseParameter, format: Format) -> String {
    let mut text = format!("{} =", named(&parameter.name, format));
    for (k, term) in parameter.terms.iter().enumerate() {
        let c = term.coefficient;
        let sign = if c.is_negative() { "-" } else { "+" };
        if k > 0 || c.is_negative() {
            text.push(' ');
            text.push_str(sign);
        }
        let magnitude = if c.is_negative() { -c } else { c };
        if magnitude != Number::ONE {
            text.push(' ');
            text.push_str(&decimal(magnitude));
        }
        text.push(' ');
        text.push_str(&symbol(term.parameter, format));
    }
    if format == Format::Latex {
        format!("${text}$")
    } else {
        text
    }
}

fn symbol(p: Parameter, format: Format) -> String {
    named(&p.name(), format)
}

/// A name such as `ZZR1` in the format: `\mathrm{ZZR}_{1}` in LaTeX.
fn named(name: &str, format: Format) -> String {
    match format {
        Format::Text => name.to_string(),
        Format::Latex => {
            let digits = name
                .find(|c: char| c.is_ascii_digit())
                .unwrap_or(name.len());
            format!("\\mathrm{{{}}}_{{{}}}", &name[..digits], &name[digits..])
        }
    }
}
