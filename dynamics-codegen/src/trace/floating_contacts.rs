//! The terms of the forward dynamics with 3-D point contacts at every frame of a tree on a
//! free-flying base, traced into the floating equations' graph so that the run time only picks
//! the feet in contact and solves their block (`FloatingContactTerms`). With `J` the frames'
//! linear rows in world axes (3 per frame, [`FloatingKinematicEquations::jacobians_world`]),
//! `γ` their classical `J̇ v` and `M = L D Lᵀ` factored from the tips
//! ([`super::ForwardEquations::factors`]):
//!
//! ```text
//! Y = L⁻¹ Jᵀ,   J M⁻¹ Jᵀ = Yᵀ D⁻¹ Y,   M⁻¹ Jᵀ = L⁻ᵀ D⁻¹ Y,   a₀ = M⁻¹ (τ − h),   J a₀ + γ
//! ```
//!
//! From the tips, a foot's column of `Y` is zero but on its own leg and the base's six, so an
//! entry of `J M⁻¹ Jᵀ` between two legs reads the base's six alone.

use super::expr::Expr;
use super::{Equations, FloatingKinematicEquations};
use crate::algo::Scalar as _;
use crate::symbolic::NodeId;
use std::cell::RefCell;

/// The contact terms of every frame at once, as node ids; `F` frames, `NV` coordinates.
#[derive(Clone, Debug, Default)]
pub struct FloatingContactEquations {
    /// `[a₀; J a₀ + γ]`: `a₀ = M⁻¹ (τ − h)` (NV), then each frame's origin's acceleration in
    /// world axes at `a₀` (3F).
    pub free: Vec<NodeId>,
    /// Row `3f + i`, axis i of frame f: `(M⁻¹ J_rᵀ)ᵀ` (NV), then row r of `J M⁻¹ Jᵀ` (3F);
    /// 3F × (NV + 3F).
    pub rows: Vec<Vec<NodeId>>,
}

impl Equations {
    /// Traces the contact terms of the frames of `kinematics` (traced by
    /// [`Equations::floating_kinematics`] into this graph).
    #[must_use]
    pub fn floating_contacts(
        &mut self,
        kinematics: &FloatingKinematicEquations,
    ) -> FloatingContactEquations {
        let graph = RefCell::new(std::mem::take(&mut self.graph));
        let expr = |id: NodeId| Expr::new(&graph, id);
        let factors = self.forward.factors_in(&graph);
        let jacobian: Vec<Vec<Expr>> = kinematics
            .jacobians_world
            .iter()
            .flat_map(|j| &j[..3])
            .map(|row| row.iter().map(|&id| expr(id)).collect())
            .collect();
        let drift = kinematics.biases_world.iter().flat_map(|b| &b[..3]);
        let free: Vec<Expr> = self.forward.qdd.iter().map(|&id| expr(id)).collect();
        let y: Vec<Vec<Expr>> = jacobian
            .iter()
            .map(|row| factors.forward_substitution(row))
            .collect();
        let z: Vec<Vec<Expr>> = y
            .iter()
            .map(|y| {
                y.iter()
                    .zip(&factors.inverse_pivots)
                    .map(|(&y, &r)| y * r)
                    .collect()
            })
            .collect();
        // The lower triangle, mirrored: the same nodes either side.
        let mut delassus: Vec<Vec<Option<Expr>>> = vec![vec![None; y.len()]; y.len()];
        for r in 0..y.len() {
            for s in 0..=r {
                let zero = free[0].zero();
                let x = y[r]
                    .iter()
                    .zip(&z[s])
                    .fold(zero, |acc, (&a, &b)| acc + a * b);
                delassus[r][s] = Some(x);
                delassus[s][r] = Some(x);
            }
        }
        let accelerations = jacobian.iter().zip(drift).map(|(row, &g)| {
            let zero = free[0].zero();
            row.iter()
                .zip(&free)
                .fold(zero, |acc, (&j, &a)| acc + j * a)
                + expr(g)
        });
        let out = FloatingContactEquations {
            free: free
                .iter()
                .copied()
                .chain(accelerations)
                .map(Expr::id)
                .collect(),
            rows: z
                .iter()
                .zip(&delassus)
                .map(|(z, row)| {
                    let column = factors.back_substitution(z);
                    let row = row.iter().map(|x| x.expect("the triangle is mirrored"));
                    column.into_iter().chain(row).map(Expr::id).collect()
                })
                .collect(),
        };
        drop(factors);
        self.graph = graph.into_inner();
        out
    }
}
