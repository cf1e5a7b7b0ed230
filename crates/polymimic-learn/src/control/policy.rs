//! The imitator's policy (its final model, what it predicts with, the body it drives and the mode
//! of control, see [`ControlMode`]) and the thesis's rule of choosing a behaviour (§3.4, end).
//!
//! By the thesis's rule, at each decision the behaviours whose preconditions the current state meets (every
//! measure within one standard deviation of its mean) are considered, or all of them if none
//! applies. Each predicts its outcome and the best by the learning-preference criteria — a
//! predicted goal, then the ball nearer the goal, then the robot nearer the ball — is executed
//! primitive by primitive, stopping early if the next primitive would take the robot off the
//! field.

use polymimic_field::BodyKind;
use polymimic_types::TrackedFrame;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use crate::config::LearningConfig;
use crate::model::ForwardModel;
use crate::prediction::{MotionTable, predict};
use crate::shaping::approach_shaping;
use crate::state::{Pitch, robot_to_ball_mm};
use crate::world::WorldModel;

/// How the imitator's model drives the robot.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ControlMode {
    /// The thesis's rule: the applicable behaviours (else all) predict with their own ball
    /// statistics; the best by the LP criteria runs to its end.
    #[default]
    Thesis,
    /// The thesis's future work: every behaviour predicts the ball with the ball response
    /// learned from all the demonstrations (§5.4), and its predicted end is rated by a goal (the
    /// sooner the better, with `prefer_sooner_goals`), then by whether the demonstrations
    /// passing near it ended, on balance, in own goals, then by how much nearer the goal it puts
    /// the ball, then the robot to the ball; only the first primitive runs before choosing
    /// again, so a behaviour that comes to rate better takes over at once (§4.4.1).
    /// Preconditions are not consulted: every behaviour competes. Behaviours push only from
    /// where the demonstrators pushed toward the goal (relative to the ball and the goal,
    /// [`PushRegion`](crate::PushRegion)), or when one predicts a goal; anywhere else the robot
    /// takes the shortest route there in its own primitives
    /// ([`ApproachPlan`](crate::ApproachPlan)), going round the ball rather than through it.
    Improved,
}

/// The imitator's model with what it needs to predict, and the body it drives (on that body's
/// field: [`Self::pitch`]).
#[derive(Clone, Copy)]
pub struct ImitatorPolicy<'a> {
    pub model: &'a ForwardModel,
    pub motion: &'a MotionTable,
    pub config: &'a LearningConfig,
    pub body: BodyKind,
    pub mode: ControlMode,
    /// What the improved mode predicts and rates with (without it the ball is predicted to
    /// stay and every state is safe).
    pub world: Option<&'a WorldModel>,
}

impl ImitatorPolicy<'_> {
    /// The field the imitator's body plays on.
    #[must_use]
    pub const fn pitch(&self) -> Pitch {
        Pitch::of_body(self.body)
    }

    /// The behaviour to execute next from `state`, by the thesis's rule; `None` if every
    /// behaviour's first primitive would leave the field.
    pub fn choose(&self, state: &TrackedFrame, rng: &mut ChaCha8Rng) -> Option<usize> {
        let behaviours = &self.model.behaviours;
        let mut stays = |i: &usize| {
            let first = self.motion.step(state.robot, behaviours[*i].primitives[0], f64::INFINITY, rng);
            self.pitch().contains(first.x_mm(), first.y_mm())
        };
        let mut candidates: Vec<usize> = (0..behaviours.len())
            .filter(|&i| behaviours[i].applies_to(state, &self.pitch()))
            .filter(&mut stays)
            .collect();
        if candidates.is_empty() {
            candidates = (0..behaviours.len()).filter(&mut stays).collect();
        }
        candidates
            .into_iter()
            .map(|i| (self.rate(i, state, rng), i))
            .max_by(|(a, i), (b, j)| {
                a.0.total_cmp(&b.0)
                    .then(a.1.total_cmp(&b.1))
                    .then(behaviours[*j].primitives.len().cmp(&behaviours[*i].primitives.len()))
                    .then(behaviours[*j].age.cmp(&behaviours[*i].age))
            })
            .map(|(_, i)| i)
    }

    /// The LP criteria applied to behaviour `index`'s prediction from `state`, and how much
    /// nearer the ball the robot is predicted to get (mm), to break ties.
    fn rate(&self, index: usize, state: &TrackedFrame, rng: &mut ChaCha8Rng) -> (f64, f64) {
        let config = self.config;
        let prediction = predict(&self.model.behaviours[index], state.robot, self.motion, config, rng);
        let ball = prediction.ball_position().unwrap_or((state.ball_x_mm, state.ball_y_mm));
        let after = TrackedFrame { robot: prediction.end(), ball_x_mm: ball.0, ball_y_mm: ball.1 };
        let (bx, by) = ball;
        if self.pitch().in_target_goal(bx, by) {
            return (config.lp_goal, 0.0);
        }
        if self.pitch().in_own_goal(bx, by) {
            return (-config.lp_goal, 0.0);
        }
        let score = approach_shaping(state, &after, &self.pitch(), config);
        (score, robot_to_ball_mm(state) - robot_to_ball_mm(&after))
    }
}
