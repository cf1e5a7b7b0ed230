//! The thesis's Average demonstrator (§4.4.2), chosen in one place for the Rust laboratory and
//! for Python's `polymimic.average_demonstrator`: of candidate imitators driven by the thesis's
//! rule, the one whose net goals (goals less own goals) lie nearest the middle of the Poor's and
//! the Expert's, strictly between them, the earliest on a tie. Net goals, not goals, because
//! that is what put the thesis's own Average between its Poor and its Expert: it scored fewer
//! goals than the Poor but far fewer own goals.

use std::borrow::Borrow;

use polymimic_field::{BodyKind, Configuration, FieldConfig, Frame};

use crate::config::LearningConfig;
use crate::control::{Attempt, ControlMode, ImitatorPolicy};
use crate::error::LaboratoryError;
use crate::prediction::MotionTable;
use crate::round::{Ending, SegmentedDemonstration};
use crate::trial::TrialResult;

/// Attempts made beyond those needed, to stand in for any whose tracking is lost.
#[must_use]
pub fn spare_attempts(per_configuration: usize) -> usize {
    (per_configuration / 5).max(5)
}

/// Goals less own goals.
pub fn net_goals(endings: impl IntoIterator<Item = Ending>) -> i64 {
    endings
        .into_iter()
        .map(|e| match e {
            Ending::Goal => 1,
            Ending::OwnGoal => -1,
            Ending::Other => 0,
        })
        .sum()
}

/// Goals less own goals scored by `who` in `demonstrations`.
#[must_use]
pub fn net_goals_of(demonstrations: &[SegmentedDemonstration], who: &str) -> i64 {
    net_goals(demonstrations.iter().filter(|d| d.demonstrator == who).map(|d| d.ending))
}

/// Whether the tracker saw the robot and the ball in every frame (what a recording needs to
/// count as a demonstration).
#[must_use]
pub fn tracked_throughout(frames: &[Frame]) -> bool {
    frames.iter().all(|f| {
        [f.robot_x_mm, f.robot_y_mm, f.robot_theta_rad, f.ball_x_mm, f.ball_y_mm].iter().all(|v| v.is_finite())
    })
}

/// The chosen imitator: the seed its attempts were made with, its trial, and the attempts
/// (`per_configuration` from each configuration, tracked throughout) that made it the Average.
#[derive(Debug, Clone, PartialEq)]
pub struct AverageChoice<T> {
    pub seed: u64,
    pub trial: T,
    pub attempts: Vec<Attempt>,
}

/// What the search for the Average needs besides its candidates.
pub struct AverageSearch<'a> {
    pub motion: &'a MotionTable,
    pub config: &'a LearningConfig,
    /// The field the candidates play on.
    pub field: &'a FieldConfig,
    /// The body the candidates drive.
    pub body: BodyKind,
    /// Attempts from each configuration that must hold tracking throughout.
    pub per_configuration: usize,
    /// Net goals of the Poor's and the Expert's demonstrations.
    pub poor_net_goals: i64,
    pub expert_net_goals: i64,
}

impl AverageSearch<'_> {
    /// Scores each candidate `(seed, trial)` in turn (its imitator's attempts made with `seed`,
    /// spare attempts standing in for those whose tracking is lost) and keeps the one nearest
    /// the middle. Candidates come lazily, so trials can run as they are scored.
    ///
    /// # Errors
    /// A candidate's error, a field error, or no candidate between the Poor and the Expert.
    pub fn choose<T: Borrow<TrialResult>>(
        &self,
        candidates: impl IntoIterator<Item = Result<(u64, T), LaboratoryError>>,
    ) -> Result<AverageChoice<T>, LaboratoryError> {
        let (poor, expert) = (self.poor_net_goals, self.expert_net_goals);
        let n = self.per_configuration;
        let mut best: Option<(u64, AverageChoice<T>)> = None;
        let mut tried = 0;
        for candidate in candidates {
            let (seed, trial) = candidate?;
            tried += 1;
            let policy = ImitatorPolicy {
                model: &trial.borrow().imitator,
                motion: self.motion,
                config: self.config,
                body: self.body,
                mode: ControlMode::Thesis,
                world: None,
            };
            let attempts = policy.evaluate(n + spare_attempts(n), self.field, seed)?;
            let valid: Vec<Attempt> = Configuration::ALL
                .iter()
                .flat_map(|&c| {
                    let of_c = attempts.iter().filter(move |a| a.configuration == Some(c));
                    of_c.filter(|a| tracked_throughout(&a.frames)).take(n).cloned()
                })
                .collect();
            if valid.len() < Configuration::ALL.len() * n {
                continue;
            }
            let net = net_goals(valid.iter().map(|a| Ending::from(a.outcome)));
            // Twice the distance from the middle, in whole goals.
            let off_middle = (2 * net).abs_diff(poor + expert);
            if poor < net && net < expert && best.as_ref().is_none_or(|(d, _)| off_middle < *d) {
                best = Some((off_middle, AverageChoice { seed, trial, attempts: valid }));
            }
        }
        best.map(|(_, choice)| choice).ok_or(LaboratoryError::NoAverage { tried, poor, expert })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn net_goals_count_goals_less_own_goals() {
        assert_eq!(net_goals([Ending::Goal, Ending::Other, Ending::Goal, Ending::OwnGoal]), 1);
        assert_eq!(net_goals([]), 0);
    }

    #[test]
    fn spare_attempts_are_a_fifth_and_at_least_five() {
        assert_eq!((spare_attempts(10), spare_attempts(25), spare_attempts(100)), (5, 5, 20));
    }

    #[test]
    fn no_candidate_is_no_average() {
        let motion = MotionTable::exact(50.0, 90.0);
        let config = LearningConfig::default();
        let field = FieldConfig::default();
        let search = AverageSearch {
            motion: &motion,
            config: &config,
            field: &field,
            body: BodyKind::Lego,
            per_configuration: 1,
            poor_net_goals: -2,
            expert_net_goals: 5,
        };
        let none: Vec<Result<(u64, TrialResult), LaboratoryError>> = Vec::new();
        assert_eq!(search.choose(none), Err(LaboratoryError::NoAverage { tried: 0, poor: -2, expert: 5 }));
    }
}
