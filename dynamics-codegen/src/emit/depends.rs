//! What each node depends on, and from that the split of the code between the shared
//! configuration and motion functions and the methods: a node in the parameters and `q` alone
//! is computed once in the configuration, a term in `q̇` that several methods need once in the
//! motion, the rest in each method.

use super::parts::Output;
use super::plan::operands;
use crate::symbolic::{Node, NodeId, Var};
use crate::trace::Equations;

/// The latest input a node depends on, in the order the inputs become known.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(super) enum Depends {
    /// The parameters and constants only.
    Constants,
    /// The joint positions `q` too (their sines and cosines included).
    Configuration,
    /// The joint velocities `q̇` too.
    Velocity,
    /// The joint accelerations `q̈` too.
    Acceleration,
}

/// What each node of `eq`'s graph depends on, by index.
pub(super) fn dependencies(eq: &Equations) -> Vec<Depends> {
    let mut depends = vec![Depends::Constants; eq.graph.len()];
    for (id, node) in eq.graph.nodes() {
        depends[id.index()] = match node {
            Node::Var(Var::Param(_) | Var::Inertial(_) | Var::Exact(_)) | Node::Const(_) => {
                Depends::Constants
            }
            Node::Var(Var::Q(_)) => Depends::Configuration,
            Node::Var(Var::Qd(_)) => Depends::Velocity,
            // A wrench or τ is read by its method alone, as late as q̈.
            Node::Var(Var::Qdd(_) | Var::Wrench(_) | Var::TipWrench(_) | Var::Tau(_)) => {
                Depends::Acceleration
            }
            // A sine or cosine of `q_i`, or an operation: as late as its operands (a joint
            // angle's offset), `q` at least for the former.
            _ => {
                let latest = operands(eq, id).iter().map(|c| depends[c.index()]).max();
                let trig = matches!(node, Node::Var(Var::SinQ(_) | Var::CosQ(_)));
                match latest {
                    Some(d) if trig => d.max(Depends::Configuration),
                    Some(d) => d,
                    None => Depends::Configuration,
                }
            }
        };
    }
    depends
}

/// The nodes without `q̇` and `q̈` that the code of `outputs` reads: outputs in the
/// configuration and the configuration's operands of the nodes in `q̇` or `q̈`, except zero,
/// one and `q_i`, which are written in place.
pub(super) fn boundary(eq: &Equations, depends: &[Depends], outputs: &[NodeId]) -> Vec<NodeId> {
    frontier(eq, outputs, |id| depends[id.index()] >= Depends::Velocity)
}

/// The nodes the code of `outputs` reads when it computes its terms in `q` itself rather than
/// reading them from the configuration ([`super::program`]'s mass matrix of a tree): the nodes
/// in the parameters and constants alone and every node other than a sum, negation or product
/// (the sines and cosines, which the configuration computes in its vector kernels), except
/// zero, one and `q_i`, which are written in place.
pub(super) fn trig_and_constants(
    eq: &Equations,
    depends: &[Depends],
    outputs: &[NodeId],
) -> Vec<NodeId> {
    frontier(eq, outputs, |id| {
        let arithmetic = matches!(
            eq.graph.node(id),
            Node::Add(..) | Node::Neg(_) | Node::Mul(..)
        );
        arithmetic && depends[id.index()] >= Depends::Configuration
    })
}

/// Where a walk down from `outputs` stops: the nodes it does not `descend` into, except zero,
/// one and `q_i`, which the code writes in place.
fn frontier(eq: &Equations, outputs: &[NodeId], descend: impl Fn(NodeId) -> bool) -> Vec<NodeId> {
    let mut seen = vec![false; eq.graph.len()];
    let mut found = Vec::new();
    let mut stack = outputs.to_vec();
    while let Some(id) = stack.pop() {
        if std::mem::replace(&mut seen[id.index()], true) {
            continue;
        }
        let in_place = match eq.graph.node(id) {
            Node::Var(Var::Q(_)) => true,
            Node::Const(c) => c.is_zero() || c.is_one(),
            _ => false,
        };
        if descend(id) {
            stack.extend(operands(eq, id));
        } else if !in_place {
            found.push(id);
        }
    }
    found
}

/// The terms in `q̇` (without `q̈`) that the code of two outputs or more computes, as the
/// nodes the rest of each output's code reads of them, in the arena's order.
pub(super) fn shared_motion(
    eq: &Equations,
    depends: &[Depends],
    outputs: &[&Output],
) -> Vec<NodeId> {
    let n = eq.graph.len();
    // Per node, how many outputs' code computes it.
    let mut users = vec![0u32; n];
    let walk = |outs: Vec<NodeId>, shared: Option<&[u32]>, found: &mut Vec<bool>| {
        let mut seen = vec![false; n];
        let mut stack = outs;
        while let Some(id) = stack.pop() {
            let i = id.index();
            if depends[i] < Depends::Velocity
                || matches!(eq.graph.node(id), Node::Var(_) | Node::Const(_))
                || std::mem::replace(&mut seen[i], true)
            {
                continue;
            }
            // A product stays with its user, which may fuse it into a multiply-add.
            let product = matches!(eq.graph.node(id), Node::Mul(..));
            if !product && shared.is_some_and(|u| u[i] >= 2 && depends[i] == Depends::Velocity) {
                found[i] = true;
                continue;
            }
            stack.extend(operands(eq, id));
        }
        seen
    };
    let mut unused = vec![false; n];
    for o in outputs {
        for (i, seen) in walk(o.shape.outputs(), None, &mut unused)
            .into_iter()
            .enumerate()
        {
            users[i] += u32::from(seen);
        }
    }
    let mut found = vec![false; n];
    for o in outputs {
        walk(o.shape.outputs(), Some(&users), &mut found);
    }
    eq.graph
        .nodes()
        .filter(|(id, _)| found[id.index()])
        .map(|(id, _)| id)
        .collect()
}
