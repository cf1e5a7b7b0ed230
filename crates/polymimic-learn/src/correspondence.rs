//! One correspondence between the settings demonstrations are played in: where a demonstration
//! recorded on one field, by one body, lies for an imitator of another body on its own field. It
//! applies after segmenting, to everything the imitator learns from a segmented demonstration
//! (its behaviours' preconditions, the learning preference's criteria, the improved control's
//! world model), so the recogniser still reads each demonstrator's motion as the tracker saw it.
//!
//! The ball carries the field: along the field its position scales with the lengths (goal line
//! onto goal line); across it the goal mouth maps onto the goal mouth and the rest of each half
//! onto the rest, so a ball in the mouth stays in it and a ball in play stays in play — a goal
//! stays a goal and an own goal an own goal even where the mouths are not in the same proportion
//! to the widths. The robot keeps its heading and its bearing from the ball; its distance from
//! the ball maps by the bodies' reach (how far from its centre a body moves the ball: a wheeled
//! body's front, the humanoid's kicking foot) up to the demonstrator's reach, so a touch stays a
//! touch, and beyond it at the fields' scale. Where either reach is unknown the robot keeps its offset from the ball in
//! millimetres. A frame without the ball maps the robot as a point of the field.

use std::borrow::Cow;

use polymimic_field::BodyKind;
use polymimic_field::body::HUMANOID;
use polymimic_perceive::Segment;
use polymimic_types::{Pose, TrackedFrame};

use crate::round::SegmentedDemonstration;
use crate::state::Pitch;

/// Where a demonstration is played: the field, and how far from its centre its body moves the
/// ball.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Setting {
    pub pitch: Pitch,
    /// How far from its centre the body moves the ball ([`reach_mm`]), where known.
    pub reach_mm: Option<f64>,
}

impl Setting {
    /// `body` demonstrating on its own field.
    #[must_use]
    pub fn of_body(body: BodyKind) -> Self {
        Self { pitch: Pitch::of_body(body), reach_mm: Some(reach_mm(body)) }
    }

    /// `body` imitating on its own field.
    #[must_use]
    pub fn of_imitator(body: BodyKind) -> Self {
        Self { pitch: Pitch::of_body(body), reach_mm: Some(imitator_reach_mm(body)) }
    }

    /// Where a point of this setting's field lies on `to`'s.
    #[must_use]
    pub fn point_onto(&self, to: &Self, x_mm: f64, y_mm: f64) -> (f64, f64) {
        let (from, onto) = (&self.pitch, &to.pitch);
        // As shares of the sizes, so a goal line or a post lands exactly on its counterpart.
        (onto.length_mm * (x_mm / from.length_mm), across_onto(from, onto, y_mm))
    }

    /// A tracked frame of this setting in `to` (see the module's documentation); in its own,
    /// itself.
    #[must_use]
    pub fn frame_onto(&self, to: &Self, frame: &TrackedFrame) -> TrackedFrame {
        if self == to {
            return *frame;
        }
        let robot = &frame.robot;
        if !(frame.ball_x_mm.is_finite() && frame.ball_y_mm.is_finite()) {
            let (x, y) = self.point_onto(to, robot.x_mm(), robot.y_mm());
            return TrackedFrame { robot: Pose::new(x, y, robot.theta_rad()), ..*frame };
        }
        let (bx, by) = self.point_onto(to, frame.ball_x_mm, frame.ball_y_mm);
        let (dx, dy) = (robot.x_mm() - frame.ball_x_mm, robot.y_mm() - frame.ball_y_mm);
        let scale = self.offset_scale(to, dx.hypot(dy));
        TrackedFrame {
            robot: Pose::new(bx + dx * scale, by + dy * scale, robot.theta_rad()),
            ball_x_mm: bx,
            ball_y_mm: by,
        }
    }

    /// What the robot's distance `distance_mm` from the ball is multiplied by in `to`.
    fn offset_scale(&self, to: &Self, distance_mm: f64) -> f64 {
        let (Some(from_reach), Some(to_reach)) = (self.reach_mm, to.reach_mm) else { return 1.0 };
        if distance_mm <= from_reach {
            return to_reach / from_reach;
        }
        let field_scale = to.pitch.length_mm / self.pitch.length_mm;
        (to_reach + field_scale * (distance_mm - from_reach)) / distance_mm
    }
}

/// How far from its centre `body` moves the ball as a demonstrator, mm: the ball's radius beyond
/// a wheeled body's front, or beyond the humanoid's kicking foot at full reach.
#[must_use]
pub fn reach_mm(body: BodyKind) -> f64 {
    match body {
        BodyKind::Humanoid => HUMANOID.foot_reach_mm.1 + 0.5 * body.field().ball_diameter_mm,
        wheeled => imitator_reach_mm(wheeled),
    }
}

/// How far from its centre `body` moves the ball as an imitator, mm: its primitives drive or walk
/// it into the ball, so the ball's radius beyond its front. The humanoid's too, even over its own
/// set with a kick: measured with the kicking foot's reach instead, it learned worse from the
/// Humanoid's demonstrations and nearly nothing from the Expert's (docs/guides/bodies.md).
#[must_use]
pub fn imitator_reach_mm(body: BodyKind) -> f64 {
    0.5 * (body.footprint_mm().0 + body.field().ball_diameter_mm)
}

/// A distance across the field (from its long axis) on `to`: piecewise linear, the mouth's half
/// onto the mouth's half, beyond it the rest of the half-width onto the rest (continued past the
/// touchline at the same rate).
fn across_onto(from: &Pitch, to: &Pitch, y_mm: f64) -> f64 {
    let (from_post, to_post) = (from.goal_mouth_mm / 2.0, to.goal_mouth_mm / 2.0);
    let (from_rest, to_rest) = (from.width_mm / 2.0 - from_post, to.width_mm / 2.0 - to_post);
    let distance = y_mm.abs();
    let mapped = if distance <= from_post || from_rest <= 0.0 || to_rest <= 0.0 {
        to_post * (distance / from_post)
    } else {
        to_post + to_rest * ((distance - from_post) / from_rest)
    };
    mapped.copysign(y_mm)
}

impl SegmentedDemonstration {
    /// Where this demonstration was played.
    #[must_use]
    pub const fn setting(&self) -> Setting {
        Setting { pitch: self.pitch, reach_mm: self.reach_mm }
    }

    /// This demonstration in `setting`: itself if it was played there.
    #[must_use]
    pub fn onto(&self, setting: &Setting) -> Self {
        let from = self.setting();
        if from == *setting {
            return self.clone();
        }
        let map = |frame: &TrackedFrame| from.frame_onto(setting, frame);
        let segments = self.segments.iter().map(|s| Segment { start: map(&s.start), end: map(&s.end), ..*s }).collect();
        Self {
            demonstrator: self.demonstrator.clone(),
            pitch: setting.pitch,
            reach_mm: setting.reach_mm,
            ending: self.ending,
            segments,
        }
    }
}

/// Every demonstration in `setting` (the imitator's): the same slice, uncopied, where every one
/// was played there already (a trial's usual case, run once per trial).
#[must_use]
pub fn onto_setting<'a>(
    demonstrations: &'a [SegmentedDemonstration],
    setting: &Setting,
) -> Cow<'a, [SegmentedDemonstration]> {
    if demonstrations.iter().all(|d| d.setting() == *setting) {
        return Cow::Borrowed(demonstrations);
    }
    Cow::Owned(demonstrations.iter().map(|d| d.onto(setting)).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    const USERS: Pitch = Pitch { length_mm: 9000.0, width_mm: 6000.0, goal_mouth_mm: 1000.0 };

    fn setting(pitch: Pitch, reach_mm: f64) -> Setting {
        Setting { pitch, reach_mm: Some(reach_mm) }
    }

    fn frame(robot: (f64, f64, f64), ball: (f64, f64)) -> TrackedFrame {
        TrackedFrame { robot: Pose::new(robot.0, robot.1, robot.2), ball_x_mm: ball.0, ball_y_mm: ball.1 }
    }

    fn close(a: &TrackedFrame, b: &TrackedFrame) -> bool {
        let near = |p: f64, q: f64| (p.is_nan() && q.is_nan()) || (p - q).abs() <= 1e-9 * p.abs().max(1.0);
        near(a.robot.x_mm(), b.robot.x_mm())
            && near(a.robot.y_mm(), b.robot.y_mm())
            && a.robot.theta_rad().to_bits() == b.robot.theta_rad().to_bits()
            && near(a.ball_x_mm, b.ball_x_mm)
            && near(a.ball_y_mm, b.ball_y_mm)
    }

    #[test]
    fn a_wheeled_body_reaches_the_ball_with_its_front_and_the_humanoid_with_its_foot() {
        assert_eq!(reach_mm(BodyKind::Lego), 70.0 + 50.0);
        assert_eq!(reach_mm(BodyKind::Tiny), 7.5 + 12.5);
        assert_eq!(reach_mm(BodyKind::Humanoid), 110.0 + 50.0);
        assert_eq!(imitator_reach_mm(BodyKind::Humanoid), 35.0 + 50.0, "walking into the ball");
        assert_eq!(imitator_reach_mm(BodyKind::Lego), reach_mm(BodyKind::Lego));
    }

    #[test]
    fn a_frame_mapped_to_another_setting_and_back_is_itself() {
        let frames = [
            frame((-120.0, 40.0, 0.3), (-80.0, 35.0)),
            frame((480.0, -190.0, -2.9), (505.0, -200.0)),
            frame((10.0, 400.0, 1.0), (30.0, 410.0)),
            frame((300.0, -20.0, 2.0), (-100.0, 150.0)),
            frame((0.0, -100.0, 0.5), (f64::NAN, f64::NAN)),
        ];
        let (tiny, lego, users) = (setting(Pitch::SMALL, 20.0), setting(Pitch::LARGE, 120.0), setting(USERS, 150.0));
        let humanoid = setting(Pitch::LARGE, 160.0);
        let unknown = Setting { pitch: USERS, reach_mm: None };
        for (a, b) in [(tiny, lego), (lego, tiny), (users, lego), (humanoid, lego), (unknown, lego)] {
            for f in &frames {
                let back = b.frame_onto(&a, &a.frame_onto(&b, f));
                assert!(close(&back, f), "{a:?} → {b:?} → back moved {f:?} to {back:?}");
            }
        }
    }

    #[test]
    fn goals_stay_goals_and_balls_in_play_stay_in_play() {
        let pairs = [(Pitch::SMALL, Pitch::LARGE), (USERS, Pitch::LARGE), (Pitch::LARGE, USERS)];
        for (from, to) in pairs.map(|(a, b)| (setting(a, 20.0), setting(b, 120.0))) {
            let p = from.pitch;
            let (half_length, post, touchline) = (p.length_mm / 2.0, p.goal_mouth_mm / 2.0, p.width_mm / 2.0);
            for (x, y) in [(half_length + 1.0, post - 1.0), (half_length, -post), (half_length + 5.0, 0.0)] {
                let (mx, my) = from.point_onto(&to, x, y);
                assert!(to.pitch.in_target_goal(mx, my), "{x}, {y} on {from:?} is a goal, on {to:?} {mx}, {my}");
                let (ox, oy) = from.point_onto(&to, -x, y);
                assert!(to.pitch.in_own_goal(ox, oy), "an own goal stays an own goal");
            }
            for (x, y) in [(half_length + 1.0, post + 1.0), (0.0, touchline + 1.0)] {
                let (mx, my) = from.point_onto(&to, x, y);
                assert!(!to.pitch.in_target_goal(mx, my) && !to.pitch.contains(mx, my), "out stays out: {x}, {y}");
            }
            let (mx, my) = from.point_onto(&to, half_length - 1.0, touchline - 1.0);
            assert!(to.pitch.contains(mx, my) && !to.pitch.in_target_goal(mx, my), "in play stays in play");
        }
    }

    #[test]
    fn a_touch_stays_a_touch_and_the_robot_keeps_its_heading_and_bearing() {
        let (tiny, lego) = (setting(Pitch::SMALL, 20.0), setting(Pitch::LARGE, 120.0));
        // The tiny touching the ball from behind, 20 mm from its centre, lands 120 mm behind it.
        let touching = tiny.frame_onto(&lego, &frame((120.0, -50.0, 0.3), (140.0, -50.0)));
        assert!((touching.ball_x_mm - 140.0 * 1020.0 / 560.0).abs() < 1e-9);
        assert!((touching.ball_y_mm + 50.0 * 202.5 / 86.25).abs() < 1e-9);
        assert!((touching.robot.x_mm() - (touching.ball_x_mm - 120.0)).abs() < 1e-9);
        assert!((touching.robot.y_mm() - touching.ball_y_mm).abs() < 1e-9);
        assert_eq!(touching.robot.theta_rad(), 0.3);
        // 220 mm away: the reach, then the 200 mm beyond it at the fields' scale.
        let far = tiny.frame_onto(&lego, &frame((0.0, 220.0, 1.0), (0.0, 0.0)));
        assert!((far.robot.y_mm() - (120.0 + 200.0 * 1020.0 / 560.0)).abs() < 1e-9 && far.robot.x_mm() == 0.0);
        // Reach unknown: the offset in millimetres.
        let unknown = Setting { pitch: Pitch::SMALL, reach_mm: None };
        let kept = unknown.frame_onto(&lego, &frame((100.0, -50.0, 0.3), (140.0, -50.0)));
        assert!((kept.robot.x_mm() - (kept.ball_x_mm - 40.0)).abs() < 1e-9);
    }

    #[test]
    fn a_demonstration_in_the_imitators_setting_is_itself() {
        let segment = Segment {
            label: polymimic_perceive::Label::Gap,
            first_frame: 0,
            last_frame: 3,
            start: frame((1.0, 2.0, 0.1), (3.0, 4.0)),
            end: frame((5.0, 6.0, 0.2), (7.0, 8.0)),
            scores: [0.0; 7],
        };
        let lego = Setting::of_imitator(BodyKind::Lego);
        let demo = SegmentedDemonstration {
            demonstrator: "d".to_owned(),
            pitch: lego.pitch,
            reach_mm: lego.reach_mm,
            ending: crate::round::Ending::Goal,
            segments: vec![segment],
        };
        assert_eq!(demo.onto(&lego), demo);
        let tiny = Setting::of_imitator(BodyKind::Tiny);
        let moved = demo.onto(&tiny);
        assert_eq!((moved.pitch, moved.reach_mm), (Pitch::SMALL, Some(20.0)));
        assert!(close(&moved.onto(&lego).segments[0].end, &demo.segments[0].end));
    }
}
