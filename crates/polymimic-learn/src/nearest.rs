//! The k nearest of a fixed set of points, by squared Euclidean distance, nearest first; ties
//! go to the earlier point. The answer is defined by that order alone, so what is summed over
//! it (a state's value, the ball's response) does not depend on how the search runs: a k-d
//! tree finds the same points, with the same distances to the bit, as sorting them all would.

use std::cmp::Ordering;

/// Points per leaf: below this a scan is cheaper than another split.
const LEAF_POINTS: usize = 12;

/// A found point: its squared distance and its index among the points given.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Found(f64, usize);

impl Eq for Found {}

impl Ord for Found {
    fn cmp(&self, other: &Self) -> Ordering {
        self.0.total_cmp(&other.0).then(self.1.cmp(&other.1))
    }
}

impl PartialOrd for Found {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// (a − b)² summed over the coordinates, in their order.
fn squared_distance<const D: usize>(a: &[f64; D], b: &[f64; D]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y).powi(2)).sum()
}

/// A box of the tree: the bounds of its points, and either its two halves or (a leaf) none.
#[derive(Debug, Clone, PartialEq)]
struct Node<const D: usize> {
    low: [f64; D],
    high: [f64; D],
    /// Its points: `start..end` of the tree's order.
    start: usize,
    end: usize,
    halves: Option<(usize, usize)>,
}

impl<const D: usize> Node<D> {
    /// No point of the box is nearer `query` than this. Each term is the gap to the box along
    /// one coordinate, which no point's own difference undercuts (rounding is monotone), so
    /// the sum never exceeds a point's [`squared_distance`] and pruning on it loses nothing.
    fn bound(&self, query: &[f64; D]) -> f64 {
        (0..D)
            .map(|d| {
                let q = query[d];
                if q < self.low[d] {
                    (self.low[d] - q).powi(2)
                } else if q > self.high[d] {
                    (q - self.high[d]).powi(2)
                } else {
                    0.0
                }
            })
            .sum()
    }
}

/// Points to search, with a k-d tree over them (none if a point is not finite: then every
/// search is a scan).
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct NearestIndex<const D: usize> {
    /// The points, in tree order, each with its index among the points given.
    points: Vec<([f64; D], usize)>,
    nodes: Vec<Node<D>>,
}

impl<const D: usize> NearestIndex<D> {
    pub(crate) fn new(points: impl Iterator<Item = [f64; D]>) -> Self {
        let points: Vec<([f64; D], usize)> = points.enumerate().map(|(i, p)| (p, i)).collect();
        let mut index = Self { points, nodes: Vec::new() };
        if !index.points.is_empty() && index.points.iter().all(|(p, _)| p.iter().all(|v| v.is_finite())) {
            index.split(0, index.points.len());
        }
        index
    }

    /// Builds the node over `start..end` (and its halves); returns its position.
    fn split(&mut self, start: usize, end: usize) -> usize {
        let slice = &mut self.points[start..end];
        let mut low = slice[0].0;
        let mut high = slice[0].0;
        for (p, _) in slice.iter() {
            for d in 0..D {
                low[d] = low[d].min(p[d]);
                high[d] = high[d].max(p[d]);
            }
        }
        let at = self.nodes.len();
        self.nodes.push(Node { low, high, start, end, halves: None });
        if end - start > LEAF_POINTS {
            let widest = (0..D).max_by(|&a, &b| (high[a] - low[a]).total_cmp(&(high[b] - low[b]))).unwrap_or(0);
            let middle = (end - start) / 2;
            slice.select_nth_unstable_by(middle, |a, b| a.0[widest].total_cmp(&b.0[widest]));
            let first = self.split(start, start + middle);
            let second = self.split(start + middle, end);
            self.nodes[at].halves = Some((first, second));
        }
        at
    }

    /// The `k` points nearest `query` (all of them if there are fewer): their squared
    /// distances and indices, nearest first, ties to the earlier point.
    pub(crate) fn nearest(&self, query: &[f64; D], k: usize) -> Vec<(f64, usize)> {
        let k = k.min(self.points.len());
        if k == 0 {
            return Vec::new();
        }
        let mut best = Vec::with_capacity(k + 1);
        if self.nodes.is_empty() || !query.iter().all(|v| v.is_finite()) {
            for &(p, i) in &self.points {
                keep(&mut best, Found(squared_distance(&p, query), i), k);
            }
        } else {
            self.search(0, query, k, &mut best);
        }
        best.into_iter().map(|Found(d2, i)| (d2, i)).collect()
    }

    fn search(&self, at: usize, query: &[f64; D], k: usize, best: &mut Vec<Found>) {
        let node = &self.nodes[at];
        match node.halves {
            None => {
                for &(p, i) in &self.points[node.start..node.end] {
                    keep(best, Found(squared_distance(&p, query), i), k);
                }
            }
            Some((first, second)) => {
                let (near, far) = {
                    let (a, b) = (self.nodes[first].bound(query), self.nodes[second].bound(query));
                    if b < a { ((second, b), (first, a)) } else { ((first, a), (second, b)) }
                };
                for (child, bound) in [near, far] {
                    // A box exactly as far as the worst kept point may still hold a tie with
                    // an earlier index: only a farther one is skipped.
                    let skip = best.len() == k && best.last().is_some_and(|worst| bound > worst.0);
                    if !skip {
                        self.search(child, query, k, best);
                    }
                }
            }
        }
    }
}

/// Keeps `found` among the `k` best so far, which are in order, nearest first (k is a handful:
/// shifting a few entries beats a heap).
fn keep(best: &mut Vec<Found>, found: Found, k: usize) {
    if best.len() == k {
        if best.last().is_some_and(|worst| found >= *worst) {
            return;
        }
        best.pop();
    }
    let at = best.partition_point(|kept| *kept < found);
    best.insert(at, found);
}

/// Every point's distance, sorted, the first k: the answer by definition, for tests.
#[cfg(test)]
pub(crate) fn brute_force_nearest<const D: usize>(
    points: impl Iterator<Item = [f64; D]>,
    query: &[f64; D],
    k: usize,
) -> Vec<(f64, usize)> {
    let mut all: Vec<(f64, usize)> = points.enumerate().map(|(i, p)| (squared_distance(&p, query), i)).collect();
    all.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    all.truncate(k);
    all
}

#[cfg(test)]
mod tests {
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    use super::*;

    #[test]
    fn the_nearest_are_found_nearest_first_and_ties_go_to_the_earlier_point() {
        let points = [[0.0, 0.0], [3.0, 0.0], [1.0, 0.0], [-1.0, 0.0], [10.0, 0.0]];
        let index = NearestIndex::new(points.into_iter());
        // 1.0 and −1.0 tie: the earlier comes first.
        assert_eq!(index.nearest(&[0.0, 0.0], 3), vec![(0.0, 0), (1.0, 2), (1.0, 3)]);
        assert_eq!(index.nearest(&[0.0, 0.0], 2), vec![(0.0, 0), (1.0, 2)], "of two tied points the earlier is kept");
        assert_eq!(index.nearest(&[0.0, 0.0], 9).len(), 5);
        assert!(NearestIndex::<2>::new(std::iter::empty()).nearest(&[0.0, 0.0], 3).is_empty());
    }

    /// Many points on a coarse lattice (so distances tie often), in 2 and 6 dimensions, at
    /// every k up to beyond their number: the tree gives the brute-force answer bit for bit.
    #[test]
    fn the_tree_finds_what_sorting_every_point_finds() {
        fn check<const D: usize>(rng: &mut ChaCha8Rng, n: usize) {
            let lattice = |rng: &mut ChaCha8Rng| f64::from(rng.random_range(-6_i32..=6)) * 12.5;
            let points: Vec<[f64; D]> = (0..n).map(|_| std::array::from_fn(|_| lattice(rng))).collect();
            let index = NearestIndex::new(points.iter().copied());
            for _ in 0..200 {
                let query: [f64; D] = std::array::from_fn(|_| lattice(rng) + rng.random_range(-7.0..7.0));
                for k in [1, 2, 8, 13, n, n + 3] {
                    let found = index.nearest(&query, k);
                    let expected = brute_force_nearest(points.iter().copied(), &query, k);
                    assert_eq!(found.len(), expected.len());
                    for (a, b) in found.iter().zip(&expected) {
                        assert_eq!((a.0.to_bits(), a.1), (b.0.to_bits(), b.1), "D={D} n={n} k={k} {query:?}");
                    }
                }
            }
        }
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        for n in [1, 7, 12, 13, 40, 500] {
            check::<2>(&mut rng, n);
            check::<6>(&mut rng, n);
        }
    }

    #[test]
    fn a_point_or_query_that_is_not_finite_is_searched_by_scanning_with_the_same_order() {
        let points = [[0.0, 0.0], [f64::NAN, 1.0], [2.0, 2.0], [1.0, 1.0]];
        let index = NearestIndex::new(points.into_iter());
        let found: Vec<usize> = index.nearest(&[0.0, 0.0], 3).iter().map(|p| p.1).collect();
        assert_eq!(found, vec![0, 3, 2], "NaN sorts after every number");
        let finite = NearestIndex::new([[0.0, 0.0], [1.0, 1.0]].into_iter());
        assert_eq!(finite.nearest(&[f64::NAN, 0.0], 1).len(), 1);
    }
}
