//! The imitator's final model driving a robot on the field (thesis §3.4, end): the policy and the
//! thesis's rule of choosing a behaviour (policy.rs), the improved rule (improved.rs), and attempts
//! from the thesis's configurations or chosen starts with their seeds (attempts.rs).

mod attempts;
mod improved;
mod policy;

pub use attempts::{Attempt, StartAt, attempt_seeds, start_attempt_seeds};
pub use policy::{ControlMode, ImitatorPolicy};
