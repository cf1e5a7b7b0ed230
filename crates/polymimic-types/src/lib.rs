//! The domain types every polymimic crate shares, each defined once: the imitator's
//! [`Primitive`]s, [`Point`]s and [`Pose`]s on the field (built on nalgebra), the
//! [`TrackedFrame`] the learner reads, angle wrapping, and the Table 3.1 [`MotionStats`].
//!
//! Units: mm and rad (degrees only where a name says `_deg`); field origin at the centre, +x
//! toward the target goal, headings counter-clockwise from +x.
//!
//! Two kinds of maths meet here, and each function says which it uses. The field computes with
//! `libm` (the same bits on every platform); the recogniser and the learner were built on std's
//! `f64` methods and keep them, so that saved models and results stay bit-identical.
//!
//! ```
//! use polymimic_types::{Point, Pose};
//!
//! let robot = Pose::new(100.0, 0.0, std::f64::consts::FRAC_PI_2);
//! let ahead = robot.field_from_robot(Point::new(50.0, 0.0));
//! assert!((ahead.x_mm() - 100.0).abs() < 1e-12 && (ahead.y_mm() - 50.0).abs() < 1e-12);
//! assert!((robot.robot_from_field(ahead).x_mm() - 50.0).abs() < 1e-12);
//! ```

mod angle;
mod frame;
mod motion;
mod motion_since;
mod point;
mod pose;
mod primitive;
mod primitive_set;

pub use angle::{direction_rad, rotation_by_rad, wrap_angle_euclid_rad, wrap_angle_rad};
pub use frame::TrackedFrame;
pub use motion::{MotionStats, Sideways};
pub use point::Point;
pub use pose::Pose;
pub use primitive::{Primitive, capitalised};
pub use primitive_set::PrimitiveSet;
