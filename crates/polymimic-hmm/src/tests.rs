//! Answers known independently of the implementation: textbook models, brute-force
//! enumeration over every state path, and the invariants of EM.

use crate::{DiscreteHmm, HmmError, HmmParams, Init, Topology};

fn model(start: &[f64], trans: &[f64], emit: &[f64], n_symbols: usize, topology: Topology) -> DiscreteHmm {
    let mut params = HmmParams::new(start.len(), n_symbols);
    params.topology = topology;
    params.tol = f64::NEG_INFINITY;
    DiscreteHmm::from_probabilities(params.check().unwrap(), start.to_vec(), trans.to_vec(), emit.to_vec()).unwrap()
}

fn weather(b: &[f64]) -> DiscreteHmm {
    model(&[0.6, 0.4], &[0.7, 0.3, 0.4, 0.6], b, 3, Topology::Ergodic)
}

#[test]
fn rainy_sunny_textbook_probability() {
    let m = weather(&[0.1, 0.4, 0.5, 0.6, 0.3, 0.1]);
    let p = m.score(&[0, 1, 2]).unwrap().exp();
    assert!((p - 0.033_612).abs() < 5e-7, "P = {p}");
}

#[test]
fn stamp_textbook_probability() {
    let m = weather(&[0.1, 0.4, 0.5, 0.7, 0.2, 0.1]);
    let p = m.score(&[0, 1, 0, 2]).unwrap().exp();
    assert!((p - 0.009_629_6).abs() < 5e-8, "P = {p}");
}

/// Every state path of a small model with its joint probability P(path, O).
fn all_paths(m: &DiscreteHmm, seq: &[u32]) -> Vec<(Vec<usize>, f64)> {
    let p = m.probabilities().unwrap();
    let n = p.n_states;
    let total = n.pow(seq.len() as u32);
    (0..total)
        .map(|code| {
            let path: Vec<usize> = (0..seq.len()).map(|t| (code / n.pow(t as u32)) % n).collect();
            let mut joint = p.startprob[path[0]] * p.b(path[0], seq[0] as usize);
            for t in 1..seq.len() {
                joint *= p.a(path[t - 1], path[t]) * p.b(path[t], seq[t] as usize);
            }
            (path, joint)
        })
        .collect()
}

fn three_state() -> DiscreteHmm {
    model(
        &[0.5, 0.3, 0.2],
        &[0.6, 0.3, 0.1, 0.2, 0.5, 0.3, 0.25, 0.25, 0.5],
        &[0.5, 0.3, 0.2, 0.1, 0.6, 0.3, 0.3, 0.1, 0.6],
        3,
        Topology::Ergodic,
    )
}

#[test]
fn likelihood_and_viterbi_match_brute_force_enumeration() {
    let m = three_state();
    let seq = [0, 2, 1, 1, 0, 2];
    let paths = all_paths(&m, &seq);
    let total: f64 = paths.iter().map(|(_, p)| p).sum();
    assert!((m.score(&seq).unwrap() - total.ln()).abs() < 1e-12);
    let (best_path, best_p) = paths.iter().fold((vec![], 0.0), |b, (q, p)| if *p > b.1 { (q.clone(), *p) } else { b });
    let (path, log_p) = m.decode(&seq).unwrap();
    assert_eq!(path, best_path);
    assert!((log_p - best_p.ln()).abs() < 1e-12);
}

#[test]
fn one_reestimation_matches_brute_force_expected_counts() {
    let mut m = three_state();
    let seqs: Vec<&[u32]> = vec![&[0, 2, 1, 1], &[2, 2, 0], &[1, 0, 0, 2, 1]];
    let (n, k) = (3, 3);
    let mut start = vec![0.0; n];
    let mut trans = vec![0.0; n * n];
    let mut emit = vec![0.0; n * k];
    for seq in &seqs {
        let paths = all_paths(&m, seq);
        let total: f64 = paths.iter().map(|(_, p)| p).sum();
        for (path, joint) in &paths {
            let w = joint / total;
            start[path[0]] += w;
            for t in 0..seq.len() {
                emit[path[t] * k + seq[t] as usize] += w;
                if t + 1 < seq.len() {
                    trans[path[t] * n + path[t + 1]] += w;
                }
            }
        }
    }
    let normalise = |v: &mut [f64], width: usize| {
        for row in v.chunks_mut(width) {
            let s: f64 = row.iter().sum();
            for x in row.iter_mut() {
                *x /= s;
            }
        }
    };
    normalise(&mut start, n);
    normalise(&mut trans, n);
    normalise(&mut emit, k);
    let mut params = (**m.params()).clone();
    params.max_iter = 1;
    m.params = params.check().unwrap();
    m.fit(&seqs, Init::Given).unwrap();
    let p = m.probabilities().unwrap();
    for (ours, brute) in [(&p.startprob, &start), (&p.transmat, &trans), (&p.emissionprob, &emit)] {
        for (a, b) in ours.iter().zip(brute.iter()) {
            assert!((a - b).abs() < 1e-12, "{ours:?} vs {brute:?}");
        }
    }
}

fn training_data(count: usize, seed: u64) -> Vec<Vec<u32>> {
    let truth = model(
        &[1.0, 0.0, 0.0],
        &[0.8, 0.15, 0.05, 0.0, 0.7, 0.3, 0.0, 0.0, 1.0],
        &[0.6, 0.3, 0.1, 0.0, 0.1, 0.2, 0.6, 0.1, 0.0, 0.1, 0.2, 0.7],
        4,
        Topology::LeftRight { links: 2 },
    );
    truth.sample(count, 12, seed).unwrap().0
}

fn fitted(sequences: &[Vec<u32>], n_states: usize, topology: Topology) -> DiscreteHmm {
    let mut params = HmmParams::new(n_states, 4);
    params.topology = topology;
    params.max_iter = 30;
    params.tol = f64::NEG_INFINITY;
    params.seed = 3;
    let mut m = DiscreteHmm::new(params.check().unwrap());
    let refs: Vec<&[u32]> = sequences.iter().map(Vec::as_slice).collect();
    m.fit(&refs, Init::Segments).unwrap();
    m
}

#[test]
fn log_likelihood_never_decreases() {
    let data = training_data(300, 11);
    for topology in [Topology::LeftRight { links: 2 }, Topology::Ergodic] {
        let m = fitted(&data, 4, topology);
        for pair in m.history().windows(2) {
            assert!(pair[1] >= pair[0] - 1e-9 * pair[0].abs(), "{:?}", m.history());
        }
    }
}

#[test]
fn left_right_zeros_stay_exactly_zero_under_training() {
    let m = fitted(&training_data(200, 5), 5, Topology::LeftRight { links: 2 });
    let p = m.probabilities().unwrap();
    for i in 0..5 {
        for j in 0..5 {
            if !(j >= i && j <= i + 2) {
                assert_eq!(p.a(i, j).to_bits(), 0, "a[{i}][{j}]");
            }
        }
    }
    assert_eq!(p.startprob[0], 1.0);
}

#[test]
fn results_are_bit_identical_for_any_thread_count() {
    // More sequences than one parallel chunk, so the reduction order matters.
    let data = training_data(1000, 2);
    let run = |threads| {
        rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap().install(|| {
            let m = fitted(&data, 4, Topology::LeftRight { links: 2 });
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            let p = m.probabilities().unwrap();
            (bits(m.history()), bits(&p.transmat), bits(&p.emissionprob))
        })
    };
    assert_eq!(run(1), run(4));
}

#[test]
fn stops_when_the_gain_falls_below_tol() {
    let data = training_data(100, 8);
    let refs: Vec<&[u32]> = data.iter().map(Vec::as_slice).collect();
    let mut params = HmmParams::new(3, 4);
    params.max_iter = 500;
    params.tol = 1e-3;
    let mut m = DiscreteHmm::new(params.check().unwrap());
    m.fit(&refs, Init::Segments).unwrap();
    assert!(m.converged());
    let h = m.history();
    assert!(h.len() < 500);
    assert!(h[h.len() - 1] - h[h.len() - 2] < 1e-3);
}

#[test]
fn an_impossible_sequence_is_named_and_leaves_the_model_unchanged() {
    let mut m = model(&[1.0, 0.0], &[0.5, 0.5, 0.0, 1.0], &[1.0, 0.0, 0.0, 1.0], 2, Topology::LeftRight { links: 1 });
    let before = m.clone();
    let err = m.score(&[1, 0]).unwrap_err();
    assert_eq!(err, HmmError::ImpossibleSequence { index: 0, position: 0 });
    let seqs: Vec<&[u32]> = vec![&[0, 1], &[0, 1, 0]];
    assert_eq!(m.fit(&seqs, Init::Given).unwrap_err(), HmmError::ImpossibleSequence { index: 1, position: 2 });
    assert_eq!(m, before);
    assert!(m.decode(&[0, 1, 0]).is_err());
}

#[test]
fn bad_sequences_are_named() {
    let mut m = DiscreteHmm::new(HmmParams::new(2, 3).check().unwrap());
    assert!(matches!(m.fit(&[], Init::Segments), Err(HmmError::Params(crate::HmmParamsError::NoSequences))));
    let seqs: Vec<&[u32]> = vec![&[0], &[]];
    assert!(matches!(
        m.fit(&seqs, Init::Segments),
        Err(HmmError::Params(crate::HmmParamsError::EmptySequence { index: 1 }))
    ));
    let seqs: Vec<&[u32]> = vec![&[0, 7]];
    assert!(matches!(
        m.fit(&seqs, Init::Segments),
        Err(HmmError::Params(crate::HmmParamsError::SymbolOutOfRange { index: 0, position: 1, symbol: 7, .. }))
    ));
    assert_eq!(m.score(&[0]).unwrap_err(), HmmError::NotFitted);
    assert_eq!(m.fit(&[&[0]], Init::Given).unwrap_err(), HmmError::NotFitted);
}

#[test]
fn saved_models_round_trip_exactly_and_foreign_files_are_refused() {
    let m = fitted(&training_data(50, 1), 3, Topology::LeftRight { links: 2 });
    let text = m.to_json().unwrap();
    assert_eq!(DiscreteHmm::from_json(&text).unwrap(), m);
    assert!(DiscreteHmm::from_json("{not json").is_err());
    assert!(DiscreteHmm::from_json(r#"{"format": "other", "version": 1}"#).is_err());
    let future = text.replace("\"version\":1", "\"version\":99");
    assert!(matches!(DiscreteHmm::from_json(&future), Err(HmmError::Corrupt(msg)) if msg.contains("99")));
    let broken = text.replacen("\"startprob\":[1.0", "\"startprob\":[7.0", 1);
    assert!(DiscreteHmm::from_json(&broken).is_err());
}

#[test]
fn samples_follow_the_model() {
    let m = weather(&[0.1, 0.4, 0.5, 0.6, 0.3, 0.1]);
    let (symbols, states) = m.sample(4000, 3, 9).unwrap();
    let first_rainy = states.iter().filter(|s| s[0] == 0).count() as f64 / 4000.0;
    assert!((first_rainy - 0.6).abs() < 0.03, "{first_rainy}");
    let walks_when_sunny = symbols.iter().zip(&states).filter(|(o, s)| s[0] == 1 && o[0] == 0).count() as f64;
    let sunny = states.iter().filter(|s| s[0] == 1).count() as f64;
    assert!((walks_when_sunny / sunny - 0.6).abs() < 0.04);
    assert_eq!(m.sample(2, 3, 9).unwrap(), m.sample(2, 3, 9).unwrap());
}

#[test]
fn a_huge_iteration_limit_trains_without_reserving_it() {
    let mut params = HmmParams::new(1, 2);
    params.topology = Topology::Ergodic;
    params.max_iter = 1 << 62;
    let mut model = DiscreteHmm::new(params.check().unwrap());
    model.fit(&[&[0, 1, 0, 1]], Init::Segments).unwrap();
    assert!(model.converged() && model.history().len() < 10, "{:?}", model.history());
}
