//! Episode set-ups: simulation parameters, the two field configurations (Fig 4.4) and start
//! states.

use polymimic_types::{Point, Pose};
use serde::{Deserialize, Serialize};

use crate::body::{BodyKind, HUMANOID, HumanoidParams};
use crate::error::{FieldParamError, check_counts, check_range};
use crate::geometry::FieldGeometry;
use crate::math::dist_to_box_mm;
use crate::physics::BallParams;
use crate::tracker::TrackerConfig;

/// Simulation parameters shared by every episode.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct FieldConfig {
    /// Tracker noise.
    pub tracker: TrackerConfig,
    /// Physics steps per tracker frame (8 → 240 Hz).
    pub substeps_per_frame: u32,
    /// Episode time limit, s (choice: 60).
    pub time_limit_s: f64,
    /// Ball material.
    pub ball: BallParams,
    /// The humanoid's body and how its controller plays. A saved config leaves out the thesis's
    /// humanoid, so that configs saved before it was configurable read and save as they were.
    #[serde(default, skip_serializing_if = "HumanoidParams::is_thesis")]
    pub humanoid: HumanoidParams,
}

impl Default for FieldConfig {
    fn default() -> Self {
        Self {
            tracker: TrackerConfig::default(),
            substeps_per_frame: 8,
            time_limit_s: 60.0,
            ball: BallParams::default(),
            humanoid: HUMANOID,
        }
    }
}

impl FieldConfig {
    /// Validate.
    ///
    /// # Errors
    /// `OutOfRange` for any parameter outside its range.
    pub fn check(&self) -> Result<(), FieldParamError> {
        self.tracker.check()?;
        self.ball.check()?;
        self.humanoid.check()?;
        check_range("substeps_per_frame", f64::from(self.substeps_per_frame), 1.0, 64.0, "1 ≤ substeps ≤ 64")?;
        check_range("time_limit_s", self.time_limit_s, 1.0 / 30.0, 86_400.0, "1/30 s ≤ limit ≤ 1 day")
    }

    /// The config as JSON (stored next to datasets so they can be regenerated).
    #[must_use]
    pub fn to_json(&self) -> String {
        // Serialising plain numbers cannot fail.
        serde_json::to_string(self).unwrap_or_default()
    }

    /// The config as JSON with every key, the thesis's humanoid too (what a user is shown and
    /// may change).
    #[must_use]
    pub fn to_json_in_full(&self) -> String {
        let compact = self.to_json();
        match compact.strip_suffix('}') {
            // The humanoid goes last, where serde puts it when it is not the thesis's.
            Some(open) if self.humanoid.is_thesis() => {
                format!("{open},\"humanoid\":{}}}", serde_json::to_string(&self.humanoid).unwrap_or_default())
            }
            _ => compact,
        }
    }

    /// A config from JSON, validated.
    ///
    /// # Errors
    /// `Json` for malformed input; `NotACount` for a substep count that is not a whole number
    /// (by its key); `OutOfRange` for invalid values.
    pub fn from_json(json: &str) -> Result<Self, FieldParamError> {
        check_counts(json, &[("substeps_per_frame", "a whole number, 1 ≤ substeps ≤ 64")])?;
        let config: Self = serde_json::from_str(json).map_err(|e| FieldParamError::Json(e.to_string()))?;
        config.check()?;
        Ok(config)
    }
}

/// The two field configurations of Fig 4.4.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Configuration {
    /// Robot at 1/3 of the length, ball at 2/3, robot facing the ball and the target goal.
    One,
    /// Ball at 1/3, robot at 2/3 facing the ball and, behind it, its own goal.
    Two,
}

impl Configuration {
    /// Both, in order.
    pub const ALL: [Configuration; 2] = [Configuration::One, Configuration::Two];

    /// 1 or 2.
    #[must_use]
    pub const fn number(self) -> u8 {
        match self {
            Configuration::One => 1,
            Configuration::Two => 2,
        }
    }

    /// Start pose of the robot and position of the ball on a field.
    #[must_use]
    pub fn start(self, field: &FieldGeometry) -> (Pose, Point) {
        let sixth = field.length_mm / 6.0;
        match self {
            Configuration::One => (Pose::new(-sixth, 0.0, 0.0), Point::new(sixth, 0.0)),
            Configuration::Two => (Pose::new(sixth, 0.0, std::f64::consts::PI), Point::new(-sixth, 0.0)),
        }
    }
}

/// Where an attempt starts: the robot's pose and the ball's position on the body's field.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Start {
    /// The robot's pose, mm and rad.
    pub robot: Pose,
    /// The ball's position, mm.
    pub ball: Point,
}

impl Start {
    /// The start of `configuration` on `body`'s field (Fig 4.4).
    #[must_use]
    pub fn of(configuration: Configuration, body: BodyKind) -> Self {
        let (robot, ball) = configuration.start(&body.field());
        Self { robot, ball }
    }

    /// Check that this start can be played by `body`: both on its field, finite, and the ball
    /// clear of the robot's footprint.
    ///
    /// # Errors
    /// `OutsideField` for a robot or ball off the field (or not finite); `BallUnderRobot` for
    /// a ball that overlaps the robot.
    pub fn check(&self, body: BodyKind) -> Result<(), FieldParamError> {
        let field = body.field();
        for (what, p, finite) in
            [("robot", self.robot.point(), self.robot.is_finite()), ("ball", self.ball, self.ball.is_finite())]
        {
            if !(finite && field.contains(p)) {
                return Err(FieldParamError::OutsideField { what, x_mm: p.x_mm(), y_mm: p.y_mm() });
            }
        }
        let (length_mm, width_mm) = body.footprint_mm();
        let clearance_mm = dist_to_box_mm(self.robot.robot_from_field(self.ball), length_mm / 2.0, width_mm / 2.0)
            - field.ball_diameter_mm / 2.0;
        if clearance_mm < 0.0 {
            return Err(FieldParamError::BallUnderRobot {
                x_mm: self.ball.x_mm(),
                y_mm: self.ball.y_mm(),
                body: body.name(),
                overlap_mm: -clearance_mm,
            });
        }
        Ok(())
    }
}

/// Where an episode starts and when it ends.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EpisodeSetup {
    /// The robot.
    pub body: BodyKind,
    /// Its start pose.
    pub robot: Pose,
    /// The ball's start position (none: the robot is alone, as in self-observation).
    pub ball: Option<Point>,
    /// Time limit, s (infinite: never times out).
    pub time_limit_s: f64,
}

impl EpisodeSetup {
    /// A configuration of Fig 4.4 on the body's own field, with the config's time limit.
    #[must_use]
    pub fn configuration(body: BodyKind, configuration: Configuration, config: &FieldConfig) -> Self {
        let field = body.field();
        let (robot, ball) = configuration.start(&field);
        Self { body, robot, ball: Some(ball), time_limit_s: config.time_limit_s }
    }

    /// A chosen start on the body's own field, with the config's time limit.
    ///
    /// # Errors
    /// As [`Start::check`].
    pub fn starting(body: BodyKind, start: Start, config: &FieldConfig) -> Result<Self, FieldParamError> {
        start.check(body)?;
        Ok(Self { body, robot: start.robot, ball: Some(start.ball), time_limit_s: config.time_limit_s })
    }

    /// The robot alone at the centre facing +x, without a time limit (self-observation).
    #[must_use]
    pub fn alone(body: BodyKind) -> Self {
        Self { body, robot: Pose::default(), ball: None, time_limit_s: f64::INFINITY }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::FieldSize;

    #[test]
    fn configurations_follow_fig_4_4() {
        let f = FieldGeometry::of(FieldSize::Large);
        let (r1, b1) = Configuration::One.start(&f);
        assert!((r1.x_mm() + 170.0).abs() < 1e-9 && (b1.x_mm() - 170.0).abs() < 1e-9);
        assert!(r1.relative_bearing_rad(b1).abs() < 1e-12);
        let (r2, b2) = Configuration::Two.start(&f);
        assert!(b2.x_mm() < 0.0 && r2.x_mm() > 0.0);
        assert!(r2.relative_bearing_rad(b2).abs() < 1e-9);
        let s = FieldGeometry::of(FieldSize::Small);
        let (r, _) = Configuration::One.start(&s);
        assert!((r.x_mm() + 560.0 / 6.0).abs() < 1e-9);
    }

    #[test]
    fn a_chosen_start_is_refused_off_the_field_or_on_the_robot() {
        let config = FieldConfig::default();
        let body = BodyKind::Lego;
        let at = |x, y, bx, by| Start { robot: Pose::new(x, y, 0.0), ball: Point::new(bx, by) };
        let fine = EpisodeSetup::starting(body, at(0.0, 0.0, 200.0, 100.0), &config).expect("plays");
        assert_eq!((fine.robot, fine.ball), (Pose::new(0.0, 0.0, 0.0), Some(Point::new(200.0, 100.0))));
        assert!(matches!(
            EpisodeSetup::starting(body, at(600.0, 0.0, 0.0, 0.0), &config),
            Err(FieldParamError::OutsideField { what: "robot", .. })
        ));
        assert!(matches!(
            EpisodeSetup::starting(body, at(0.0, 0.0, 0.0, -500.0), &config),
            Err(FieldParamError::OutsideField { what: "ball", .. })
        ));
        assert!(matches!(
            EpisodeSetup::starting(body, at(f64::NAN, 0.0, 0.0, 100.0), &config),
            Err(FieldParamError::OutsideField { what: "robot", .. })
        ));
        // The ball's edge inside the footprint (half its length ahead, less than a radius on).
        let (length_mm, _) = body.footprint_mm();
        let e = EpisodeSetup::starting(body, at(0.0, 0.0, length_mm / 2.0 + 40.0, 0.0), &config);
        assert!(
            matches!(e, Err(FieldParamError::BallUnderRobot { overlap_mm, .. }) if (overlap_mm - 10.0).abs() < 1e-9)
        );
        assert!(EpisodeSetup::starting(body, at(0.0, 0.0, length_mm / 2.0 + 50.0, 0.0), &config).is_ok());
        // The two configurations are starts like any other.
        for c in Configuration::ALL {
            let start = Start::of(c, body);
            assert_eq!(
                EpisodeSetup::starting(body, start, &config).expect("plays"),
                EpisodeSetup::configuration(body, c, &config)
            );
        }
    }

    #[test]
    fn default_config_is_valid_and_bad_values_are_caught() {
        assert!(FieldConfig::default().check().is_ok());
        let bad = FieldConfig { substeps_per_frame: 0, ..FieldConfig::default() };
        assert!(bad.check().is_err());
        let bad = FieldConfig { time_limit_s: f64::NAN, ..FieldConfig::default() };
        assert!(bad.check().is_err());
    }

    #[test]
    fn config_round_trips_through_json_and_is_checked() {
        let c = FieldConfig::default();
        assert_eq!(FieldConfig::from_json(&c.to_json()), Ok(c));
        assert!(matches!(FieldConfig::from_json("{"), Err(FieldParamError::Json(_))));
        // The thesis's humanoid is left out of what is saved and shown in full.
        assert!(!c.to_json().contains("humanoid") && c.to_json_in_full().contains("\"look_s\":0.4"));
        assert_eq!(FieldConfig::from_json(&c.to_json_in_full()), Ok(c));
        let pivot = FieldConfig { humanoid: HumanoidParams { turn_pivot_mm: 1.0, ..HUMANOID }, ..c };
        assert_eq!(c.to_json_in_full().replace("\"turn_pivot_mm\":20.3", "\"turn_pivot_mm\":1.0"), pivot.to_json());
        let pivoting = FieldConfig { humanoid: HumanoidParams { turn_pivot_mm: 28.0, ..HUMANOID }, ..c };
        assert!(pivoting.to_json().contains("\"turn_pivot_mm\":28.0"));
        assert_eq!(FieldConfig::from_json(&pivoting.to_json()), Ok(pivoting));
        let shy = c.to_json_in_full().replace("\"look_s\":0.4", "\"look_s\":-1.0");
        assert!(matches!(
            FieldConfig::from_json(&shy),
            Err(FieldParamError::OutOfRange { name: "humanoid.look_s", .. })
        ));
        let bad = c.to_json().replace("\"substeps_per_frame\":8", "\"substeps_per_frame\":0");
        assert!(matches!(FieldConfig::from_json(&bad), Err(FieldParamError::OutOfRange { .. })));
        let negative = c.to_json().replace("\"substeps_per_frame\":8", "\"substeps_per_frame\":-8");
        assert!(matches!(
            FieldConfig::from_json(&negative),
            Err(FieldParamError::NotACount { name: "substeps_per_frame", .. })
        ));
    }
}
