//! Lloyd's k-means refinement: parallel assignment that skips points Hamerly's bounds keep in
//! their cells, and sums reduced in a fixed order.

use rayon::prelude::*;

use crate::bounds::{Bounds, Moves};
use crate::kdtree::KdTree;
use crate::points::{Points, distance2};

/// Points per parallel work item; fixed so that sums are added in one order whatever the
/// number of threads.
const POINTS_PER_CHUNK: usize = 4096;

/// When refinement stops.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stopping {
    /// Stop once the relative drop in distortion, (D_prev − D) / D, is at most this.
    pub tol: f64,
    /// Lloyd iterations at the most.
    pub max_iter: usize,
}

/// What one refinement did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Refinement {
    /// Mean squared distance of the points to the final codewords.
    pub distortion: f64,
    pub iterations: usize,
    /// Cells that were found empty and re-seeded.
    pub reseeded: usize,
}

struct CellSums {
    sums: Vec<f64>,
    counts: Vec<usize>,
    squared_error: f64,
    changed: usize,
}

impl CellSums {
    fn zeros(k: usize, dim: usize) -> Self {
        Self { sums: vec![0.0; k * dim], counts: vec![0; k], squared_error: 0.0, changed: 0 }
    }

    fn add(&mut self, other: &Self) {
        self.sums.iter_mut().zip(&other.sums).for_each(|(a, b)| *a += b);
        self.counts.iter_mut().zip(&other.counts).for_each(|(a, b)| *a += b);
        self.squared_error += other.squared_error;
        self.changed += other.changed;
    }
}

/// Assigns every point to its nearest codeword (updating `labels`, which also serve as search
/// hints) and sums the cells.
fn assign(points: Points, codewords: &[f64], labels: &mut [usize], bounds: &mut Bounds) -> CellSums {
    let dim = points.dim();
    let k = codewords.len() / dim;
    bounds.advance(codewords);
    let moves = &bounds.moves;
    let tree = KdTree::new(codewords, dim);
    let partial: Vec<CellSums> = labels
        .par_chunks_mut(POINTS_PER_CHUNK)
        .zip(bounds.lower.par_chunks_mut(POINTS_PER_CHUNK))
        .enumerate()
        .map(|(chunk, (chunk_labels, chunk_lower))| {
            let first = chunk * POINTS_PER_CHUNK;
            // The tracker's dimensions compiled apart, so their loops unroll; same arithmetic.
            match dim {
                2 => assign_chunk::<2>(points, first, codewords, chunk_labels, chunk_lower, &tree, moves),
                3 => assign_chunk::<3>(points, first, codewords, chunk_labels, chunk_lower, &tree, moves),
                _ => assign_chunk::<0>(points, first, codewords, chunk_labels, chunk_lower, &tree, moves),
            }
        })
        .collect();
    let mut total = CellSums::zeros(k, dim);
    for cells in &partial {
        total.add(cells);
    }
    total
}

/// Assigns the points from `first` on (one per label) and sums their cells. `DIM` is the
/// dimension when known at compile time, 0 otherwise.
fn assign_chunk<const DIM: usize>(
    points: Points,
    first: usize,
    codewords: &[f64],
    labels: &mut [usize],
    lower: &mut [f64],
    tree: &KdTree,
    moves: &Moves,
) -> CellSums {
    let dim = if DIM == 0 { points.dim() } else { DIM };
    let k = codewords.len() / dim;
    let mut cells = CellSums::zeros(k, dim);
    for (offset, (label, lower)) in labels.iter_mut().zip(lower).enumerate() {
        let point = &points.raw()[(first + offset) * dim..(first + offset + 1) * dim];
        let own = (*label).min(k - 1);
        let own_d2 = distance2(point, &codewords[own * dim..(own + 1) * dim]);
        let (nearest, d2) = if let Some(bound) = moves.still_nearest(dim, point, own, own_d2, *lower) {
            *lower = bound;
            (own, own_d2)
        } else {
            let (nearest, d2, second_d2) = tree.nearest_two(point, own);
            *lower = second_d2.sqrt();
            (nearest, d2)
        };
        cells.changed += usize::from(nearest != *label);
        *label = nearest;
        cells.squared_error += d2;
        cells.counts[nearest] += 1;
        cells.sums[nearest * dim..(nearest + 1) * dim].iter_mut().zip(point).for_each(|(s, x)| *s += x);
    }
    cells
}

/// Refines `codewords` in place on `points` by Lloyd iterations, starting from the given
/// `labels` as search hints. A cell left empty is re-seeded with the point farthest from its
/// codeword in the largest cell.
pub fn refine(points: Points, codewords: &mut [f64], labels: &mut [usize], stopping: Stopping) -> Refinement {
    let dim = points.dim();
    let n = points.len() as f64;
    let mut previous_distortion = f64::INFINITY;
    let mut iterations = 0;
    let mut reseeded = 0;
    let mut reseeded_last_time = 0;
    let mut bounds = Bounds::new(points.len(), dim);
    while iterations < stopping.max_iter {
        let cells = assign(points, codewords, labels, &mut bounds);
        let distortion = cells.squared_error / n;
        if iterations > 0 && cells.changed == 0 && reseeded_last_time == 0 {
            // Same cells as last time: the codewords are already their means.
            return Refinement { distortion, iterations, reseeded };
        }
        iterations += 1;
        for (c, codeword) in codewords.chunks_exact_mut(dim).enumerate() {
            if cells.counts[c] > 0 {
                let count = cells.counts[c] as f64;
                codeword.iter_mut().zip(&cells.sums[c * dim..]).for_each(|(x, s)| *x = s / count);
            }
        }
        reseeded_last_time = reseed_empty_cells(points, codewords, labels, &cells.counts);
        reseeded += reseeded_last_time;
        if reseeded_last_time > 0 {
            bounds.forget();
        }
        let drop = (previous_distortion - distortion) / distortion;
        if reseeded_last_time == 0 && (distortion == 0.0 || drop <= stopping.tol) {
            break;
        }
        previous_distortion = distortion;
    }
    let distortion = assign(points, codewords, labels, &mut bounds).squared_error / n;
    Refinement { distortion, iterations, reseeded }
}

/// Mean squared distance of `points` to their nearest codewords (labels are updated).
pub fn distortion(points: Points, codewords: &[f64], labels: &mut [usize]) -> f64 {
    let tree = KdTree::new(codewords, points.dim());
    let squared_errors: Vec<f64> = labels
        .par_chunks_mut(POINTS_PER_CHUNK)
        .enumerate()
        .map(|(chunk, chunk_labels)| {
            let mut sum = 0.0;
            for (offset, label) in chunk_labels.iter_mut().enumerate() {
                let (nearest, d2) = tree.nearest(points.get(chunk * POINTS_PER_CHUNK + offset), *label);
                *label = nearest;
                sum += d2;
            }
            sum
        })
        .collect();
    squared_errors.iter().sum::<f64>() / points.len() as f64
}

/// Moves each empty codeword onto the point farthest from its codeword in the currently
/// largest cell, taking that point out of the cell. Returns how many were moved.
fn reseed_empty_cells(points: Points, codewords: &mut [f64], labels: &mut [usize], counts: &[usize]) -> usize {
    let dim = points.dim();
    let mut counts = counts.to_vec();
    let empty: Vec<usize> = (0..counts.len()).filter(|&c| counts[c] == 0).collect();
    for &cell in &empty {
        let largest = (0..counts.len()).rev().max_by_key(|&c| counts[c]).unwrap_or(0);
        if counts[largest] < 2 {
            break;
        }
        let farthest = (0..points.len())
            .filter(|&p| labels[p] == largest)
            .map(|p| (p, distance2(points.get(p), &codewords[largest * dim..(largest + 1) * dim])))
            .fold((usize::MAX, f64::NEG_INFINITY), |best, c| if c.1 > best.1 { c } else { best })
            .0;
        codewords[cell * dim..(cell + 1) * dim].copy_from_slice(points.get(farthest));
        labels[farthest] = cell;
        counts[largest] -= 1;
        counts[cell] = 1;
    }
    empty.len()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_obvious_clusters_converge_to_their_means() {
        let data = [0.0, 0.0, 0.0, 1.0, 10.0, 10.0, 10.0, 11.0];
        let points = Points::new(&data, 2).unwrap();
        let mut codewords = vec![1.0, 1.0, 9.0, 9.0];
        let mut labels = vec![0; 4];
        let r = refine(points, &mut codewords, &mut labels, Stopping { tol: 0.0, max_iter: 50 });
        assert_eq!(codewords, vec![0.0, 0.5, 10.0, 10.5]);
        assert_eq!(labels, vec![0, 0, 1, 1]);
        assert!((r.distortion - 0.25).abs() < 1e-15);
    }

    #[test]
    fn an_empty_cell_is_reseeded_from_the_largest_cell() {
        let data = [0.0, 1.0, 2.0, 10.0];
        let points = Points::new(&data, 1).unwrap();
        // Codeword 1 sits where no point is nearest to it.
        let mut codewords = vec![3.0, 100.0];
        let mut labels = vec![0; 4];
        let r = refine(points, &mut codewords, &mut labels, Stopping { tol: 0.0, max_iter: 50 });
        assert_eq!(r.reseeded, 1);
        assert_eq!(codewords, vec![1.0, 10.0]);
    }
}
