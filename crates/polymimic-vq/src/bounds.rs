//! Hamerly's bounds for Lloyd's assignment step, exact to the last bit.
//!
//! Every point keeps a lower bound on its distance to every codeword other than its own.
//! While its own codeword is nearer than that bound the point stays in its cell without a
//! search; near convergence the codewords barely move and most points stay. After the
//! codewords move, the bound falls by the largest move — except that the few codewords that
//! moved most are measured from the point directly instead, so that one fast codeword does
//! not send every point back to the search.
//!
//! The bounds only ever decide "stays": they are kept a little below the truth (by more than
//! any rounding), and a point stays only when its codeword is nearer than the bound by a
//! relative margin of [`SLACK`], so that exact arithmetic and floating point agree that it is
//! strictly the nearest. Any doubt means a search, and the search is exact; so the labels,
//! and everything summed from them, are those of a search of every point.

use crate::points::distance2;

/// Relative margin by which a point's own codeword must beat the bound: far above the
/// rounding of the squared distances compared (a few units in 1e-16).
const SLACK: f64 = 1e-9;

/// Codewords measured from each point directly rather than through the bound.
const FAST: usize = 4;

/// The moves of the codewords since the last assignment, shared by every point.
pub struct Moves {
    dim: usize,
    /// The codewords that moved most, fastest first, and their new coordinates.
    fast: Vec<usize>,
    fast_codewords: Vec<f64>,
    /// An upper bound on the move of every other codeword.
    slow_drift: f64,
    /// Relative rounding of one distance or one subtraction, rounded up generously.
    rounding: f64,
}

impl Moves {
    /// The new lower bound when the point's own codeword (at `own_d2`) is still strictly
    /// the nearest; `None` when the point must be searched.
    /// `dim` is the points' dimension (a constant where the caller is compiled for one).
    #[inline]
    pub fn still_nearest(&self, dim: usize, point: &[f64], own: usize, own_d2: f64, lower: f64) -> Option<f64> {
        let own_d = own_d2.sqrt() * (1.0 + SLACK);
        let mut bound = (lower - self.slow_drift) - (lower.abs() + self.slow_drift) * self.rounding;
        // NaN (never searched) and +∞ − ∞ fail the comparison, as they should.
        let below_bound = own_d < bound;
        if !below_bound {
            return None;
        }
        let mut nearest_fast_d2 = f64::INFINITY;
        for (codeword, &index) in self.fast_codewords.chunks_exact(dim).zip(&self.fast) {
            if index != own {
                nearest_fast_d2 = nearest_fast_d2.min(distance2(point, codeword));
            }
        }
        let nearest_fast = nearest_fast_d2.sqrt() * (1.0 - self.rounding);
        let nearer_than_the_fast = own_d < nearest_fast;
        if !nearer_than_the_fast {
            return None;
        }
        bound = bound.min(nearest_fast);
        Some(bound)
    }
}

pub struct Bounds {
    /// Per point, a lower bound on its distance to every codeword but its own (NaN: unknown).
    pub lower: Vec<f64>,
    pub moves: Moves,
    /// The codewords of the last assignment.
    previous: Vec<f64>,
}

impl Bounds {
    pub fn new(n_points: usize, dim: usize) -> Self {
        let rounding = 4.0 * (dim as f64 + 2.0) * f64::EPSILON;
        Self {
            lower: vec![f64::NAN; n_points],
            moves: Moves { dim, fast: Vec::new(), fast_codewords: Vec::new(), slow_drift: 0.0, rounding },
            previous: Vec::new(),
        }
    }

    /// Every point is searched at the next assignment (labels were changed elsewhere).
    pub fn forget(&mut self) {
        self.previous.clear();
    }

    /// Takes in the codewords of the coming assignment: measures how far each has moved
    /// since the last one, or forgets every bound if there was none.
    pub fn advance(&mut self, codewords: &[f64]) {
        let dim = self.moves.dim;
        let moves = &mut self.moves;
        moves.fast.clear();
        moves.fast_codewords.clear();
        moves.slow_drift = 0.0;
        if self.previous.len() == codewords.len() {
            let drift: Vec<f64> = self
                .previous
                .chunks_exact(dim)
                .zip(codewords.chunks_exact(dim))
                .map(|(old, new)| distance2(old, new).sqrt())
                .collect();
            let mut order: Vec<usize> = (0..drift.len()).collect();
            order.sort_by(|&a, &b| drift[b].total_cmp(&drift[a]).then(a.cmp(&b)));
            let fast = order.len().min(FAST);
            moves.fast.extend_from_slice(&order[..fast]);
            for &c in &moves.fast {
                moves.fast_codewords.extend_from_slice(&codewords[c * dim..(c + 1) * dim]);
            }
            moves.slow_drift = order.get(fast).map_or(0.0, |&c| drift[c] * (1.0 + SLACK));
        } else {
            self.lower.fill(f64::NAN);
            self.previous.resize(codewords.len(), 0.0);
        }
        self.previous.copy_from_slice(codewords);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_unsearched_point_is_searched() {
        let mut bounds = Bounds::new(1, 1);
        bounds.advance(&[0.0, 10.0]);
        assert_eq!(bounds.moves.still_nearest(1, &[1.0], 0, 1.0, bounds.lower[0]), None);
    }

    #[test]
    fn a_point_stays_only_while_the_moves_cannot_have_overtaken_its_codeword() {
        let mut bounds = Bounds::new(1, 1);
        bounds.advance(&[0.0, 10.0]);
        // Searched: own codeword at distance 1, the other at 9.
        bounds.advance(&[0.0, 8.0]);
        assert!(bounds.moves.still_nearest(1, &[1.0], 0, 1.0, 9.0).is_some_and(|b| b < 7.0 && b > 6.99));
        bounds.advance(&[0.0, 1.0]);
        // The fast codeword is measured directly: now a tie, which a search must settle.
        assert_eq!(bounds.moves.still_nearest(1, &[1.0], 0, 1.0, 7.0), None);
    }
}
