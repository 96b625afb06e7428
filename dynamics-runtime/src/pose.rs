//! A rigid pose, as the kinematic methods return it: `x ↦ rotation · x + position`.

use crate::Real;

/// A frame's pose in another: its rotation (rows; the columns are the book's `n`, `o`, `a`)
/// and the position of its origin (`p`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Pose<T> {
    /// The rotation matrix, row by row.
    pub rotation: [[T; 3]; 3],
    /// The position of the origin.
    pub position: [T; 3],
}

impl<T: Real> Pose<T> {
    /// The pose of the rows `[R | p]` of a homogeneous transform.
    #[must_use]
    pub fn from_rows(rows: [[T; 4]; 3]) -> Pose<T> {
        Pose {
            rotation: rows.map(|r| [r[0], r[1], r[2]]),
            position: [rows[0][3], rows[1][3], rows[2][3]],
        }
    }

    /// The 4×4 homogeneous transform `[n o a p; 0 0 0 1]` (the book's form).
    #[must_use]
    pub fn homogeneous(&self) -> [[T; 4]; 4] {
        let (r, p) = (&self.rotation, &self.position);
        let row = |i: usize| [r[i][0], r[i][1], r[i][2], p[i]];
        [row(0), row(1), row(2), [T::ZERO, T::ZERO, T::ZERO, T::ONE]]
    }
}
