//! How much each demonstrator counts for the imitator under [`ImitatorWeighting::Lp`]: its
//! model's learning preference relative to the highest.
//!
//! [`ImitatorWeighting::Lp`]: crate::ImitatorWeighting::Lp

use crate::config::ImitatorWeighting;
use crate::error::LearnParamsError;
use crate::round::SegmentedDemonstration;

/// Every model's weight under `weighting`, from their LPs (`initial_lp` the LP each started
/// from); [`ImitatorWeighting::Even`] weighs every model 1.
#[must_use]
pub fn imitator_weights(weighting: ImitatorWeighting, lps: &[f64], initial_lp: f64) -> Vec<f64> {
    match weighting {
        ImitatorWeighting::Even => vec![1.0; lps.len()],
        ImitatorWeighting::Lp => lp_weights(lps),
        ImitatorWeighting::LpGain => lp_weights(&lps.iter().map(|lp| (lp - initial_lp).max(0.0)).collect::<Vec<_>>()),
    }
}

/// `w_m = LP_m / max_k LP_k` for every model's LP in `lps`: the highest weighs 1; if no LP is
/// above 0, every model weighs 1.
#[must_use]
pub fn lp_weights(lps: &[f64]) -> Vec<f64> {
    let top = lps.iter().copied().fold(0.0, f64::max);
    if top > 0.0 { lps.iter().map(|lp| lp / top).collect() } else { vec![1.0; lps.len()] }
}

/// The weight of each demonstration: that of its demonstrator's model among `models` (each
/// a name and its LP), by [`imitator_weights`] over all of them.
///
/// # Errors
/// Names the first demonstration whose demonstrator has no model.
pub fn demonstration_weights(
    demonstrations: &[SegmentedDemonstration],
    models: &[(String, f64)],
    weighting: ImitatorWeighting,
    initial_lp: f64,
) -> Result<Vec<f64>, LearnParamsError> {
    let lps: Vec<f64> = models.iter().map(|(_, lp)| *lp).collect();
    let weights = imitator_weights(weighting, &lps, initial_lp);
    demonstrations
        .iter()
        .enumerate()
        .map(|(index, d)| {
            models
                .iter()
                .position(|(name, _)| *name == d.demonstrator)
                .map(|m| weights[m])
                .ok_or_else(|| LearnParamsError::NoModelFor { index, demonstrator: d.demonstrator.clone() })
        })
        .collect()
}

/// The demonstrations with their weights (`weights[i]` for demonstration i; any beyond the
/// end of `weights` weighs 1, so `&[]` weighs every one alike), leaving out those whose
/// weight is not above 0: what the world model learns from.
pub(crate) fn weighted<'a>(
    demonstrations: &'a [SegmentedDemonstration],
    weights: &'a [f64],
) -> impl Iterator<Item = (&'a SegmentedDemonstration, f64)> {
    demonstrations
        .iter()
        .enumerate()
        .map(|(i, d)| (d, weights.get(i).copied().unwrap_or(1.0)))
        .filter(|&(_, w)| w > 0.0 && w.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::round::Ending;
    use crate::state::Pitch;

    fn by(name: &str) -> SegmentedDemonstration {
        SegmentedDemonstration {
            demonstrator: name.to_owned(),
            pitch: Pitch::LARGE,
            reach_mm: None,
            ending: Ending::Other,
            segments: Vec::new(),
        }
    }

    #[test]
    fn the_best_member_weighs_one_and_the_others_their_share_of_its_lp() {
        assert_eq!(lp_weights(&[0.2, 0.8, 0.4]), vec![0.25, 1.0, 0.5]);
        assert_eq!(lp_weights(&[0.0, 0.0]), vec![1.0, 1.0], "nobody preferred: everyone counts");
        assert_eq!(lp_weights(&[0.5, 0.5]), vec![1.0, 1.0]);
        assert!(lp_weights(&[]).is_empty());
    }

    #[test]
    fn the_gain_weighs_each_member_by_its_rise_above_the_starting_lp() {
        // Binary fractions: the rises 0, 0.25, 0.125 and −0.25 are exact.
        let lps = [0.5, 0.75, 0.625, 0.25];
        assert_eq!(imitator_weights(ImitatorWeighting::LpGain, &lps, 0.5), vec![0.0, 1.0, 0.5, 0.0]);
        assert_eq!(
            imitator_weights(ImitatorWeighting::LpGain, &[0.4, 0.5], 0.5),
            vec![1.0, 1.0],
            "none rose: all count"
        );
        // LPs held at the start (the uniform-LP ablation): lp_gain weighs as even does.
        assert_eq!(
            imitator_weights(ImitatorWeighting::LpGain, &[0.5; 3], 0.5),
            imitator_weights(ImitatorWeighting::Even, &[0.5; 3], 0.5)
        );
        assert_eq!(imitator_weights(ImitatorWeighting::Lp, &lps, 0.5), lp_weights(&lps));
        assert_eq!(imitator_weights(ImitatorWeighting::Even, &lps, 0.5), vec![1.0; 4]);
    }

    #[test]
    fn each_demonstration_takes_its_demonstrators_weight_and_a_stranger_is_named() {
        let models = [("poor".to_owned(), 0.25), ("expert".to_owned(), 1.0)];
        let weights =
            demonstration_weights(&[by("expert"), by("poor"), by("expert")], &models, ImitatorWeighting::Lp, 0.5);
        assert_eq!(weights, Ok(vec![1.0, 0.25, 1.0]));
        assert_eq!(
            demonstration_weights(&[by("poor"), by("tiny")], &models, ImitatorWeighting::Lp, 0.5),
            Err(LearnParamsError::NoModelFor { index: 1, demonstrator: "tiny".to_owned() })
        );
    }
}
