//! Learning from many demonstrators (thesis §3.3, §3.4): behaviours grown from primitives by
//! frequency counting with decay and permanency, one forward model per demonstrator weighted
//! by a learning preference, candidates nominated to the imitator's model, two-phase training.

mod approach;
mod average;
mod ball_response;
mod behaviour;
mod config;
mod control;
mod correspondence;
mod error;
mod laboratory;
mod model;
mod nearest;
mod player;
mod prediction;
mod prefix_tree;
mod push_region;
mod record;
mod round;
mod running;
mod shaping;
mod state;
mod state_value;
mod trial;
mod weighting;
mod world;

pub use approach::ApproachPlan;
pub use average::{AverageChoice, AverageSearch, net_goals, net_goals_of, spare_attempts, tracked_throughout};
pub use ball_response::BallResponse;
pub use behaviour::Behaviour;
pub use config::{ImitatorWeighting, LearningConfig, LpApproachWeight, LpBounds, LpCriteria, LpScope, WorldWeighting};
pub use control::{Attempt, ControlMode, ImitatorPolicy, StartAt, attempt_seeds, start_attempt_seeds};
pub use correspondence::{Setting, imitator_reach_mm, onto_setting, reach_mm};
pub use error::{LaboratoryError, LearnError, LearnParamsError};
pub use laboratory::{FinalLps, Laboratory, ModelSummary, Score, lp_order_hits, summarise};
pub use model::{Event, ForwardModel, ModelMetrics};
pub use player::{PRIMITIVE_S, PlayingImitator, Stepping};
pub use prediction::{MotionTable, Prediction, matches, predict};
pub use push_region::{BallGoalPose, Interval, PushRegion, RegionShape};
pub use record::{BehaviourRecord, Json, ModelRecord, RecordError, TrialRecord};
pub use round::{Ending, SegmentedDemonstration};
pub use running::Running;
pub use shaping::{LpCause, LpCauseCounts};
pub use state::{Pitch, ball_to_goal_mm, precondition_measures, range_bearing, robot_to_ball_mm};
pub use state_value::StateValue;
pub use trial::{PhaseOne, TrialResult, run_trial};
pub use weighting::{demonstration_weights, imitator_weights, lp_weights};
pub use world::{Practice, Refines, WorldModel};

#[cfg(test)]
mod tests;
