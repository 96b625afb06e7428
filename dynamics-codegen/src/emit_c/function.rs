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
/// (6 per tip), the joints' `n`; on a floating base `q`'s `n + 7` and the others' `n + 6`.
fn argument_length(eq: &Equations, a: Argument) -> usize {
    match a {
        Argument::Wrench => 6,
        Argument::Wrenches => 6 * eq.tips.as_ref().map_or(0, |t| t.names.len()),
        Argument::Q => eq.dof + super::q_shift(eq),
        Argument::Qd | Argument::Qdd | Argument::Tau => eq.dof,
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
