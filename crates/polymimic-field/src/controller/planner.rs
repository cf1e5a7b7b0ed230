//! Shared geometry of a competition-style attacker: get behind the ball on the ball–goal line
//! without touching it on the way, then push (or kick) it along that line. Where that line's
//! spot behind the ball is off the field (the ball near a side line), the line runs from the
//! nearest spot the robot can stand on through the ball instead.

use polymimic_types::{Point, Pose};

use crate::geometry::FieldGeometry;
use crate::math::{PI, wrap_angle_rad};

/// What the attacker should do next.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Plan {
    /// Go to this point (a detour round the ball, or the spot behind it).
    GoTo(Point),
    /// At the spot behind the ball: turn to face this heading (rad).
    Face(f64),
    /// Behind the ball and aligned: push toward this point.
    Push(Point),
}

/// Sizes the planner needs, mm.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Sizes {
    /// Ball radius.
    pub ball_r: f64,
    /// Robot centre to its front face.
    pub front: f64,
    /// Robot centre to its farthest corner (it sweeps this circle when it spins).
    pub reach: f64,
    /// Gap between the front face and the ball at the spot behind it.
    pub gap: f64,
    /// Position tolerance at the spot.
    pub spot_tol: f64,
    /// Heading tolerance before pushing, rad.
    pub face_tol_rad: f64,
}

/// Where to aim: a little inside the target goal's mouth.
pub(crate) fn aim_point(field: &FieldGeometry) -> Point {
    Point::new(field.half_length_mm() + field.ball_diameter_mm, 0.0)
}

/// The ball–goal line as a frame: at the ball, x toward the aim point, y its left normal.
fn line(ball: Point, aim: Point) -> Pose {
    Pose::at(ball, ball.bearing_rad(aim))
}

/// The spot behind the ball on the ball–goal line, `extra` mm farther back than the gap.
pub(crate) fn behind_spot(ball: Point, aim: Point, s: &Sizes, extra: f64) -> Point {
    let back = s.ball_r + s.front + s.gap + extra;
    line(ball, aim).ahead(-back)
}

/// Is the way from `a` to `b` blocked by a disc of radius `r` at `c`? Only the interior of the
/// segment counts: ending next to the ball (the spot behind it) is the point.
fn blocked(a: Point, b: Point, c: Point, r: f64) -> bool {
    let (dx, dy) = (b.x_mm() - a.x_mm(), b.y_mm() - a.y_mm());
    let len2 = dx * dx + dy * dy;
    if len2 <= 0.0 {
        return false;
    }
    let t = ((c.x_mm() - a.x_mm()) * dx + (c.y_mm() - a.y_mm()) * dy) / len2;
    t > 0.0 && t < 1.0 && c.dist_mm(Point::new(a.x_mm() + t * dx, a.y_mm() + t * dy)) < r
}

/// Keep a target where the robot can stand without leaving the field.
fn clamp_to_field(p: Point, field: &FieldGeometry, reach: f64) -> Point {
    let (mx, my) = ((field.half_length_mm() - reach - 5.0).max(0.0), (field.half_width_mm() - reach - 5.0).max(0.0));
    Point::new(p.x_mm().clamp(-mx, mx), p.y_mm().clamp(-my, my))
}

/// Which way round the ball (+1: through the line's left-normal side, counter-clockwise). The robot's own side of the
/// line; on the line, the side away from the nearer side line; on the centre line, left.
fn detour_side(lateral: f64, line: Pose, s: &Sizes) -> f64 {
    let ball = line.point();
    // The y of the line's left normal (−sin, cos) is the x of its direction.
    let normal_y = line.heading().x;
    if lateral.abs() > 0.3 * s.ball_r {
        lateral.signum()
    } else if ball.y_mm().abs() > 0.3 * s.ball_r && normal_y.abs() > 1e-6 {
        -ball.y_mm().signum() * normal_y.signum()
    } else {
        1.0
    }
}

/// The attacker's plan. `pushing` is the previous decision (hysteresis: once pushing, keep
/// pushing while roughly behind the ball).
pub(crate) fn plan(robot: Pose, ball: Point, field: &FieldGeometry, s: &Sizes, pushing: bool) -> Plan {
    let aim = aim_point(field);
    let on_goal_line = behind_spot(ball, aim, s, 0.0);
    let spot = clamp_to_field(on_goal_line, field, s.reach);
    // With the ball near a side line the spot on the ball–goal line can be off the field. Then
    // push from the nearest spot the robot can stand on, through the ball: the ball runs along
    // the side line toward the goal, where waiting to stand on the ball–goal line waits forever.
    let line = if spot == on_goal_line { line(ball, aim) } else { Pose::at(ball, spot.bearing_rad(ball)) };
    // The robot in the line's frame: how far along it (negative: behind the ball), how far off.
    let in_line_frame = line.robot_from_field(robot.point());
    let (along, lateral) = (in_line_frame.x_mm(), in_line_frame.y_mm());
    let push_heading = line.theta_rad();
    let heading_err = wrap_angle_rad(push_heading - robot.theta_rad());
    let contact = s.ball_r + s.front;
    // Behind the ball, on the line, facing the goal: push; looser once already pushing.
    let k = if pushing { 1.6 } else { 1.0 };
    let behind = along < -0.5 * contact && along > -(contact + s.gap + 3.0 * s.spot_tol);
    let on_line = lateral.abs() < k * 0.45 * s.ball_r.max(s.spot_tol);
    let facing = heading_err.abs() < k * s.face_tol_rad && robot.relative_bearing_rad(ball).abs() < k * s.face_tol_rad;
    if behind && on_line && facing {
        return Plan::Push(line.ahead(2.0 * contact));
    }
    if robot.point().dist_mm(spot) < s.spot_tol {
        return Plan::Face(push_heading);
    }
    // Keep the spinning robot's corners off the ball on the way round.
    let clearance = s.ball_r + s.reach + 0.25 * s.gap;
    if !blocked(robot.point(), spot, ball, clearance) {
        return Plan::GoTo(spot);
    }
    let side = detour_side(lateral, line, s);
    let d = robot.point().dist_mm(ball);
    let away = robot.point().bearing_rad(ball) + PI;
    let target = if d <= 1.05 * clearance {
        // Too close: back off round the ball, a quarter turn ahead on the chosen side.
        // Counter-clockwise round the ball passes the left-normal side (+1).
        let a = away + side * 0.6;
        Pose::at(ball, a).ahead(1.4 * clearance)
    } else {
        // Aim just outside the tangent to the clearance circle on the chosen side; as the
        // robot moves the tangent point slides round the ball until the spot is in view.
        let r = 1.15 * clearance;
        let alpha = (r / d).min(1.0).asin();
        let dir = robot.point().bearing_rad(ball) - side * alpha;
        let reach = (d * d - r * r).max(0.0).sqrt() + 0.5 * r;
        Pose::at(robot.point(), dir).ahead(reach)
    };
    Plan::GoTo(clamp_to_field(target, field, s.reach))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::FieldSize;

    const S: Sizes = Sizes { ball_r: 50.0, front: 70.0, reach: 103.0, gap: 40.0, spot_tol: 25.0, face_tol_rad: 0.25 };

    #[test]
    fn behind_and_aligned_means_push() {
        let f = FieldGeometry::of(FieldSize::Large);
        let ball = Point::new(0.0, 0.0);
        let robot = Pose::new(-125.0, 0.0, 0.0);
        assert!(matches!(plan(robot, ball, &f, &S, false), Plan::Push(_)));
    }

    #[test]
    fn facing_the_own_goal_means_a_detour_not_a_push() {
        let f = FieldGeometry::of(FieldSize::Large);
        let ball = Point::new(-170.0, 0.0);
        let robot = Pose::new(170.0, 0.0, std::f64::consts::PI);
        match plan(robot, ball, &f, &S, false) {
            Plan::GoTo(w) => {
                assert!(w.y_mm().abs() > 100.0, "{w:?}");
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn near_a_side_line_it_pushes_from_the_spot_it_can_reach() {
        // The spot behind this ball on the ball–goal line is 42 mm beyond the side line; the
        // nearest the robot may stand is 150 mm off that line.
        let f = FieldGeometry::of(FieldSize::Large);
        let ball = Point::new(300.0, 330.0);
        let spot = clamp_to_field(behind_spot(ball, aim_point(&f), &S, 0.0), &f, S.reach);
        assert!((spot.y_mm() - (f.half_width_mm() - S.reach - 5.0)).abs() < 1e-9, "{spot:?}");
        let robot = Pose::at(spot, spot.bearing_rad(ball));
        match plan(robot, ball, &f, &S, false) {
            Plan::Push(target) => {
                // Straight on through the ball, from the spot, ahead of it.
                let off_line = Pose::at(spot, spot.bearing_rad(ball)).robot_from_field(target);
                assert!(off_line.y_mm().abs() < 1e-6 && off_line.x_mm() > spot.dist_mm(ball), "{target:?}");
            }
            other => panic!("{other:?}"),
        }
        // Facing the goal from there instead, it turns toward the ball rather than wait.
        let facing_goal = Pose::at(spot, ball.bearing_rad(aim_point(&f)));
        match plan(facing_goal, ball, &f, &S, false) {
            Plan::Face(h) => assert!((h - spot.bearing_rad(ball)).abs() < 1e-12),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn clear_path_goes_to_the_spot() {
        let f = FieldGeometry::of(FieldSize::Large);
        let ball = Point::new(170.0, 0.0);
        let robot = Pose::new(-170.0, 0.0, 0.0);
        let spot = behind_spot(ball, aim_point(&f), &S, 0.0);
        assert_eq!(plan(robot, ball, &f, &S, false), Plan::GoTo(spot));
        let at_spot = Pose::new(spot.x_mm(), spot.y_mm(), 1.0);
        assert!(matches!(plan(at_spot, ball, &f, &S, false), Plan::Face(_)));
    }
}
