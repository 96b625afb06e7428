//! The kinematic tree of a URDF and the serial chain in it from the base link to a `tip` link.
//!
//! The chain is the path of joints from `base` (default: the root link) to `tip`. A joint that
//! moves but is not on the path, hanging off a link from the base up to the link before the
//! tip, is a branch and refused; so are floating and planar joints on the path. Below
//! the tip, a part fixed to the tip link is merged into it and what moves below it is cut off.
//! Without a `tip`, the joints below the base are taken as a tree (`select`).

use super::xml::{error, Description, Kind};
use crate::front::errors::{FileError, Requested};
use std::collections::BTreeMap;

/// The links and joints of a URDF as a tree.
pub(super) struct Tree<'a> {
    pub doc: &'a Description,
    /// Each link's index by name.
    index: BTreeMap<&'a str, usize>,
    /// Per link, the joint that has it as child.
    pub(super) parent: Vec<Option<usize>>,
    /// Per link, the joints that have it as parent, in the file's order.
    children: Vec<Vec<usize>>,
    /// Per joint, whether it or a joint below it moves.
    moving: Vec<bool>,
}

/// The joints the robot is made of: a serial chain from base to tip, or a tree below the base.
pub(super) struct Chain {
    /// The base link.
    pub base: usize,
    /// The joints below the base that are kept, fixed ones included, in depth-first order
    /// (each link's child joints in the file's order).
    pub joints: Vec<usize>,
    /// The links named as tips, in the order named (for the hand frame).
    pub tips: Vec<usize>,
}

/// The tree of `doc`; every link named twice, joint naming an unknown link, or link with two
/// parents is an error.
pub(super) fn tree(doc: &Description) -> Result<Tree<'_>, Vec<FileError>> {
    let mut errors = Vec::new();
    let mut index = BTreeMap::new();
    for (i, link) in doc.links.iter().enumerate() {
        if index.insert(link.name.as_str(), i).is_some() {
            errors.push(error(
                link.at,
                format!("a second link named `{}`", link.name),
            ));
        }
    }
    let mut parent = vec![None; doc.links.len()];
    let mut children = vec![Vec::new(); doc.links.len()];
    for (j, joint) in doc.joints.iter().enumerate() {
        let (Some(&p), Some(&c)) = (
            index.get(joint.parent.as_str()),
            index.get(joint.child.as_str()),
        ) else {
            let unknown = [&joint.parent, &joint.child]
                .into_iter()
                .find(|l| !index.contains_key(l.as_str()));
            let unknown = unknown.map_or("", |l| l.as_str());
            errors.push(error(
                joint.at,
                format!(
                    "joint `{}` names the link `{unknown}`, which the file does not define",
                    joint.name
                ),
            ));
            continue;
        };
        if let Some(first) = parent[c].replace(j) {
            let first: &str = &doc.joints[first].name;
            errors.push(error(
                joint.at,
                format!(
                    "link `{}` is the child of joints `{first}` and `{}`: a URDF is a tree",
                    joint.child, joint.name
                ),
            ));
        }
        children[p].push(j);
    }
    let mut tree = Tree {
        doc,
        index,
        parent,
        children,
        moving: vec![false; doc.joints.len()],
    };
    if let Some(link) = tree.on_a_loop() {
        let link = &doc.links[link];
        errors.push(error(
            link.at,
            format!(
                "link `{}` is its own ancestor: the joints make a loop, not a tree",
                link.name
            ),
        ));
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    tree.moving = tree.moving_below();
    Ok(tree)
}

impl Tree<'_> {
    /// The link named `name` by the request's key `role`.
    pub(super) fn find(&self, name: &str, role: Requested) -> Result<usize, FileError> {
        self.index.get(name).copied().ok_or_else(|| {
            let names: Vec<String> = self
                .doc
                .links
                .iter()
                .map(|l| format!("`{}`", l.name))
                .collect();
            error(
                self.doc.at,
                format!(
                    "no link `{name}` for `{}`: the links are {}",
                    role.key(),
                    names.join(", ")
                ),
            )
            .about(role)
        })
    }

    /// The parent link of joint `joint`.
    pub(super) fn parent_link(&self, joint: usize) -> usize {
        self.index[self.doc.joints[joint].parent.as_str()]
    }

    /// A link that is its own ancestor, if the joints make a loop. Each link is walked up from
    /// once (a walk stops at a link known to reach a root), so that a long chain is not
    /// quadratic.
    fn on_a_loop(&self) -> Option<usize> {
        #[derive(Clone, Copy, PartialEq)]
        enum Seen {
            Not,
            OnThisWalk,
            ReachesARoot,
        }
        let mut seen = vec![Seen::Not; self.doc.links.len()];
        for link in 0..self.doc.links.len() {
            let mut walk = Vec::new();
            let mut at = Some(link);
            while let Some(l) = at {
                match seen[l] {
                    Seen::ReachesARoot => break,
                    Seen::OnThisWalk => return Some(l),
                    Seen::Not => {}
                }
                seen[l] = Seen::OnThisWalk;
                walk.push(l);
                at = self.parent[l].map(|j| self.parent_link(j));
            }
            for l in walk {
                seen[l] = Seen::ReachesARoot;
            }
        }
        None
    }

    /// Per joint, whether it or a joint below it moves: each moving joint marks the joints
    /// above it, up to one marked already, so that each joint is marked once.
    fn moving_below(&self) -> Vec<bool> {
        let mut moving = vec![false; self.doc.joints.len()];
        for (j, joint) in self.doc.joints.iter().enumerate() {
            if !joint.kind.moves() {
                continue;
            }
            let mut at = Some(j);
            while let Some(j) = at.filter(|j| !moving[*j]) {
                moving[j] = true;
                at = self.parent[self.parent_link(j)];
            }
        }
        moving
    }

    /// The joints from the root down to `link` (the tree has no loop).
    pub(super) fn ancestors(&self, link: usize) -> Vec<usize> {
        let mut joints = Vec::new();
        let mut at = link;
        while let Some(j) = self.parent[at] {
            joints.push(j);
            at = self.parent_link(j);
        }
        joints.reverse();
        joints
    }

    /// The child link of joint `joint`.
    pub fn child(&self, joint: usize) -> usize {
        self.index[self.doc.joints[joint].child.as_str()]
    }

    /// The joints that have `link` as parent.
    pub fn children(&self, link: usize) -> &[usize] {
        &self.children[link]
    }

    /// Whether joint `joint` or one below it moves.
    pub fn moves(&self, joint: usize) -> bool {
        self.moving[joint]
    }

    /// The base link: the one named, or the root link.
    pub(super) fn base(&self, base: Option<&str>) -> Result<usize, Vec<FileError>> {
        match base {
            Some(name) => self.find(name, Requested::Base).map_err(|e| vec![e]),
            None => self.root().map_err(|e| vec![e]),
        }
    }

    /// The chain from `base` to the link named `tip`.
    pub fn chain(&self, base: usize, tip: &str) -> Result<Chain, Vec<FileError>> {
        let tip = self.find(tip, Requested::Tip).map_err(|e| vec![e])?;
        let from_root = self.ancestors(tip);
        let start = from_root
            .iter()
            .position(|j| self.doc.joints[*j].parent == self.doc.links[base].name);
        let joints = match start {
            Some(start) => from_root[start..].to_vec(),
            None if base == tip => Vec::new(),
            None => {
                let (b, t) = (&self.doc.links[base].name, &self.doc.links[tip].name);
                return Err(vec![error(
                    self.doc.links[tip].at,
                    format!("the tip link `{t}` is not below the base link `{b}`"),
                )
                .about(Requested::Tip)]);
            }
        };
        let chain = Chain {
            base,
            joints,
            tips: vec![tip],
        };
        let errors: Vec<FileError> = self
            .path_problems(&chain)
            .chain(self.branches(&chain))
            .collect();
        if errors.is_empty() {
            Ok(chain)
        } else {
            Err(errors)
        }
    }

    /// The only link without a parent joint.
    fn root(&self) -> Result<usize, FileError> {
        let roots: Vec<usize> = (0..self.doc.links.len())
            .filter(|l| self.parent[*l].is_none())
            .collect();
        match roots[..] {
            [root] => Ok(root),
            _ => {
                let names: Vec<String> = roots
                    .iter()
                    .map(|l| format!("`{}`", self.doc.links[*l].name))
                    .collect();
                Err(error(
                    self.doc.at,
                    format!(
                        "the robot has {} root links ({}): name the base with `base = \"..\"`",
                        roots.len(),
                        names.join(", ")
                    ),
                ))
            }
        }
    }

    /// The joints on the path that cannot be part of a serial chain.
    pub(super) fn path_problems<'c>(
        &'c self,
        chain: &'c Chain,
    ) -> impl Iterator<Item = FileError> + 'c {
        chain.joints.iter().filter_map(move |&j| {
            let joint = &self.doc.joints[j];
            let name = &joint.name;
            match joint.kind {
                Kind::Floating | Kind::Planar => {
                    let kind = if joint.kind == Kind::Floating { "floating" } else { "planar" };
                    Some(error(joint.at, format!("`<joint name=\"{name}\" type=\"{kind}\">`: a {kind} joint moves in more than one direction; a robot has revolute, continuous, prismatic and fixed joints")))
                }
                _ => None,
            }
        })
    }

    /// Joints that move off the path, hanging from the base up to the link before the tip.
    fn branches<'c>(&'c self, chain: &'c Chain) -> impl Iterator<Item = FileError> + 'c {
        let path_links =
            std::iter::once(chain.base).chain(chain.joints.iter().map(|j| self.child(*j)));
        // Paired with the joint that leaves it along the path, a link's branches are told from
        // the chain by one comparison, not a search of the path (quadratic on a long chain).
        let before_tip = path_links.zip(chain.joints.iter().copied());
        before_tip.flat_map(move |(link, next)| {
            self.children[link].iter().filter_map(move |&j| {
                if j == next || !self.moves(j) {
                    return None;
                }
                let joint = &self.doc.joints[j];
                let link = &self.doc.links[link].name;
                Some(error(joint.at, format!("`<joint name=\"{}\">` branches off the chain at link `{link}` and it, or a joint below it, moves: the chain from base to tip must be serial (choose another `tip`, or make the joint fixed)", joint.name)))
            })
        })
    }
}
