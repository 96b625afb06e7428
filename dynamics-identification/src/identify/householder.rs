//! The triangular factor of a tall matrix whose rows arrive in blocks, by Householder
//! reflections: after rows `A` (m × w, m as large as the data), `A = Q R` with `Q` orthogonal and
//! `R` upper triangular, w × w, so that `‖A x‖ = ‖R x‖` for every `x` and `AᵀA = RᵀR`. Only `R`
//! and one block of rows are held, never `A`, and `AᵀA` is never formed (it would square the
//! condition number).
//!
//! A block `B` of rows is absorbed by factoring `[R; B]`: for column j, the reflection
//! `H = I − 2 v vᵀ / vᵀv` with `v = [R_jj − α; B_·j]`, `α = −sign(R_jj) ‖[R_jj; B_·j]‖`, turns the
//! column into `[α; 0]` (R's rows below j are zero in column j, so `v` has no other entries) and
//! is applied to the columns after j. Blocks are stored column by column, so each step is a dot
//! product and an update over contiguous memory; with `m` rows a block costs about `2 m w²`
//! operations.

/// A streamed upper-triangular factor.
#[derive(Clone, Debug)]
pub struct Triangle {
    width: usize,
    /// R, row-major; entries below the diagonal stay zero.
    r: Vec<f64>,
    /// The pending rows, column-major: entry (row i, column j) at `j * capacity + i`.
    block: Vec<f64>,
    capacity: usize,
    pending: usize,
    rows: usize,
}

impl Triangle {
    /// The factor of no rows yet, of `width` columns, absorbing rows `block_rows` at a time.
    #[must_use]
    pub fn new(width: usize, block_rows: usize) -> Triangle {
        let capacity = block_rows.max(1);
        Triangle {
            width,
            r: vec![0.0; width * width],
            block: vec![0.0; width * capacity],
            capacity,
            pending: 0,
            rows: 0,
        }
    }

    /// The rows taken so far.
    #[must_use]
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Takes one row (`width` values).
    pub fn push(&mut self, row: &[f64]) {
        debug_assert_eq!(row.len(), self.width);
        for (j, &x) in row.iter().enumerate() {
            self.block[j * self.capacity + self.pending] = x;
        }
        self.pending += 1;
        self.rows += 1;
        if self.pending == self.capacity {
            self.absorb();
        }
    }

    /// R, once every row pushed is absorbed: row-major, `width × width`.
    pub fn factor(&mut self) -> &[f64] {
        self.absorb();
        &self.r
    }

    /// Absorbs the pending rows into R.
    fn absorb(&mut self) {
        let (w, m, cap) = (self.width, self.pending, self.capacity);
        if m == 0 {
            return;
        }
        for j in 0..w {
            let (left, right) = self.block.split_at_mut((j + 1) * cap);
            let v = &left[j * cap..j * cap + m];
            let tail: f64 = v.iter().map(|x| x * x).sum();
            if tail == 0.0 {
                // The column is zero below R: nothing to reflect.
                continue;
            }
            let rjj = self.r[j * w + j];
            let norm = rjj.hypot(tail.sqrt());
            let alpha = if rjj >= 0.0 { -norm } else { norm };
            let v0 = rjj - alpha;
            let vtv = v0 * v0 + tail;
            for k in j + 1..w {
                let column = &mut right[(k - j - 1) * cap..(k - j - 1) * cap + m];
                let rjk = &mut self.r[j * w + k];
                let s = v0 * *rjk + dot(v, column);
                let f = 2.0 * s / vtv;
                *rjk -= f * v0;
                for (c, x) in column.iter_mut().zip(v) {
                    *c -= f * x;
                }
            }
            self.r[j * w + j] = alpha;
        }
        self.pending = 0;
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Solves `R x = b` for upper-triangular `R` (row-major, `n × n`) by back substitution.
#[must_use]
pub fn back_substitute(r: &[f64], n: usize, b: &[f64]) -> Vec<f64> {
    let mut x = vec![0.0; n];
    for i in (0..n).rev() {
        let row = &r[i * n..(i + 1) * n];
        let s: f64 = (i + 1..n).map(|k| row[k] * x[k]).sum();
        x[i] = (b[i] - s) / row[i];
    }
    x
}

/// `R⁻¹` of an upper-triangular `R` (row-major, `n × n`), upper triangular, row-major.
#[must_use]
pub fn inverse(r: &[f64], n: usize) -> Vec<f64> {
    let mut inv = vec![0.0; n * n];
    for c in 0..n {
        let unit: Vec<f64> = (0..n).map(|i| f64::from(u8::from(i == c))).collect();
        for (i, x) in back_substitute(r, n, &unit).into_iter().enumerate() {
            inv[i * n + c] = x;
        }
    }
    inv
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 7 × 3 matrix (a quadratic's basis at 7 points, and a right-hand side) whose normal
    /// equations are solved by hand below.
    fn rows() -> Vec<[f64; 4]> {
        (0..7)
            .map(|i| {
                let x = f64::from(i) - 3.0;
                // y = 1 + 2x − 0.5x² plus a residual orthogonal to 1, x, x².
                let wiggle = [-1.0, 6.0, -15.0, 20.0, -15.0, 6.0, -1.0][i as usize];
                [1.0, x, x * x, 1.0 + 2.0 * x - 0.5 * x * x + 0.01 * wiggle]
            })
            .collect()
    }

    #[test]
    fn least_squares_through_the_factor() {
        // The wiggle is the 6th difference of a unit impulse, orthogonal to every polynomial of
        // degree below 6: the fit is exactly 1 + 2x − 0.5x², its residual 0.01 ‖wiggle‖.
        for block in [1, 2, 3, 100] {
            let mut t = Triangle::new(4, block);
            for row in rows() {
                t.push(&row);
            }
            assert_eq!(t.rows(), 7);
            let r = t.factor().to_vec();
            let r3: Vec<f64> = (0..3).flat_map(|i| r[i * 4..i * 4 + 3].to_vec()).collect();
            let z: Vec<f64> = (0..3).map(|i| r[i * 4 + 3]).collect();
            let x = back_substitute(&r3, 3, &z);
            for (got, want) in x.iter().zip([1.0, 2.0, -0.5]) {
                assert!((got - want).abs() < 1e-13, "{block}: {x:?}");
            }
            let residual: f64 = 0.01 * (1.0f64 + 36.0 + 225.0 + 400.0 + 225.0 + 36.0 + 1.0).sqrt();
            assert!((r[15].abs() - residual).abs() < 1e-13, "{}", r[15]);
            // RᵀR = AᵀA: the sums of 1, x², x⁴ over x = −3..3 are 7, 28, 196.
            let gram =
                |a: usize, b: usize| (0..4).map(|i| r[i * 4 + a] * r[i * 4 + b]).sum::<f64>();
            assert!((gram(0, 0) - 7.0).abs() < 1e-12 && (gram(1, 1) - 28.0).abs() < 1e-12);
            assert!((gram(2, 2) - 196.0).abs() < 1e-11 && gram(0, 1).abs() < 1e-12);
        }
    }

    #[test]
    fn a_zero_column_is_left_alone() {
        let mut t = Triangle::new(2, 4);
        t.push(&[0.0, 3.0]);
        t.push(&[0.0, 4.0]);
        let r = t.factor();
        assert_eq!(r[0], 0.0);
        assert!((r[3].abs() - 5.0).abs() < 1e-15);
    }

    #[test]
    fn the_inverse_of_a_triangle() {
        let r = [2.0, 1.0, -1.0, 0.0, 4.0, 2.0, 0.0, 0.0, 0.5];
        let inv = inverse(&r, 3);
        for i in 0..3 {
            for j in 0..3 {
                let product: f64 = (0..3).map(|k| r[i * 3 + k] * inv[k * 3 + j]).sum();
                let unit = if i == j { 1.0 } else { 0.0 };
                assert!((product - unit).abs() < 1e-15, "{i} {j}");
            }
        }
    }
}
