//! Behaviours: sequences of primitives with what they have been seen to do (thesis §3.3).

use polymimic_types::{Primitive, TrackedFrame};
use serde::{Deserialize, Serialize};

use crate::config::LearningConfig;
use crate::running::Running;
use crate::state::{Pitch, precondition_measures, range_bearing};

/// A behaviour: its primitives (a primitive is a behaviour of one), how established it is,
/// and statistics of the ball and of the states it started from.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Behaviour {
    pub primitives: Vec<Primitive>,
    pub permanency: f64,
    pub permanent: bool,
    /// Creation order within its model: lower is older.
    pub age: u64,
    /// Where the ball ended relative to the robot when this behaviour moved it: bearing (deg).
    pub ball_angle_deg: Running,
    /// …and distance (mm).
    pub ball_distance_mm: Running,
    /// Distance and bearing to the target goal, the own goal and the ball at the start of
    /// every span this behaviour was selected for.
    pub preconditions: [Running; 6],
    /// The demonstrator model that nominated it, if it is a candidate in the imitator's model.
    pub nominated_by: Option<usize>,
    /// Times it was selected.
    pub selected: usize,
}

impl Behaviour {
    #[must_use]
    pub fn new(primitives: Vec<Primitive>, age: u64, config: &LearningConfig) -> Self {
        let permanent = primitives.len() == 1;
        Self {
            primitives,
            permanency: if permanent { 1.0 } else { config.default_permanency },
            permanent,
            age,
            ball_angle_deg: Running::default(),
            ball_distance_mm: Running::default(),
            preconditions: [Running::default(); 6],
            nominated_by: None,
            selected: 0,
        }
    }

    #[must_use]
    pub fn is_primitive(&self) -> bool {
        self.primitives.len() == 1
    }

    /// Whether its ball statistics are good enough to predict the ball.
    #[must_use]
    pub fn predicts_ball(&self, config: &LearningConfig) -> bool {
        self.ball_angle_deg.count >= config.ball_min_samples && self.ball_angle_deg.sd() <= config.ball_max_angle_sd_deg
    }

    /// Records a span it was selected for: the start state's preconditions, and where the ball
    /// ended relative to the robot if the ball moved.
    pub fn record_span(&mut self, start: &TrackedFrame, end: &TrackedFrame, pitch: &Pitch, config: &LearningConfig) {
        self.selected += 1;
        for (stat, value) in self.preconditions.iter_mut().zip(precondition_measures(start, pitch)) {
            stat.push(value);
        }
        let moved = (end.ball_x_mm - start.ball_x_mm).hypot(end.ball_y_mm - start.ball_y_mm);
        if moved > config.ball_moved_mm {
            let (distance, bearing) = range_bearing(&end.robot, end.ball_x_mm, end.ball_y_mm);
            self.ball_angle_deg.push(bearing);
            self.ball_distance_mm.push(distance);
        }
    }

    /// Whether every precondition measure of `state` lies within one standard deviation of its
    /// mean (a behaviour selected fewer than twice has no spread and never applies).
    #[must_use]
    pub fn applies_to(&self, state: &TrackedFrame, pitch: &Pitch) -> bool {
        self.preconditions[0].count >= 2
            && self
                .preconditions
                .iter()
                .zip(precondition_measures(state, pitch))
                .all(|(stat, value)| (value - stat.mean).abs() <= stat.sd())
    }

    /// The primitives as letters, e.g. "FFL".
    #[must_use]
    pub fn letters(&self) -> String {
        self.primitives.iter().map(|p| p.letter()).collect()
    }
}
