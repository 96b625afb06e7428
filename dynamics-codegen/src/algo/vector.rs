//! 3-vectors and 3×3 matrices over a [`Scalar`], written out component by component so that a
//! symbolic trace gets one node per component and every zero folds away.

use super::Scalar;

/// A 3-vector.
#[derive(Clone, Copy, Debug)]
pub struct V3<S> {
    /// x component.
    pub x: S,
    /// y component.
    pub y: S,
    /// z component.
    pub z: S,
}

impl<S: Scalar> V3<S> {
    /// `(x, y, z)`.
    pub fn new(x: S, y: S, z: S) -> V3<S> {
        V3 { x, y, z }
    }

    /// The zero vector in the context of `s`.
    pub fn zero(s: S) -> V3<S> {
        let z = s.zero();
        V3::new(z, z, z)
    }

    /// `k · self`.
    #[must_use]
    pub fn scale(self, k: S) -> V3<S> {
        V3::new(k * self.x, k * self.y, k * self.z)
    }

    /// `self · o`.
    pub fn dot(self, o: V3<S>) -> S {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// `self × o`.
    #[must_use]
    pub fn cross(self, o: V3<S>) -> V3<S> {
        V3::new(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
    }

    /// `self × (0, 0, k)`: `(y k, −x k, 0)`.
    #[must_use]
    pub fn cross_z(self, k: S) -> V3<S> {
        V3::new(self.y * k, -(self.x * k), k.zero())
    }
}

/// A 3×3 matrix, rows first.
#[derive(Clone, Copy, Debug)]
pub struct Mat3<S> {
    /// Rows.
    pub m: [[S; 3]; 3],
}

impl<S: Scalar> Mat3<S> {
    /// The symmetric matrix of `[xx, yy, zz, xy, xz, yz]`.
    pub fn symmetric(e: [S; 6]) -> Mat3<S> {
        let [xx, yy, zz, xy, xz, yz] = e;
        Mat3 {
            m: [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]],
        }
    }

    /// The rotation about x by an angle with sine `s` and cosine `c`.
    pub fn rot_x(s: S, c: S) -> Mat3<S> {
        let (o, l) = (s.zero(), s.one());
        Mat3 {
            m: [[l, o, o], [o, c, -s], [o, s, c]],
        }
    }

    /// The rotation about z by an angle with sine `s` and cosine `c`.
    pub fn rot_z(s: S, c: S) -> Mat3<S> {
        let (o, l) = (s.zero(), s.one());
        Mat3 {
            m: [[c, -s, o], [s, c, o], [o, o, l]],
        }
    }

    /// `self · v`.
    pub fn mul_vec(&self, v: V3<S>) -> V3<S> {
        let r = |i: usize| self.m[i][0] * v.x + self.m[i][1] * v.y + self.m[i][2] * v.z;
        V3::new(r(0), r(1), r(2))
    }

    /// `selfᵀ · v`.
    pub fn tr_mul_vec(&self, v: V3<S>) -> V3<S> {
        let c = |j: usize| self.m[0][j] * v.x + self.m[1][j] * v.y + self.m[2][j] * v.z;
        V3::new(c(0), c(1), c(2))
    }

    /// `self · o`.
    #[must_use]
    pub fn mul(&self, o: &Mat3<S>) -> Mat3<S> {
        let e = |i: usize, j: usize| {
            self.m[i][0] * o.m[0][j] + self.m[i][1] * o.m[1][j] + self.m[i][2] * o.m[2][j]
        };
        Mat3 {
            m: [
                [e(0, 0), e(0, 1), e(0, 2)],
                [e(1, 0), e(1, 1), e(1, 2)],
                [e(2, 0), e(2, 1), e(2, 2)],
            ],
        }
    }

    /// `selfᵀ`.
    #[must_use]
    pub fn transpose(&self) -> Mat3<S> {
        let m = &self.m;
        Mat3 {
            m: [
                [m[0][0], m[1][0], m[2][0]],
                [m[0][1], m[1][1], m[2][1]],
                [m[0][2], m[1][2], m[2][2]],
            ],
        }
    }

    /// `R · self · Rᵀ` for a symmetric `self`, returned as `[xx, yy, zz, xy, xz, yz]`.
    pub fn congruence(&self, r: &Mat3<S>) -> [S; 6] {
        let t = r.mul(self).mul(&r.transpose());
        [
            t.m[0][0], t.m[1][1], t.m[2][2], t.m[0][1], t.m[0][2], t.m[1][2],
        ]
    }
}

impl<S: Scalar> std::ops::Add for V3<S> {
    type Output = V3<S>;
    fn add(self, o: V3<S>) -> V3<S> {
        V3::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl<S: Scalar> std::ops::Sub for V3<S> {
    type Output = V3<S>;
    fn sub(self, o: V3<S>) -> V3<S> {
        V3::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl<S: Scalar> std::ops::Neg for V3<S> {
    type Output = V3<S>;
    fn neg(self) -> V3<S> {
        V3::new(-self.x, -self.y, -self.z)
    }
}
