//! Initial emissions from the temporal split of the training sequences (thesis Fig 3.11).

/// State i counts the symbols of piece i of every sequence, where a sequence of length T is
/// cut into pieces of ceil(T / n) symbols (the last may be shorter, or missing when T < n).
/// Every probability is then floored at `floor` and each row renormalised; a state whose
/// pieces hold no symbol at all starts uniform.
#[must_use]
pub fn segment_emissions(sequences: &[&[u32]], n_states: usize, n_symbols: usize, floor: f64) -> Vec<f64> {
    let mut counts = vec![0.0; n_states * n_symbols];
    for seq in sequences {
        let piece_len = seq.len().div_ceil(n_states);
        for (t, &symbol) in seq.iter().enumerate() {
            let state = t / piece_len;
            counts[state * n_symbols + symbol as usize] += 1.0;
        }
    }
    for row in counts.chunks_exact_mut(n_symbols) {
        let total: f64 = row.iter().sum();
        if total == 0.0 {
            row.fill(1.0 / n_symbols as f64);
            continue;
        }
        for p in row.iter_mut() {
            *p = (*p / total).max(floor);
        }
        let floored_total: f64 = row.iter().sum();
        for p in row.iter_mut() {
            *p /= floored_total;
        }
    }
    counts
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pieces_of_ceil_length_with_a_short_last_piece() {
        // T = 5, n = 2: pieces of 3 and 2 symbols.
        let seq: &[u32] = &[0, 0, 1, 2, 2];
        let b = segment_emissions(&[seq], 2, 3, 0.0);
        assert_eq!(b, vec![2.0 / 3.0, 1.0 / 3.0, 0.0, 0.0, 0.0, 1.0]);
    }

    #[test]
    fn floor_keeps_unseen_symbols_possible_and_rows_stochastic() {
        let seq: &[u32] = &[0, 0, 1, 1];
        let b = segment_emissions(&[seq], 2, 3, 1e-8);
        for row in b.chunks(3) {
            assert!(row.iter().all(|&p| p >= 1e-8 * 0.99));
            assert!((row.iter().sum::<f64>() - 1.0).abs() < 1e-15);
        }
    }

    #[test]
    fn states_beyond_a_short_sequence_start_uniform() {
        let seq: &[u32] = &[1];
        let b = segment_emissions(&[seq], 3, 2, 1e-8);
        assert_eq!(&b[2..], &[0.5, 0.5, 0.5, 0.5]);
    }
}
