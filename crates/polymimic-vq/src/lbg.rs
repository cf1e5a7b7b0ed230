//! The Linde-Buzo-Gray algorithm: grow a codebook from the data's mean by splitting every
//! codeword in two and refining with k-means, until it has the size asked for.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use crate::error::VqParamsError;
use crate::lloyd::{Stopping, refine};
use crate::points::{Points, distance2};

/// How a codebook is grown. Build with [`LbgParams::new`], then [`LbgParams::check`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct LbgParams {
    pub size: usize,
    /// k-means at each size stops once the relative drop in distortion is at most this.
    pub tol: f64,
    /// Lloyd iterations at the most, at each size.
    pub max_iter: usize,
    /// A codeword c splits into c ± ε·(1 + |c|)⊙s, componentwise.
    pub split_epsilon: f64,
    /// Seeds the sign pattern s of each split, so successive splits do not all separate
    /// codewords along the same diagonal.
    pub seed: u64,
}

impl LbgParams {
    /// The thesis's codebook: 512 codewords, ε = 1e-3.
    #[must_use]
    pub fn new(size: usize) -> Self {
        Self { size, tol: 1e-4, max_iter: 100, split_epsilon: 1e-3, seed: 0 }
    }

    /// # Errors
    /// Names the field out of range.
    pub fn check(self) -> Result<Self, VqParamsError> {
        if self.size == 0 {
            return Err(VqParamsError::NoCodewords(self.size));
        }
        if !(self.tol.is_finite() && self.tol >= 0.0) {
            return Err(VqParamsError::BadTolerance(self.tol));
        }
        if !(self.split_epsilon > 0.0 && self.split_epsilon < 1.0) {
            return Err(VqParamsError::BadEpsilon(self.split_epsilon));
        }
        Ok(self)
    }
}

/// What growing the codebook did.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct LbgReport {
    pub distortion: f64,
    /// Lloyd iterations summed over every size.
    pub lloyd_iterations: usize,
    pub reseeded_cells: usize,
}

/// Grows a codebook of `params.size` codewords (row-major) on `points`.
///
/// # Errors
/// Fewer points than codewords.
pub fn grow(points: Points, params: LbgParams) -> Result<(Vec<f64>, LbgReport), VqParamsError> {
    let params = params.check()?;
    if points.len() < params.size {
        return Err(VqParamsError::TooFewPoints { size: params.size, n_points: points.len() });
    }
    let dim = points.dim();
    let mut rng = ChaCha8Rng::seed_from_u64(params.seed);
    let mut codewords = mean(points);
    let mut labels = vec![0usize; points.len()];
    let stopping = Stopping { tol: params.tol, max_iter: params.max_iter };
    let mut report = LbgReport::default();
    let mut count = 1;
    while count < params.size {
        let to_split = (params.size - count).min(count);
        let chosen = worst_cells(points, &codewords, &labels, to_split);
        let (split, first_child) = split(&codewords, dim, &chosen, params.split_epsilon, &mut rng);
        codewords = split;
        count = codewords.len() / dim;
        for label in &mut labels {
            *label = first_child[*label];
        }
        let refinement = refine(points, &mut codewords, &mut labels, stopping);
        report.lloyd_iterations += refinement.iterations;
        report.reseeded_cells += refinement.reseeded;
        report.distortion = refinement.distortion;
    }
    if params.size == 1 {
        report.distortion = crate::lloyd::distortion(points, &codewords, &mut labels);
    }
    Ok((codewords, report))
}

fn mean(points: Points) -> Vec<f64> {
    let mut sum = vec![0.0; points.dim()];
    for i in 0..points.len() {
        sum.iter_mut().zip(points.get(i)).for_each(|(s, x)| *s += x);
    }
    sum.iter().map(|s| s / points.len() as f64).collect()
}

/// The `count` cells with the largest total squared error (all of them when doubling).
fn worst_cells(points: Points, codewords: &[f64], labels: &[usize], count: usize) -> Vec<bool> {
    let dim = points.dim();
    let k = codewords.len() / dim;
    if count == k {
        return vec![true; k];
    }
    let mut error = vec![0.0; k];
    for (p, &label) in labels.iter().enumerate() {
        error[label] += distance2(points.get(p), &codewords[label * dim..(label + 1) * dim]);
    }
    let mut order: Vec<usize> = (0..k).collect();
    order.sort_by(|&a, &b| error[b].total_cmp(&error[a]).then(a.cmp(&b)));
    let mut chosen = vec![false; k];
    order.iter().take(count).for_each(|&c| chosen[c] = true);
    chosen
}

/// Splits the chosen codewords in two; returns the new codebook and, for each old codeword,
/// the index of its first child (used as every old member's search hint).
fn split(codewords: &[f64], dim: usize, chosen: &[bool], epsilon: f64, rng: &mut ChaCha8Rng) -> (Vec<f64>, Vec<usize>) {
    let mut grown = Vec::with_capacity(codewords.len() * 2);
    let mut first_child = Vec::with_capacity(chosen.len());
    for (c, codeword) in codewords.chunks_exact(dim).enumerate() {
        first_child.push(grown.len() / dim);
        if !chosen[c] {
            grown.extend_from_slice(codeword);
            continue;
        }
        let offset: Vec<f64> = codeword
            .iter()
            .map(|x| {
                let sign = if rng.random::<bool>() { 1.0 } else { -1.0 };
                sign * epsilon * (1.0 + x.abs())
            })
            .collect();
        grown.extend(codeword.iter().zip(&offset).map(|(x, o)| x - o));
        grown.extend(codeword.iter().zip(&offset).map(|(x, o)| x + o));
    }
    (grown, first_child)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(n_per_side: usize) -> Vec<f64> {
        let mut data = Vec::new();
        for i in 0..n_per_side {
            for j in 0..n_per_side {
                data.extend([i as f64, j as f64]);
            }
        }
        data
    }

    #[test]
    fn grows_exactly_the_size_asked_for_even_when_not_a_power_of_two() {
        let data = grid(20);
        let points = Points::new(&data, 2).unwrap();
        for size in [1, 2, 3, 7, 16, 50] {
            let (codewords, report) = grow(points, LbgParams::new(size)).unwrap();
            assert_eq!(codewords.len(), size * 2);
            assert!(report.distortion.is_finite());
        }
    }

    #[test]
    fn one_codeword_is_the_mean() {
        let data = [1.0, 2.0, 3.0, 6.0];
        let (codewords, report) = grow(Points::new(&data, 1).unwrap(), LbgParams::new(1)).unwrap();
        assert_eq!(codewords, vec![3.0]);
        assert!((report.distortion - 3.5).abs() < 1e-15);
    }

    #[test]
    fn distortion_falls_as_the_codebook_grows() {
        let data = grid(30);
        let points = Points::new(&data, 2).unwrap();
        let distortions: Vec<f64> =
            [1, 4, 16, 64].iter().map(|&s| grow(points, LbgParams::new(s)).unwrap().1.distortion).collect();
        assert!(distortions.windows(2).all(|w| w[1] < w[0]), "{distortions:?}");
    }

    #[test]
    fn as_many_codewords_as_distinct_points_quantise_without_error() {
        let data = [0.0, 5.0, 9.0, 20.0];
        let (mut codewords, report) = grow(Points::new(&data, 1).unwrap(), LbgParams::new(4)).unwrap();
        codewords.sort_by(f64::total_cmp);
        assert_eq!(codewords, data.to_vec());
        assert_eq!(report.distortion, 0.0);
    }

    #[test]
    fn too_few_points_is_an_error() {
        let data = [0.0, 1.0];
        assert_eq!(
            grow(Points::new(&data, 1).unwrap(), LbgParams::new(3)).unwrap_err(),
            VqParamsError::TooFewPoints { size: 3, n_points: 2 }
        );
    }

    include!(concat!(env!("CARGO_MANIFEST_DIR"), "/benches/common/points.rs"));

    fn tracker_like(n_points: usize) -> Vec<f64> {
        tracker_like_points(n_points, 2)
    }

    /// FNV-1a over the bits of every codeword, the iteration count and the distortion.
    fn fingerprint(data: &[f64], dim: usize, size: usize, seed: u64) -> u64 {
        let mut params = LbgParams::new(size);
        params.seed = seed;
        let (codewords, report) = grow(Points::new(data, dim).unwrap(), params).unwrap();
        let words = codewords.iter().map(|x| x.to_bits()).chain([
            report.lloyd_iterations as u64,
            report.reseeded_cells as u64,
            report.distortion.to_bits(),
        ]);
        words.fold(0xcbf2_9ce4_8422_2325, |hash, word| {
            word.to_le_bytes().iter().fold(hash, |h, &b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3))
        })
    }

    /// Guards every speed-up of the search and the update: the codebooks grown by the
    /// original implementation, bit for bit, whatever the number of threads.
    #[test]
    #[cfg_attr(debug_assertions, ignore = "minutes unoptimised: cargo test -p polymimic-vq --release")]
    fn codebooks_are_bit_identical_to_the_reference_implementations() {
        let data = tracker_like(20_000);
        let coarse: Vec<f64> = data.iter().map(|x| (x / 4.0).round()).collect();
        let flat: Vec<f64> = data.chunks_exact(3).flat_map(|p| [p[0], p[1]]).collect();
        let wide: Vec<f64> =
            data[..15_000].chunks_exact(3).flat_map(|p| [p[0], p[1], p[2], p[0] - p[1], p[2] * 0.5]).collect();
        let line: Vec<f64> = data.iter().step_by(3).copied().collect();
        let cases: [(&[f64], usize, usize, u64, u64); 5] = [
            (&data, 3, 512, 0, 0x2524_87de_90c5_0743),
            (&coarse, 3, 512, 0, 0x5452_e1ae_7e46_4b80),
            (&flat, 2, 100, 1, 0x29b2_d2fc_7c3b_0a5f),
            (&wide, 5, 64, 3, 0x8124_ec9b_3e93_b8c8),
            (&line, 1, 16, 0, 0xb9f5_b6fa_16ba_217e),
        ];
        for threads in [1, 3] {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            for &(points, dim, size, seed, expected) in &cases {
                let found = pool.install(|| fingerprint(points, dim, size, seed));
                assert_eq!(found, expected, "{dim}-D to {size} on {threads} threads");
            }
        }
    }
}
