//! The transition matrix in the layout that suits its shape. A left-right model's A is zero
//! outside a few diagonals, and a zero stays zero under re-estimation, so storing just those
//! diagonals cuts the work of every recursion from W² to W·D; any other A is dense.

/// What the recursions need of A, for vectors of `W` states.
pub(crate) trait Transitions<const W: usize>: Send + Sync {
    /// Sums of outer products, laid out like A is stored.
    type Sums: Send;
    /// `prevᵀ A`.
    fn forward(&self, prev: &[f64; W]) -> [f64; W];
    /// `A w`.
    fn backward(&self, w: &[f64; W]) -> [f64; W];
    /// Adds the outer product `alpha ⊗ w` where A may be non-zero, into `sums` (laid out
    /// like this type's own storage).
    fn add_outer(&self, alpha: &[f64; W], w: &[f64; W], sums: &mut Self::Sums);
    /// A zeroed accumulator for [`Self::add_outer`].
    fn zero_sums(&self) -> Self::Sums;
    /// `into += from`.
    fn add_sums(into: &mut Self::Sums, from: &Self::Sums);
    /// `sums` (from [`Self::add_outer`]) times a_ij, as a dense row-major `n × n` matrix.
    fn expected_transitions(&self, sums: &Self::Sums, n: usize) -> Vec<f64>;
}

/// A as `W` rows of `W`.
pub(crate) struct Dense<const W: usize> {
    rows: Vec<[f64; W]>,
}

impl<const W: usize> Dense<W> {
    pub fn new(transmat: &[f64], n: usize) -> Self {
        let mut rows = vec![[0.0; W]; W];
        for (i, row) in rows.iter_mut().enumerate().take(n) {
            row[..n].copy_from_slice(&transmat[i * n..(i + 1) * n]);
        }
        Self { rows }
    }
}

impl<const W: usize> Transitions<W> for Dense<W> {
    type Sums = Vec<[f64; W]>;

    #[inline(always)]
    fn forward(&self, prev: &[f64; W]) -> [f64; W] {
        let mut next = [0.0; W];
        for (&p, row) in prev.iter().zip(&self.rows) {
            for j in 0..W {
                next[j] += p * row[j];
            }
        }
        next
    }

    #[inline(always)]
    fn backward(&self, w: &[f64; W]) -> [f64; W] {
        let mut beta = [0.0; W];
        for (i, row) in self.rows.iter().enumerate() {
            let mut sum = 0.0;
            for j in 0..W {
                sum += row[j] * w[j];
            }
            beta[i] = sum;
        }
        beta
    }

    #[inline(always)]
    fn add_outer(&self, alpha: &[f64; W], w: &[f64; W], sums: &mut Self::Sums) {
        for (&a, row) in alpha.iter().zip(sums.iter_mut()) {
            for j in 0..W {
                row[j] += a * w[j];
            }
        }
    }

    fn zero_sums(&self) -> Self::Sums {
        vec![[0.0; W]; W]
    }

    fn add_sums(into: &mut Self::Sums, from: &Self::Sums) {
        add_rows(into, from);
    }

    fn expected_transitions(&self, sums: &Self::Sums, n: usize) -> Vec<f64> {
        (0..n).flat_map(|i| (0..n).map(move |j| sums[i][j] * self.rows[i][j])).collect()
    }
}

/// A upper-banded: `diagonals[d][i]` is a_{i, i+d} for d < D (a left-right model with
/// D − 1 links).
pub(crate) struct Banded<const W: usize, const D: usize> {
    diagonals: [[f64; W]; D],
}

impl<const W: usize, const D: usize> Banded<W, D> {
    /// `None` when A has a non-zero entry outside the D diagonals.
    pub fn new(transmat: &[f64], n: usize) -> Option<Self> {
        let mut diagonals = [[0.0; W]; D];
        for i in 0..n {
            for j in 0..n {
                let a = transmat[i * n + j];
                if j >= i && j - i < D {
                    diagonals[j - i][i] = a;
                } else if a != 0.0 {
                    return None;
                }
            }
        }
        Some(Self { diagonals })
    }
}

impl<const W: usize, const D: usize> Transitions<W> for Banded<W, D> {
    type Sums = [[f64; W]; D];

    #[inline(always)]
    fn forward(&self, prev: &[f64; W]) -> [f64; W] {
        let mut next = [0.0; W];
        for (d, diagonal) in self.diagonals.iter().enumerate() {
            for i in 0..W - d.min(W) {
                next[i + d] += prev[i] * diagonal[i];
            }
        }
        next
    }

    #[inline(always)]
    fn backward(&self, w: &[f64; W]) -> [f64; W] {
        let mut beta = [0.0; W];
        for (d, diagonal) in self.diagonals.iter().enumerate() {
            for i in 0..W - d.min(W) {
                beta[i] += diagonal[i] * w[i + d];
            }
        }
        beta
    }

    #[inline(always)]
    fn add_outer(&self, alpha: &[f64; W], w: &[f64; W], sums: &mut Self::Sums) {
        for (d, row) in sums.iter_mut().enumerate() {
            for i in 0..W - d.min(W) {
                row[i] += alpha[i] * w[i + d];
            }
        }
    }

    fn zero_sums(&self) -> Self::Sums {
        [[0.0; W]; D]
    }

    fn add_sums(into: &mut Self::Sums, from: &Self::Sums) {
        add_rows(into, from);
    }

    fn expected_transitions(&self, sums: &Self::Sums, n: usize) -> Vec<f64> {
        let mut dense = vec![0.0; n * n];
        for (d, (sum, diagonal)) in sums.iter().zip(&self.diagonals).enumerate() {
            for i in 0..n.saturating_sub(d) {
                dense[i * n + i + d] = sum[i] * diagonal[i];
            }
        }
        dense
    }
}

/// `into += from`, row by row.
pub(crate) fn add_rows<const W: usize>(into: &mut [[f64; W]], from: &[[f64; W]]) {
    for (a, b) in into.iter_mut().zip(from) {
        for j in 0..W {
            a[j] += b[j];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const A: [f64; 9] = [0.5, 0.3, 0.2, 0.0, 0.6, 0.4, 0.0, 0.0, 1.0];

    #[test]
    fn banded_and_dense_agree() {
        let dense = Dense::<4>::new(&A, 3);
        let banded = Banded::<4, 3>::new(&A, 3).unwrap();
        let v = [0.2, 0.3, 0.5, 0.0];
        assert_eq!(dense.forward(&v), banded.forward(&v));
        let close = |a: [f64; 4], b: [f64; 4]| a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-15);
        assert!(close(dense.backward(&v), banded.backward(&v)));
        let (mut ds, mut bs) = (dense.zero_sums(), banded.zero_sums());
        dense.add_outer(&v, &[1.0, 2.0, 3.0, 0.0], &mut ds);
        banded.add_outer(&v, &[1.0, 2.0, 3.0, 0.0], &mut bs);
        assert_eq!(dense.expected_transitions(&ds, 3), banded.expected_transitions(&bs, 3));
    }

    #[test]
    fn banded_refuses_entries_outside_its_diagonals() {
        assert!(Banded::<3, 2>::new(&A, 3).is_none());
        assert!(Banded::<3, 1>::new(&[0.5, 0.5, 0.0, 1.0], 2).is_none());
    }
}
