//! The joints of `dh = [...]`: one per D-H row, with its `link(...)`. In row i, `q` (or `qi`)
//! in the θ cell makes joint i revolute with `θ = q + offset`, in the d cell prismatic with
//! `d = q + offset`. A tree's row adds its antecedent (0 the base, else an earlier row's
//! number), γ and b: `[θ, d, a, α, antecedent, γ, b]` (modified convention only).

use super::entry::DhRowAttr;
use super::parse::Attrs;
use super::reader::{check_arithmetic, check_joint_count, JointList, Reader};
use super::tree::{self, ParentAttr};
use crate::front::angle::unitless_angle;
use crate::front::errors::Errors;
use crate::front::fields::check_names;
use crate::front::value::Spanned;
use crate::model::{snap_angle, Branch, Convention, Joint, JointKind, Value};
use proc_macro2::Span;
use std::collections::BTreeMap;

/// What the count errors call the D-H table's rows.
pub(super) fn counted(n: usize) -> String {
    format!("the D-H table has {n} rows")
}

/// The joints of the D-H table `rows` (with the span of its brackets); `span` is the derive's
/// name.
pub(super) fn joints(
    reader: &mut Reader,
    (rows, table_span): &(Vec<DhRowAttr>, Span),
    attrs: &Attrs,
    span: Span,
) -> Vec<Joint> {
    let spans: Vec<Span> = rows.iter().map(|(at, _, _)| *at).collect();
    let list = JointList {
        spans: &spans,
        span: *table_span,
        empty: "the D-H table is empty: give one row `[θ, d, a, α]` per joint",
        counted,
    };
    check_joint_count(&list, &attrs.links, reader.errors);
    let mut joints: Vec<Joint> = rows
        .iter()
        .enumerate()
        .map(|(i, row)| {
            let mut joint = joint(reader, i + 1, row, attrs, span);
            let tree = row.2.as_ref();
            joint.branch = tree.and_then(|tree| branch(reader, (i + 1, rows.len()), tree, attrs));
            joint
        })
        .collect();
    tree::settle(&mut joints);
    joints
}

/// Row `n`'s antecedent column `[antecedent, γ, b]` (modified convention only), or `None`
/// with an error on the cell at fault.
fn branch(
    reader: &mut Reader,
    (n, count): (usize, usize),
    tree: &[Spanned; 3],
    attrs: &Attrs,
) -> Option<Branch> {
    let [antecedent, gamma, b] = tree;
    if attrs.convention.map(|c| c.0) != Some(Convention::Modified) {
        let message = "a standard D-H table has no antecedent column: trees are given in the \
                       modified convention (Khalil-Kleinfinger); add `convention = modified` \
                       and write the rows in it";
        reader.errors.push(antecedent.span, message);
        return None;
    }
    let number = antecedent
        .value
        .exact()
        .filter(|k| k.is_exact() && !k.is_negative())
        .and_then(crate::symbolic::Number::as_integer)
        .and_then(|k| u64::try_from(k).ok());
    let Some(number) = number else {
        let message = format!("row {n}: the antecedent is an earlier row's number (1 for the first) or 0 for the base, not `{}`", antecedent.value);
        reader.errors.push(antecedent.span, message);
        return None;
    };
    let parent = ParentAttr::Number(number, antecedent.span);
    let parent = match tree::antecedent(n, &parent, count, &BTreeMap::new(), true) {
        Ok(parent) => parent,
        Err(message) => {
            reader.errors.push(antecedent.span, message);
            return None;
        }
    };
    if let Some((term, message)) = unitless_angle(&gamma.unitless, false) {
        reader.errors.push_range(term.span, term.end, message);
    }
    Some(Branch {
        parent,
        gamma: snap_angle(&reader.value(Some(gamma))),
        b: reader.value(Some(b)),
    })
}

/// Joint `n` (1-based) from its D-H row and its `link(...)`.
fn joint(reader: &mut Reader, n: usize, row: &DhRowAttr, attrs: &Attrs, span: Span) -> Joint {
    let (row_span, [theta, d, a, alpha], _) = row;
    for cell in [theta, d] {
        check_names(cell, reader.fields, reader.errors);
        check_arithmetic(cell, reader.errors);
        check_joint_index(&cell.value, n, cell.span, reader.errors);
    }
    for angle in [theta, alpha] {
        if let Some((term, message)) = unitless_angle(&angle.unitless, false) {
            reader.errors.push_range(term.span, term.end, message);
        }
    }
    let kind = kind(reader.errors, n, *row_span, theta, d);
    // Angles near quarter turns (1.5708) are those quarter turns, as in frames and URDFs.
    let theta = snap_angle(&offset(reader.errors, theta));
    let d = offset(reader.errors, d);
    let a = reader.value(Some(a));
    let alpha = snap_angle(&reader.value(Some(alpha)));
    let link = reader.link((n, *row_span), &attrs.links, attrs.check_inertia, span);
    Joint::dh(kind, [theta, d, a, alpha], link)
}

/// Revolute if `q` is in the θ cell, prismatic if in the d cell.
fn kind(errors: &mut Errors, n: usize, row_span: Span, theta: &Spanned, d: &Spanned) -> JointKind {
    match (theta.value.joint_occurrences(), d.value.joint_occurrences()) {
        (1, 0) => JointKind::Revolute,
        (0, 1) => JointKind::Prismatic,
        (0, 0) => {
            errors.push(row_span, format!("row {n} has no joint variable: write `q` in the θ column (revolute) or the d column (prismatic)"));
            JointKind::Revolute
        }
        _ => {
            errors.push(
                row_span,
                format!("row {n} must have the joint variable `q` once, in the θ or the d column"),
            );
            JointKind::Revolute
        }
    }
}

/// The offset added to `q` in a D-H cell, or the cell's value where it has no `q`.
fn offset(errors: &mut Errors, cell: &Spanned) -> Value {
    if cell.value.joint_occurrences() == 0 {
        return cell.value.clone();
    }
    cell.value.joint_offset().unwrap_or_else(|| {
        errors.push(
            cell.span,
            "write the joint variable as `q`, `q + offset` or `q - offset`",
        );
        Value::zero()
    })
}

/// An error for `qk` in row `row` with `k ≠ row`.
fn check_joint_index(v: &Value, row: usize, span: Span, errors: &mut Errors) {
    match v {
        Value::Joint(Some(k)) if *k != row => errors.push(
            span,
            format!("`q{k}` in row {row}: the joint variable of row {row} is `q` or `q{row}`"),
        ),
        Value::Neg(a) => check_joint_index(a, row, span, errors),
        Value::Add(a, b) | Value::Sub(a, b) | Value::Mul(a, b) | Value::Div(a, b) => {
            check_joint_index(a, row, span, errors);
            check_joint_index(b, row, span, errors);
        }
        _ => {}
    }
}
