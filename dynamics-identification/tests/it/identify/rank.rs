//! The identifiable parameters, and the combinations of those that are not.

use dynamics_identification::identify::householder::Triangle;
use dynamics_identification::identify::rank::{identifiable, Unidentified};

/// Columns: x, 0, 2x + 3·1 (a combination), 1, x², and a column of 10⁻⁹ x³ (small but
/// independent: scaling keeps it).
fn factor() -> Vec<f64> {
    let mut t = Triangle::new(6, 8);
    for i in 0..20 {
        let x = f64::from(i) / 7.0 - 1.0;
        t.push(&[x, 0.0, 2.0 * x + 3.0, 1.0, x * x, 1e-9 * x * x * x]);
    }
    t.factor().to_vec()
}

#[test]
fn zero_and_dependent_columns_are_named_with_their_combination() {
    let (kept, dropped) = identifiable(&factor(), 6, 1e-8);
    assert_eq!(kept, [0, 2, 4, 5]);
    assert_eq!(
        dropped[0],
        Unidentified {
            parameter: 1,
            combination: vec![],
        }
    );
    // The constant column comes after 2x + 3, so it is the one named: 1 = (2x + 3)/3 − 2x/3.
    let d = &dropped[1];
    assert_eq!((dropped.len(), d.parameter), (2, 3), "{dropped:?}");
    let mut terms = d.combination.clone();
    terms.sort_by_key(|t| t.0);
    assert_eq!(terms.len(), 2, "{terms:?}");
    assert_eq!((terms[0].0, terms[1].0), (0, 2));
    assert!((terms[0].1 + 2.0 / 3.0).abs() < 1e-12, "{terms:?}");
    assert!((terms[1].1 - 1.0 / 3.0).abs() < 1e-12, "{terms:?}");
}

#[test]
fn a_near_dependence_is_named_only_below_the_tolerance() {
    let mut t = Triangle::new(2, 8);
    for i in 0..10 {
        let x = f64::from(i);
        // The second column leaves the first's direction by about 10⁻⁵.
        t.push(&[x, x + 1e-5 * x * x]);
    }
    let r = t.factor().to_vec();
    assert_eq!(identifiable(&r, 2, 1e-6).0, [0, 1]);
    assert_eq!(identifiable(&r, 2, 1e-4).0, [0]);
}
