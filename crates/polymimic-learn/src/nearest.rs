//! The k nearest of a set of points, by squared Euclidean distance; ties go to the earlier
//! point, so results do not depend on how the selection happens to order them.

/// Indices of the `k` points nearest `query` (all of them if there are fewer), with their
/// squared distances, in no particular order.
pub(crate) fn nearest<const D: usize>(
    points: impl Iterator<Item = [f64; D]>,
    query: &[f64; D],
    k: usize,
) -> Vec<(f64, usize)> {
    let mut all: Vec<(f64, usize)> =
        points.enumerate().map(|(i, p)| (p.iter().zip(query).map(|(a, b)| (a - b).powi(2)).sum(), i)).collect();
    let k = k.min(all.len());
    if k == 0 {
        return Vec::new();
    }
    all.select_nth_unstable_by(k - 1, |a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    all.truncate(k);
    all
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_nearest_are_found_and_ties_go_to_the_earlier_point() {
        let points = [[0.0, 0.0], [3.0, 0.0], [1.0, 0.0], [-1.0, 0.0], [10.0, 0.0]];
        let mut found = nearest(points.into_iter(), &[0.0, 0.0], 3);
        found.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        // 1.0 and −1.0 tie; both are within the three nearest.
        assert_eq!(found, vec![(0.0, 0), (1.0, 2), (1.0, 3)]);
        let mut two = nearest(points.into_iter(), &[0.0, 0.0], 2);
        two.sort_by_key(|p| p.1);
        assert_eq!(two, vec![(0.0, 0), (1.0, 2)], "of two tied points the earlier is kept");
        assert_eq!(nearest(points.into_iter(), &[0.0, 0.0], 9).len(), 5);
        assert!(nearest(std::iter::empty::<[f64; 2]>(), &[0.0, 0.0], 3).is_empty());
    }
}
