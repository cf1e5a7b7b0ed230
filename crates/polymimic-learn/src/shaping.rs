//! What moves a learning preference (thesis Table 3.3, eq 3.13), and by how much.

use polymimic_types::TrackedFrame;
use serde::{Deserialize, Serialize};

use crate::config::{LearningConfig, LpCriteria};
use crate::state::{Pitch, ball_to_goal_mm, robot_to_ball_mm};

/// One reason an LP changes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LpCause {
    Goal,
    OwnGoal,
    BallNearerGoal,
    BallFartherFromGoal,
    RobotNearerBall,
    RobotFartherFromBall,
    /// A behaviour predicted where the ball went.
    BallPredicted,
    /// A candidate the model nominated became permanent in the imitator's model…
    CandidatePermanent,
    /// …or was deleted there.
    CandidateDeleted,
}

impl LpCause {
    /// The signed change of eq 3.13, an own goal's weighted by `lp_own_goal_weight`.
    #[must_use]
    pub fn amount(self, config: &LearningConfig) -> f64 {
        match self {
            Self::Goal => config.lp_goal,
            Self::OwnGoal => -config.lp_goal * config.lp_own_goal_weight,
            Self::BallNearerGoal => config.lp_ball_to_goal,
            Self::BallFartherFromGoal => -config.lp_ball_to_goal,
            Self::RobotNearerBall => config.lp_robot_to_ball,
            Self::RobotFartherFromBall => -config.lp_robot_to_ball,
            Self::BallPredicted | Self::CandidatePermanent => config.lp_event,
            Self::CandidateDeleted => -config.lp_event,
        }
    }
}

/// How often each cause changed a model's LP.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct LpCauseCounts {
    pub goal: usize,
    pub own_goal: usize,
    pub ball_nearer_goal: usize,
    pub ball_farther_from_goal: usize,
    pub robot_nearer_ball: usize,
    pub robot_farther_from_ball: usize,
    pub ball_predicted: usize,
    pub candidate_permanent: usize,
    pub candidate_deleted: usize,
}

impl LpCauseCounts {
    pub fn count(&mut self, cause: LpCause) {
        let slot = match cause {
            LpCause::Goal => &mut self.goal,
            LpCause::OwnGoal => &mut self.own_goal,
            LpCause::BallNearerGoal => &mut self.ball_nearer_goal,
            LpCause::BallFartherFromGoal => &mut self.ball_farther_from_goal,
            LpCause::RobotNearerBall => &mut self.robot_nearer_ball,
            LpCause::RobotFartherFromBall => &mut self.robot_farther_from_ball,
            LpCause::BallPredicted => &mut self.ball_predicted,
            LpCause::CandidatePermanent => &mut self.candidate_permanent,
            LpCause::CandidateDeleted => &mut self.candidate_deleted,
        };
        *slot += 1;
    }

    /// Every count with its name, in the order of Table 3.3.
    #[must_use]
    pub fn named(&self) -> [(&'static str, usize); 9] {
        [
            ("goal", self.goal),
            ("own_goal", self.own_goal),
            ("ball_nearer_goal", self.ball_nearer_goal),
            ("ball_farther_from_goal", self.ball_farther_from_goal),
            ("robot_nearer_ball", self.robot_nearer_ball),
            ("robot_farther_from_ball", self.robot_farther_from_ball),
            ("ball_predicted", self.ball_predicted),
            ("candidate_permanent", self.candidate_permanent),
            ("candidate_deleted", self.candidate_deleted),
        ]
    }
}

/// The task criteria short of a goal, from one state to another: the ball nearer the target
/// goal (or farther), and the robot nearer the ball (or farther), as `config.lp_criteria`
/// combines them. Changes within the dead bands count as neither. Shared by learning and by
/// control's rating of predictions.
pub(crate) fn approach_causes(
    before: &TrackedFrame,
    after: &TrackedFrame,
    pitch: &Pitch,
    config: &LearningConfig,
) -> [Option<LpCause>; 2] {
    let judge = |then: f64, now: f64, dead_band: f64, nearer: LpCause, farther: LpCause| {
        if now < then - dead_band {
            Some(nearer)
        } else if now > then + dead_band {
            Some(farther)
        } else {
            None
        }
    };
    let ball = judge(
        ball_to_goal_mm(before, pitch),
        ball_to_goal_mm(after, pitch),
        config.ball_dead_band_mm,
        LpCause::BallNearerGoal,
        LpCause::BallFartherFromGoal,
    );
    let robot = judge(
        robot_to_ball_mm(before),
        robot_to_ball_mm(after),
        config.robot_dead_band_mm,
        LpCause::RobotNearerBall,
        LpCause::RobotFartherFromBall,
    );
    match config.lp_criteria {
        LpCriteria::Foremost if ball.is_some() => [ball, None],
        LpCriteria::Foremost => [robot, None],
        LpCriteria::Both => [ball, robot],
    }
}

/// The summed change of [`approach_causes`].
pub(crate) fn approach_shaping(
    before: &TrackedFrame,
    after: &TrackedFrame,
    pitch: &Pitch,
    config: &LearningConfig,
) -> f64 {
    approach_causes(before, after, pitch, config).iter().flatten().map(|c| c.amount(config)).sum()
}
