//! The C functions of a robot: one per method of the families its equations hold and per
//! precision, with their signatures (read from the method table and the result's shape) and
//! their text.

use super::body::{Reads, Writer};
use super::expr::Precision;
use crate::method::{Argument, Method};
use crate::trace::{Equations, Shape, Solved};

/// What a C function returns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Returns {
    /// Nothing: the result goes into the output arrays.
    Nothing,
    /// The result, a scalar (the energies).
    Value,
    /// 0 where every pivot of the LDLᵀ of M is positive, 1 where one is not (the outputs are
    /// written either way).
    Status,
}

/// An array a function writes its result into: its name and its dimensions.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Array {
    /// The argument's name: the method's element prefix (`m`, `tau`, `g`).
    pub name: String,
    /// Its dimensions, outermost first: `[6]`, `[6][6]`, `[2][6][6]`.
    pub dims: Vec<usize>,
}

/// One C function of the header.
#[derive(Clone, Debug)]
pub struct Function {
    /// The method it computes.
    pub method: Method,
    /// Its floating-point type.
    pub precision: Precision,
    /// Its name: the robot's prefix, the method's name, `_f32` for `float`.
    pub name: String,
    /// The number of the robot's parameters, its first argument (`const double params[K]`)
    /// where not zero.
    pub parameters: usize,
    /// Its inputs after the parameters, each an array of this length.
    pub arguments: Vec<(Argument, usize)>,
    /// The arrays the result goes into, after the inputs.
    pub outputs: Vec<Array>,
    /// What it returns.
    pub returns: Returns,
}

/// The functions of `eq`, named `{prefix}_{method}`: every method of the families the
/// equations hold (`Equations::families`), a method with a default body of zeros (friction)
/// included, so that a C caller finds the same functions for every robot; in the table's
/// order, `double` then `float`.
#[must_use]
pub fn functions(eq: &Equations, prefix: &str) -> Vec<Function> {
    let mut functions = Vec::new();
    for &method in Method::ALL {
        if !eq.families.has(method) {
            continue;
        }
        let shape = method.shape(eq);
        let Some((outputs, returns)) = outputs(method, &shape) else {
            continue;
        };
        let arguments = method
            .arguments()
            .iter()
            .map(|&a| (a, argument_length(eq, a)))
            .collect::<Vec<_>>();
        for precision in Precision::ALL {
            functions.push(Function {
                method,
                precision,
                name: format!("{prefix}_{}{}", method.name(), precision.suffix()),
                parameters: eq.fields.len(),
                arguments: arguments.clone(),
                outputs: outputs.clone(),
                returns,
            });
        }
    }
    functions
}

/// The length of argument `a`'s array: a wrench's 6, the tips' wrenches one after the other
/// (6 per tip), the joints' `n`.
fn argument_length(eq: &Equations, a: Argument) -> usize {
    match a {
        Argument::Wrench => 6,
        Argument::Wrenches => 6 * eq.tips.as_ref().map_or(0, |t| t.names.len()),
        Argument::Q | Argument::Qd | Argument::Qdd | Argument::Tau => eq.dof,
    }
}

/// The arrays of a result of `shape` and what the function returns; `None` for a result
/// with no elements (C has no arrays of length zero).
fn outputs(method: Method, shape: &Shape) -> Option<(Vec<Array>, Returns)> {
    // The result's array is named as its elements are (`m` for `m1_2`), unless an argument
    // has that name.
    let name = if method
        .arguments()
        .iter()
        .any(|a| a.name() == method.prefix())
    {
        "out".to_owned()
    } else {
        method.prefix().to_owned()
    };
    let dims_of = |m: &[Vec<crate::symbolic::NodeId>]| -> Vec<usize> {
        let rows = m.len();
        let cols = m.first().map_or(0, Vec::len);
        vec![rows, cols]
    };
    let (parts, returns) = match *shape {
        Shape::Scalar(_) => (vec![], Returns::Value),
        Shape::Vector(v) => (vec![(name, vec![v.len()])], Returns::Nothing),
        Shape::Matrix(m) => (vec![(name, dims_of(m))], Returns::Nothing),
        Shape::Stack(s)
        | Shape::Lanes {
            stack: s,
            solved: None,
            ..
        } => {
            let mut dims = vec![s.len()];
            dims.extend(s.first().map_or(vec![0, 0], |m| dims_of(m)));
            (vec![(name, dims)], Returns::Nothing)
        }
        Shape::SolvedVector { vector, .. } => (vec![(name, vec![vector.len()])], Returns::Status),
        Shape::SolvedMatrix { matrix, .. } => (vec![(name, dims_of(matrix))], Returns::Status),
        Shape::SolvedStack { vector, stack, .. }
        | Shape::Lanes {
            stack,
            solved: Some(Solved { vector, .. }),
            ..
        } => {
            let mut dims = vec![stack.len()];
            dims.extend(stack.first().map_or(vec![0, 0], |m| dims_of(m)));
            // The vector of a solved stack is the solution itself (`q̈` beside its
            // derivatives).
            (
                vec![("value".to_owned(), vec![vector.len()]), (name, dims)],
                Returns::Status,
            )
        }
    };
    let arrays: Vec<Array> = parts
        .into_iter()
        .map(|(name, dims)| Array { name, dims })
        .collect();
    if arrays.iter().any(|a| a.dims.contains(&0)) {
        return None;
    }
    Some((arrays, returns))
}

impl Function {
    /// Its declaration: `static inline void puma560_gravity_torques(const double q[6], double
    /// g[6])`.
    #[must_use]
    pub fn signature(&self) -> String {
        let ty = self.precision.c_type();
        let mut arguments = Vec::new();
        if self.parameters > 0 {
            arguments.push(format!("const {ty} params[{}]", self.parameters));
        }
        for &(a, len) in &self.arguments {
            arguments.push(format!("const {ty} {}[{len}]", a.name()));
        }
        for array in &self.outputs {
            let dims: String = array.dims.iter().map(|d| format!("[{d}]")).collect();
            arguments.push(format!("{ty} {}{dims}", array.name));
        }
        let returns = match self.returns {
            Returns::Nothing => "void",
            Returns::Value => ty,
            Returns::Status => "int",
        };
        let arguments = if arguments.is_empty() {
            "void".to_owned()
        } else {
            arguments.join(", ")
        };
        format!("static inline {returns} {}({arguments})", self.name)
    }

    /// Its definition, with the method table's summary as its comment; `sign` names the header's sign
    /// function of the function's precision.
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub fn definition(&self, eq: &Equations, sign: &str) -> String {
        let mut text = format!("{}{} {{\n", comment(eq, self.method), self.signature());
        if self.plans_lanes(eq) {
            // gcc's vectors are 256 bits wide by default even where the target has AVX-512.
            text.insert_str(
                text.find("static inline").unwrap_or(0),
                "DYNAMICS_LANES_WIDE\n",
            );
            text.push_str("#if DYNAMICS_TANGENT_LANES\n");
            self.write_body(eq, sign, true, &mut text);
            text.push_str("#else\n");
            self.write_body(eq, sign, false, &mut text);
            text.push_str("#endif\n");
        } else {
            self.write_body(eq, sign, false, &mut text);
        }
        text.push_str("}\n");
        text
    }

    /// Whether its tangents may be computed in lanes (`DYNAMICS_TANGENT_LANES`): the inverse
    /// dynamics' derivatives where the trace planned them.
    pub(super) fn plans_lanes(&self, eq: &Equations) -> bool {
        match self.method.shape(eq) {
            Shape::Lanes { lanes, .. } => lanes.iter().any(Option::is_some),
            _ => false,
        }
    }

    /// The body's lines, indented, onto `text`: the inputs it does not read cast to `void`,
    /// then its statements (with `lanes`, its tangents in lanes).
    fn write_body(&self, eq: &Equations, sign: &str, lanes: bool, text: &mut String) {
        let arrays: Vec<String> = self.outputs.iter().map(|a| a.name.clone()).collect();
        let body =
            Writer::new(eq, self.precision, sign.to_owned()).body(self.method, &arrays, lanes);
        for unread in self.unread(body.reads) {
            text.push_str(&format!("    (void){unread};\n"));
        }
        for line in &body.lines {
            text.push_str("    ");
            text.push_str(line);
            text.push('\n');
        }
    }

    /// The inputs the body does not read (`qd` of a robot without friction's
    /// `friction_torques`), which a compiler warns of unless cast to `void`.
    fn unread(&self, reads: Reads) -> Vec<&'static str> {
        let mut unread = Vec::new();
        if self.parameters > 0 && !reads.params {
            unread.push("params");
        }
        for &(a, _) in &self.arguments {
            let read = match a {
                Argument::Q => reads.q,
                Argument::Qd => reads.qd,
                Argument::Qdd => reads.qdd,
                Argument::Wrench => reads.wrench,
                Argument::Wrenches => reads.wrenches,
                Argument::Tau => reads.tau,
            };
            if !read {
                unread.push(a.name());
            }
        }
        unread
    }
}

/// The comment above a function of `method`: its name and summary; for a simplified method,
/// each output's proven bound and the envelope too, the rustdoc of the Rust method.
fn comment(eq: &Equations, method: Method) -> String {
    let Some(doc) = crate::emit::simplified_doc(eq, method) else {
        return format!(
            "/* {}: {} */\n",
            method.name(),
            comment_safe(method.summary())
        );
    };
    let mut lines = doc.lines().filter(|l| !l.starts_with("```"));
    let summary = comment_safe(lines.next().unwrap_or_default().trim());
    let mut text = format!("/* {}: {summary}", method.name());
    for line in lines {
        let line = comment_safe(line);
        if line.trim().is_empty() {
            text.push_str("\n *");
        } else {
            text.push_str(&format!("\n * {}", line.trim()));
        }
    }
    text.push_str("\n */\n");
    text
}

/// `text` for a line of a C comment: in printable ASCII, which every C toolchain reads (the
/// method table's `q̇`, `τ`, `ᵀ` spelled `qd`, `tau`, `^T`; a control character, such as the
/// NUL compilers refuse or a line break of a robot's name, and any other character `?`), and
/// without the `*/` that would end the comment early.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn comment_safe(text: &str) -> String {
    let mut ascii = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            c if c.is_ascii() && !c.is_ascii_control() => ascii.push(c),
            // Combining dots: `q̇`, `q̈`, `J̇`.
            '\u{307}' => ascii.push('d'),
            '\u{308}' => ascii.push_str("dd"),
            '∂' => ascii.push('d'),
            'τ' => ascii.push_str("tau"),
            'π' => ascii.push_str("pi"),
            'Σ' => ascii.push_str("sum"),
            '−' => ascii.push('-'),
            '≤' => ascii.push_str("<="),
            '·' => ascii.push('*'),
            'ᵀ' => ascii.push_str("^T"),
            'ᴴ' => ascii.push('H'),
            '⁻' => ascii.push_str("^-"),
            '¹' => ascii.push('1'),
            '⋯' | '…' => ascii.push_str("..."),
            _ => ascii.push('?'),
        }
    }
    ascii.replace("*/", "* /")
}

#[cfg(test)]
pub(super) mod tests {
    use super::{functions, Precision};
    use crate::method::{Family, FamilySet, Method};

    /// A 2R arm in a description file, with friction (a method with a default body).
    const ARM: &str = r#"
        name = "arm"
        gravity = [0, -9.81, 0]
        [[joints]]
        type = "revolute"
        a = 0.5
        mass = 2
        com = [-0.25, 0, 0]
        inertia = [0, 0.04, 0.04, 0, 0, 0]
        friction_viscous = 0.1
        [[joints]]
        type = "revolute"
        a = 0.4
        mass = 1
        com = [-0.2, 0, 0]
        inertia = [0, 0.01, 0.01, 0, 0, 0]
    "#;

    /// The equations of [`ARM`] with every family: every method of the table (the C back
    /// end's tests).
    pub(in crate::emit_c) fn arm_with_every_family() -> crate::trace::Equations {
        let robot = crate::front::from_toml(ARM, "arm").expect("a valid robot");
        let mut eq = crate::trace::derive(&robot);
        let every = Family::ALL
            .iter()
            .copied()
            .fold(FamilySet::default(), FamilySet::with);
        eq.add_families(&robot, every);
        // The simplified family needs its request, which no family set carries.
        let joint = crate::front::default_envelope(crate::model::JointKind::Revolute);
        let request = crate::model::Simplification {
            tolerance: vec![0.01; 2],
            envelope: crate::model::Envelope {
                joints: vec![joint; 2],
            },
        };
        crate::simplify::add(&mut eq, &request).expect("simplifies");
        eq
    }

    /// With every family asked for, each method of the table has its two functions, in the
    /// table's order: a new row gets its C function with no change to the C back end.
    #[test]
    fn every_method_of_the_table_has_a_function_in_each_precision() {
        let eq = arm_with_every_family();
        let names: Vec<String> = functions(&eq, "arm").into_iter().map(|f| f.name).collect();
        let expected: Vec<String> = Method::ALL
            .iter()
            .flat_map(|m| Precision::ALL.map(|p| format!("arm_{}{}", m.name(), p.suffix())))
            .collect();
        assert_eq!(names, expected);
    }

    /// The header's promise that outputs may alias inputs: in every function, no line after
    /// the first store into an output array reads an input array, the regressors' stores as
    /// their values are computed included.
    #[test]
    fn every_input_is_read_before_the_first_store() {
        let eq = arm_with_every_family();
        for f in functions(&eq, "arm") {
            let inputs: Vec<String> = f
                .arguments
                .iter()
                .map(|(a, _)| a.name())
                .chain((f.parameters > 0).then_some("params"))
                .map(|a| format!("{a}["))
                .collect();
            let text = f.definition(&eq, "arm_sign");
            let stores: Vec<String> = f.outputs.iter().map(|a| format!("{}[", a.name)).collect();
            let body = text.lines().skip_while(|l| !l.starts_with("static inline"));
            let mut stored = false;
            for line in body.skip(1) {
                let line = line.trim_start();
                // The derivatives' second body (their tangents column by column) reads anew.
                if line.starts_with("#else") {
                    stored = false;
                }
                let reads = |array: &str| {
                    line.match_indices(array).any(|(i, _)| {
                        i == 0 || !line[..i].ends_with(|c: char| c.is_alphanumeric() || c == '_')
                    })
                };
                if stored {
                    assert!(
                        !inputs.iter().any(|a| reads(a.as_str())),
                        "{}: `{line}` reads an input after a store",
                        f.name
                    );
                }
                stored |= stores.iter().any(|a| line.starts_with(a.as_str()));
            }
            assert!(stored || f.outputs.is_empty(), "{} stores nothing", f.name);
        }
    }

    /// The names a function binds cannot meet: an output array or element (`m`, `m1_2`) is
    /// never an argument (`q`, `tau`), a temporary (`t4`), a pivot (`d2`), a sine or cosine
    /// (`s2`, `c2`), a parameter (`p_...`) or the solved stack's `value`.
    #[test]
    fn comments_are_ascii() {
        let table = [
            ("C(q, q̇) q̇ + g(q).", "C(q, qd) qd + g(q)."),
            ("q̈ = M(q)⁻¹ (τ − f(q̇)).", "qdd = M(q)^-1 (tau - f(qd))."),
            (
                "T = ᴴJᵀ ᴴF, ∂τ/∂q, A1 ⋯ An, Σ_k",
                "T = HJ^T HF, dtau/dq, A1 ... An, sum_k",
            ),
            ("a */ b ✓", "a * / b ?"),
        ];
        for (text, ascii) in table {
            assert_eq!(super::comment_safe(text), ascii);
        }
        for &m in Method::ALL {
            let summary = super::comment_safe(m.summary());
            assert!(!summary.contains('?'), "{m:?}: {summary}");
        }
    }

    #[test]
    fn element_names_are_apart_from_every_other_local() {
        for &m in Method::ALL {
            let prefix = m.prefix();
            assert!(m.arguments().iter().all(|a| a.name() != prefix), "{m:?}");
            assert!(
                !["t", "d", "s", "c", "value", "params"].contains(&prefix),
                "{m:?}"
            );
            assert!(!prefix.starts_with("p_"), "{m:?}");
            // An element `tau3` would be the joint torque read by a method that takes `tau`.
            let takes_tau = m.arguments().contains(&crate::method::Argument::Tau);
            assert!(!(takes_tau && prefix == "tau"), "{m:?}");
        }
    }
}
