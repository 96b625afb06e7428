//! The joint variables a function reads, `let [qd1, _, qd3] = *qd_;`, and the sines and
//! cosines of the joint angles, computed once each, four joints side by side.

use super::emitter::Emitter;
use super::local;
use super::plan::Place;
use crate::symbolic::{Node, Var};
use proc_macro2::TokenStream;
use quote::quote;

impl Emitter<'_> {
    /// `let [qd1, _, qd3] = *qd_;`: the joint positions, velocities and accelerations the
    /// marked nodes read, named as the book numbers them, and the wrench's components
    /// (`let [_, _, fz, ..] = *wrench_;`) and torques (`let [tau1, tau2] = *tau_;`).
    pub(super) fn joint_variables(&self) -> Vec<TokenStream> {
        let n = self.eq.dof;
        let mut used = [
            vec![false; n],
            vec![false; n],
            vec![false; n],
            vec![false; 6],
            vec![false; n],
            vec![false; 6 * self.eq.tips.as_ref().map_or(0, |t| t.names.len())],
        ];
        for (id, node) in self.graph.leaves() {
            if !self.needed[id.index()] {
                continue;
            }
            match node {
                Node::Var(Var::Q(i)) => used[0][usize::from(i)] = true,
                Node::Var(Var::Qd(i)) => used[1][usize::from(i)] = true,
                Node::Var(Var::Qdd(i)) => used[2][usize::from(i)] = true,
                Node::Var(Var::Wrench(k)) => used[3][usize::from(k)] = true,
                Node::Var(Var::Tau(i)) => used[4][usize::from(i)] = true,
                Node::Var(Var::TipWrench(k)) => used[5][usize::from(k)] = true,
                _ => {}
            }
        }
        // Each array argument and the input its elements are.
        type Element = fn(u16) -> Var;
        let kinds: [(&str, Element); 5] = [
            ("q", Var::Q),
            ("qd", Var::Qd),
            ("qdd", Var::Qdd),
            ("wrench", Var::Wrench),
            ("tau", Var::Tau),
        ];
        let mut used = Vec::from(used);
        let wrenches = self.tip_wrenches(&used.pop().unwrap_or_default());
        kinds
            .iter()
            .zip(used)
            .filter(|(_, used)| used.contains(&true))
            .map(|(&(array, var), used)| {
                let array = local(&format!("{array}_"));
                let names = used.iter().enumerate().map(|(i, &u)| {
                    if u {
                        let v = self.variable_name(var(u16::try_from(i).unwrap_or(u16::MAX)));
                        quote!(#v)
                    } else {
                        quote!(_)
                    }
                });
                quote!(let [#(#names),*] = *#array;)
            })
            .chain(wrenches)
            .collect()
    }

    /// `let [[fx1, ..], [_, _, fz2, ..]] = *wrenches_;`: the components of the tips' wrenches
    /// read (`used[6 t + k]`), if any.
    fn tip_wrenches(&self, used: &[bool]) -> Option<TokenStream> {
        if !used.contains(&true) {
            return None;
        }
        let tips = used.chunks(6).enumerate().map(|(t, used)| {
            let names = used.iter().enumerate().map(|(k, &u)| {
                if u {
                    let index = u16::try_from(6 * t + k).unwrap_or(u16::MAX);
                    let v = self.variable_name(Var::TipWrench(index));
                    quote!(#v)
                } else {
                    quote!(_)
                }
            });
            quote!([#(#names),*])
        });
        let array = local("wrenches_");
        Some(quote!(let [#(#tips),*] = *#array;))
    }

    /// The sines and cosines of the joints that need them, computed side by side: up to eight
    /// joints a call, `let ([s1, …, s6, _, _], [c1, …, c6, _, _]) = T::sin_cos_8([q_[0], …]);`
    /// (six to eight, where one range test and two vectors in flight cost less than two
    /// calls), `let ([s2, s3, _, _], [c2, c3, _, _]) = T::sin_cos_4([q_[1], q_[2], T::ONE,
    /// T::ONE]);` (two to four, and five as four and one); a group is padded with `T::ONE`, `_`
    /// names an unused value; a single joint on its own, `let (s6, c6) = T::sin_cos(q_[5]);`.
    pub(super) fn sines_and_cosines(&mut self, statements: &mut Vec<TokenStream>) {
        let mut joints = Vec::new();
        for i in 0..self.eq.dof {
            let i16 = u16::try_from(i).unwrap_or(u16::MAX);
            let needed = |v: Var| {
                self.graph
                    .nodes()
                    .any(|(id, node)| node == Node::Var(v) && self.needed[id.index()])
            };
            let (s, c) = (needed(Var::SinQ(i16)), needed(Var::CosQ(i16)));
            if !s && !c {
                continue;
            }
            let q = local("q_");
            let index = proc_macro2::Literal::usize_unsuffixed(i);
            let angle = match self.eq.angle_offsets[i] {
                Some(off) => {
                    let o = self.expr(off, Place::AddRight);
                    quote!(#q[#index] + #o)
                }
                None => quote!(#q[#index]),
            };
            let name = |used: bool, v: Var| {
                if used {
                    let n = self.variable_name(v);
                    quote!(#n)
                } else {
                    quote!(_)
                }
            };
            joints.push((
                name(s, Var::SinQ(i16)),
                name(c, Var::CosQ(i16)),
                angle,
                s,
                c,
            ));
        }
        let mut rest = &joints[..];
        while !rest.is_empty() {
            // Five joints go as four and one: the second vector would cost more than one
            // scalar pair.
            let width = match rest.len() {
                5 => 4,
                n => n.min(8),
            };
            let (group, tail) = rest.split_at(width);
            rest = tail;
            if let [(sn, cn, angle, s, c)] = group {
                statements.push(match (s, c) {
                    (true, true) => quote!(let (#sn, #cn) = T::sin_cos(#angle);),
                    (true, false) => quote!(let #sn = T::sin(#angle);),
                    _ => quote!(let #cn = T::cos(#angle);),
                });
                continue;
            }
            let (width, call) = if group.len() > 4 {
                (8, quote!(sin_cos_8))
            } else {
                (4, quote!(sin_cos_4))
            };
            let pad = width - group.len();
            let blank = std::iter::repeat(quote!(_)).take(pad);
            let sines = group.iter().map(|j| j.0.clone()).chain(blank.clone());
            let cosines = group.iter().map(|j| j.1.clone()).chain(blank);
            let angles = group
                .iter()
                .map(|j| j.2.clone())
                .chain(std::iter::repeat(quote!(T::ONE)).take(pad));
            statements.push(quote!(
                let ([#(#sines),*], [#(#cosines),*]) = T::#call([#(#angles),*]);
            ));
        }
    }
}
