//! A tree's structure in the printout: which joint each branch hangs from, and which entries
//! of `D` are zero because their joints are on different branches (`D_ij ≠ 0` only where one
//! of i, j is an ancestor of the other, or itself).

use crate::model::Robot;

/// Each joint's antecedent (`None`: the base), for a robot that branches; `None` for a chain.
pub(super) fn antecedents(robot: &Robot) -> Option<Vec<Option<usize>>> {
    robot
        .is_tree()
        .then(|| (0..robot.dof()).map(|i| robot.parent(i)).collect())
}

/// Whether joint `a` is `d` or one of its ancestors.
fn supports(antecedents: &[Option<usize>], a: usize, mut d: usize) -> bool {
    loop {
        if d == a {
            return true;
        }
        match antecedents[d] {
            Some(p) => d = p,
            None => return false,
        }
    }
}

/// Whether `D_ij` can be nonzero: one joint is the other or an ancestor of it.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn related(antecedents: Option<&[Option<usize>]>, i: usize, j: usize) -> bool {
    antecedents.map_or(true, |a| supports(a, i, j) || supports(a, j, i))
}

/// The branches, 1-based: each run of joints that hang one from the one before, with where it
/// hangs: "joints 1-7 from the base; joint 8 from joint 7; joint 9 from joint 7".
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn describe(antecedents: &[Option<usize>]) -> String {
    let mut runs: Vec<(usize, usize)> = Vec::new();
    for (j, &a) in antecedents.iter().enumerate() {
        match runs.last_mut() {
            Some((_, last)) if a == Some(*last) && *last + 1 == j => *last = j,
            _ => runs.push((j, j)),
        }
    }
    let runs: Vec<String> = runs
        .iter()
        .map(|&(first, last)| {
            let joints = if first == last {
                format!("joint {}", first + 1)
            } else {
                format!("joints {}-{}", first + 1, last + 1)
            };
            let from =
                antecedents[first].map_or("the base".to_string(), |a| format!("joint {}", a + 1));
            format!("{joints} from {from}")
        })
        .collect();
    runs.join("; ")
}

/// The entries `D_ij` (i < j, 1-based) that are zero because i and j are on different
/// branches, as `D89, D8 10`.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn zero_inertia(antecedents: &[Option<usize>]) -> Vec<(usize, usize)> {
    let n = antecedents.len();
    (0..n)
        .flat_map(|i| (i + 1..n).map(move |j| (i, j)))
        .filter(|&(i, j)| !related(Some(antecedents), i, j))
        .collect()
}
