//! Which joints of a URDF make the robot: the serial path to `tip` (as `tree` finds it), or
//! the tree below `base`: every branch by default, or the branches that lead to the `tips`.
//! The joints come in depth-first order, a link's child joints in the file's order; a part
//! fixed to a kept link is merged into it and a branch that is not kept is cut off, as below a
//! tip. Floating and planar joints that are kept are refused.

use super::tree::{Chain, Tree};
use super::xml::error;
use super::Chain as Request;
use crate::front::errors::{FileError, Requested};

impl Tree<'_> {
    /// The joints `request` keeps.
    pub(super) fn select(&self, request: Request) -> Result<Chain, Vec<FileError>> {
        let base = self.base(request.base)?;
        match (request.tip, request.tips) {
            (Some(_), [_, ..]) => Err(vec![error(
                self.doc.at,
                "`tip` and `tips` are both given: `tip` takes the serial path to one link, \
                 `tips` the branches to several; give one",
            )]),
            (Some(tip), []) => self.chain(base, tip),
            (None, tips) => self.branches_below(base, tips),
        }
    }

    /// Below `base`, the joints that lead to a moving joint (`tips` empty) or to one of the
    /// `tips`, in depth-first order.
    fn branches_below(&self, base: usize, tips: &[&str]) -> Result<Chain, Vec<FileError>> {
        let mut errors = Vec::new();
        let mut tip_links = Vec::new();
        let mut leads_to_tip = vec![false; self.doc.joints.len()];
        for (i, name) in tips.iter().enumerate() {
            let tip = match self.find(name, Requested::Tips(i)) {
                Ok(tip) => tip,
                Err(e) => {
                    errors.push(e);
                    continue;
                }
            };
            let (b, t) = (&self.doc.links[base].name, &self.doc.links[tip].name);
            let from_root = self.ancestors(tip);
            let start = from_root.iter().position(|j| self.parent_link(*j) == base);
            let Some(path) = start.map(|start| &from_root[start..]) else {
                let message = if tip == base {
                    format!("`tips`: the link `{t}` is the base link")
                } else {
                    format!("`tips`: the link `{t}` is not below the base link `{b}`")
                };
                errors.push(error(self.doc.links[tip].at, message).about(Requested::Tips(i)));
                continue;
            };
            if !path.iter().any(|j| self.doc.joints[*j].kind.moves()) {
                let message = format!(
                    "`tips`: the link `{t}` is fixed to the base link `{b}` (no joint between \
                     them moves): its pose and Jacobian would be constants; name a link that moves"
                );
                errors.push(error(self.doc.links[tip].at, message).about(Requested::Tips(i)));
                continue;
            }
            path.iter().for_each(|j| leads_to_tip[*j] = true);
            tip_links.push(tip);
        }
        if !errors.is_empty() {
            return Err(errors);
        }
        let kept = |j: usize| {
            if tips.is_empty() {
                self.moves(j)
            } else {
                leads_to_tip[j]
            }
        };
        let mut joints = Vec::new();
        // Depth first with a stack (a chain may be thousands of links long): each link's
        // children pushed last first, so that they come out in the file's order.
        let mut stack: Vec<usize> = self.children(base).iter().rev().copied().collect();
        while let Some(j) = stack.pop() {
            if !kept(j) {
                continue;
            }
            joints.push(j);
            stack.extend(self.children(self.child(j)).iter().rev());
        }
        let chain = Chain {
            base,
            joints,
            tips: tip_links,
        };
        let errors: Vec<FileError> = self.path_problems(&chain).collect();
        if errors.is_empty() {
            Ok(chain)
        } else {
            Err(errors)
        }
    }
}
