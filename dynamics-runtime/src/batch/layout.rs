//! Where a batch's states and results are: one after the other (array of structs), or one slice
//! per joint (structure of arrays).

/// States of `M` values each, read by index: `&[[T; M]]` (state k is `states[k]`) or
/// `[&[T]; M]` (value j of state k is `states[j][k]`, every slice as long).
pub trait States<T, const M: usize> {
    /// The number of states.
    fn count(&self) -> usize;
    /// Value `j` of state `k`.
    fn value(&self, k: usize, j: usize) -> T;
    /// The first value whose slice holds another number of states than [`States::count`],
    /// and that number: one slice per value may be ragged, a slice of states never is.
    #[inline(always)]
    fn ragged(&self) -> Option<(usize, usize)> {
        None
    }
    /// State `k`.
    #[inline(always)]
    fn state(&self, k: usize) -> [T; M] {
        core::array::from_fn(|j| self.value(k, j))
    }
}

impl<T: Copy, const M: usize> States<T, M> for [[T; M]] {
    #[inline(always)]
    fn count(&self) -> usize {
        self.len()
    }
    #[inline(always)]
    fn value(&self, k: usize, j: usize) -> T {
        self[k][j]
    }
    #[inline(always)]
    fn state(&self, k: usize) -> [T; M] {
        self[k]
    }
}

/// As the slice of its states.
impl<T: Copy, const M: usize, const K: usize> States<T, M> for [[T; M]; K] {
    #[inline(always)]
    fn count(&self) -> usize {
        K
    }
    #[inline(always)]
    fn value(&self, k: usize, j: usize) -> T {
        self.as_slice().value(k, j)
    }
    #[inline(always)]
    fn state(&self, k: usize) -> [T; M] {
        self.as_slice().state(k)
    }
}

/// One slice per value. The number of states is the first slice's length (0 for `M = 0`); the
/// `_batch` methods refuse slices of different lengths ([`States::ragged`]) before they read.
impl<T: Copy, const M: usize> States<T, M> for [&[T]; M] {
    #[inline(always)]
    fn count(&self) -> usize {
        self.first().map_or(0, |column| column.len())
    }
    #[inline(always)]
    fn value(&self, k: usize, j: usize) -> T {
        self[j][k]
    }
    #[inline(always)]
    fn ragged(&self) -> Option<(usize, usize)> {
        ragged(self.iter().map(|column| column.len()))
    }
}

/// The first length of `lengths` that is not the first's, with its index.
#[inline(always)]
fn ragged(lengths: impl Iterator<Item = usize>) -> Option<(usize, usize)> {
    let mut lengths = lengths.enumerate();
    let (_, first) = lengths.next()?;
    lengths.find(|&(_, len)| len != first)
}

/// Results written by index: `&mut [O]`, or one slice per joint for results of one value per
/// joint (`[&mut [T]; N]`, value j of result k at `[j][k]`).
pub trait StatesMut<O> {
    /// The number of results.
    fn count(&self) -> usize;
    /// Writes result `k`.
    fn set(&mut self, k: usize, value: O);
    /// As [`States::ragged`]: the first slice of another length than the first's, and that
    /// length.
    #[inline(always)]
    fn ragged(&self) -> Option<(usize, usize)> {
        None
    }
    /// Results `k` to `k + L − 1` side by side, where they are (a slice of results), for
    /// writing a group's lanes in place.
    #[inline(always)]
    fn group<const L: usize>(&mut self, k: usize) -> Option<&mut [O; L]> {
        let _ = k;
        None
    }
}

impl<O> StatesMut<O> for [O] {
    #[inline(always)]
    fn count(&self) -> usize {
        self.len()
    }
    #[inline(always)]
    fn set(&mut self, k: usize, value: O) {
        self[k] = value;
    }
    #[inline(always)]
    fn group<const L: usize>(&mut self, k: usize) -> Option<&mut [O; L]> {
        self.get_mut(k..k + L)?.try_into().ok()
    }
}

/// As the slice of its results.
impl<O, const K: usize> StatesMut<O> for [O; K] {
    #[inline(always)]
    fn count(&self) -> usize {
        K
    }
    #[inline(always)]
    fn set(&mut self, k: usize, value: O) {
        self.as_mut_slice().set(k, value);
    }
    #[inline(always)]
    fn group<const L: usize>(&mut self, k: usize) -> Option<&mut [O; L]> {
        self.as_mut_slice().group(k)
    }
}

/// One slice per value; the number of results is the first slice's length.
impl<T, const M: usize> StatesMut<[T; M]> for [&mut [T]; M] {
    #[inline(always)]
    fn count(&self) -> usize {
        self.first().map_or(0, |column| column.len())
    }
    #[inline(always)]
    fn ragged(&self) -> Option<(usize, usize)> {
        ragged(self.iter().map(|column| column.len()))
    }
    #[inline(always)]
    fn set(&mut self, k: usize, value: [T; M]) {
        for (column, x) in self.iter_mut().zip(value) {
            column[k] = x;
        }
    }
}

/// Through a mutable reference (a chunk of results is one).
impl<O, S: StatesMut<O> + ?Sized> StatesMut<O> for &mut S {
    #[inline(always)]
    fn count(&self) -> usize {
        (**self).count()
    }
    #[inline(always)]
    fn ragged(&self) -> Option<(usize, usize)> {
        (**self).ragged()
    }
    #[inline(always)]
    fn set(&mut self, k: usize, value: O) {
        (**self).set(k, value);
    }
    #[inline(always)]
    fn group<const L: usize>(&mut self, k: usize) -> Option<&mut [O; L]> {
        (**self).group(k)
    }
}
