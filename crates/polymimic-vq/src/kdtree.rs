//! Exact nearest-codeword search by a k-d tree over the codewords.
//!
//! In three dimensions a query visits a few dozen of the 512 codewords instead of all of
//! them; seeding the search with the point's previous codeword prunes most of the tree.

use crate::points::distance2;

const LEAF_SIZE: usize = 6;

#[derive(Debug, Clone)]
enum Node {
    Leaf { start: usize, end: usize },
    Split { dimension: usize, value: f64, below: usize, above: usize },
}

/// The nearest codeword so far and the squared distance to the nearest of the others.
struct Two {
    index: usize,
    d2: f64,
    second_d2: f64,
}

/// A k-d tree over a fixed set of codewords (it keeps its own copy of them).
#[derive(Debug, Clone)]
pub struct KdTree {
    codewords: Vec<f64>,
    dim: usize,
    /// Codeword indices, grouped so every leaf owns a contiguous run.
    order: Vec<usize>,
    nodes: Vec<Node>,
}

impl KdTree {
    /// Builds the tree over row-major `codewords` of dimension `dim` (at least one).
    #[must_use]
    pub fn new(codewords: &[f64], dim: usize) -> Self {
        let count = codewords.len() / dim;
        let mut tree = Self { codewords: codewords.to_vec(), dim, order: (0..count).collect(), nodes: Vec::new() };
        tree.build(0, count);
        tree
    }

    fn codeword(&self, index: usize) -> &[f64] {
        &self.codewords[index * self.dim..(index + 1) * self.dim]
    }

    fn build(&mut self, start: usize, end: usize) -> usize {
        if end - start <= LEAF_SIZE {
            self.nodes.push(Node::Leaf { start, end });
            return self.nodes.len() - 1;
        }
        // Split the widest dimension at its median.
        let dimension = (0..self.dim)
            .max_by(|&a, &b| self.spread(start, end, a).total_cmp(&self.spread(start, end, b)))
            .unwrap_or(0);
        let middle = start + (end - start) / 2;
        let (codewords, dim) = (&self.codewords, self.dim);
        self.order[start..end].select_nth_unstable_by(middle - start, |&a, &b| {
            codewords[a * dim + dimension].total_cmp(&codewords[b * dim + dimension])
        });
        let value = self.codeword(self.order[middle])[dimension];
        let node = self.nodes.len();
        self.nodes.push(Node::Leaf { start, end });
        let below = self.build(start, middle);
        let above = self.build(middle, end);
        self.nodes[node] = Node::Split { dimension, value, below, above };
        node
    }

    fn spread(&self, start: usize, end: usize, dimension: usize) -> f64 {
        let values = self.order[start..end].iter().map(|&i| self.codeword(i)[dimension]);
        let (low, high) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
        high - low
    }

    /// The nearest codeword to `point` and its squared distance; ties go to the lowest index.
    /// `hint` (any codeword index, usually the point's previous one) only speeds the search.
    #[must_use]
    pub fn nearest(&self, point: &[f64], hint: usize) -> (usize, f64) {
        let hint = hint.min(self.order.len() - 1);
        let mut best = (hint, distance2(point, self.codeword(hint)));
        self.search(0, point, &mut best);
        best
    }

    /// As [`Self::nearest`], and the squared distance to the nearest of all the other
    /// codewords (infinite when there is only one): a lower bound that lets later Lloyd
    /// iterations skip the search while the codewords move less than the gap.
    #[must_use]
    pub fn nearest_two(&self, point: &[f64], hint: usize) -> (usize, f64, f64) {
        let hint = hint.min(self.order.len() - 1);
        let mut best = Two { index: hint, d2: distance2(point, self.codeword(hint)), second_d2: f64::INFINITY };
        self.search_two(0, point, &mut best);
        (best.index, best.d2, best.second_d2)
    }

    fn search_two(&self, node: usize, point: &[f64], best: &mut Two) {
        match self.nodes[node] {
            Node::Leaf { start, end } => {
                for &index in &self.order[start..end] {
                    if index == best.index {
                        continue;
                    }
                    let d = distance2(point, self.codeword(index));
                    if d < best.d2 || (d == best.d2 && index < best.index) {
                        best.second_d2 = best.d2;
                        best.index = index;
                        best.d2 = d;
                    } else if d < best.second_d2 {
                        best.second_d2 = d;
                    }
                }
            }
            Node::Split { dimension, value, below, above } => {
                let offset = point[dimension] - value;
                let (near, far) = if offset < 0.0 { (below, above) } else { (above, below) };
                self.search_two(near, point, best);
                // Every codeword beyond the plane is at least offset² away (in floating point
                // too: rounding is monotonic); equal still visits, for the ties.
                if offset * offset <= best.second_d2 {
                    self.search_two(far, point, best);
                }
            }
        }
    }

    fn search(&self, node: usize, point: &[f64], best: &mut (usize, f64)) {
        match self.nodes[node] {
            Node::Leaf { start, end } => {
                for &index in &self.order[start..end] {
                    let d = distance2(point, self.codeword(index));
                    if d < best.1 || (d == best.1 && index < best.0) {
                        *best = (index, d);
                    }
                }
            }
            Node::Split { dimension, value, below, above } => {
                let offset = point[dimension] - value;
                let (near, far) = if offset < 0.0 { (below, above) } else { (above, below) };
                self.search(near, point, best);
                // Equal distance still visits, so ties resolve to the lowest index.
                if offset * offset <= best.1 {
                    self.search(far, point, best);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn brute_force(codewords: &[f64], dim: usize, point: &[f64]) -> (usize, f64) {
        (0..codewords.len() / dim)
            .map(|i| (i, distance2(point, &codewords[i * dim..(i + 1) * dim])))
            .fold((usize::MAX, f64::INFINITY), |b, c| if c.1 < b.1 { c } else { b })
    }

    #[test]
    fn agrees_with_brute_force_in_several_dimensions() {
        let mut rng = ChaCha8Rng::seed_from_u64(4);
        for dim in [1, 2, 3, 5] {
            let codewords: Vec<f64> = (0..200 * dim).map(|_| rng.random::<f64>() * 10.0).collect();
            let tree = KdTree::new(&codewords, dim);
            for hint in [0, 57, 199] {
                let point: Vec<f64> = (0..dim).map(|_| rng.random::<f64>() * 12.0 - 1.0).collect();
                assert_eq!(tree.nearest(&point, hint), brute_force(&codewords, dim, &point));
            }
        }
    }

    #[test]
    fn nearest_two_agrees_with_brute_force_on_the_nearest_and_the_runner_up() {
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        for dim in [1, 2, 3, 5] {
            // Coarse coordinates, so that ties between codewords are common.
            let codewords: Vec<f64> = (0..150 * dim).map(|_| f64::from(rng.random_range(0..8u8))).collect();
            let tree = KdTree::new(&codewords, dim);
            for hint in [0, 31, 149] {
                let point: Vec<f64> = (0..dim).map(|_| f64::from(rng.random_range(0..16u8)) * 0.5).collect();
                let (index, d2, second_d2) = tree.nearest_two(&point, hint);
                assert_eq!((index, d2), brute_force(&codewords, dim, &point));
                let runner_up = (0..150)
                    .filter(|&i| i != index)
                    .map(|i| distance2(&point, &codewords[i * dim..(i + 1) * dim]))
                    .fold(f64::INFINITY, f64::min);
                assert_eq!(second_d2, runner_up);
            }
        }
        assert_eq!(KdTree::new(&[2.0], 1).nearest_two(&[0.0], 0), (0, 4.0, f64::INFINITY));
    }

    #[test]
    fn ties_go_to_the_lowest_index_whatever_the_hint() {
        let codewords = [1.0, -1.0, 1.0, -1.0, 5.0];
        let tree = KdTree::new(&codewords, 1);
        assert_eq!(tree.nearest(&[0.0], 3), (0, 1.0));
    }
}
