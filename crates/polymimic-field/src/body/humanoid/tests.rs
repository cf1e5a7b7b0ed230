//! The humanoid body's motion: walking, side-steps, turning about a foot, kicks and the camera.

use super::*;
use crate::math::{deg, rng};

fn run(b: &mut HumanoidBody, h: HumanoidCommand, frames: u32, r: &mut Rng) {
    for _ in 0..frames {
        b.command(Command::Humanoid(h), r).expect("humanoid command");
        for _ in 0..8 {
            b.substep(1.0 / 240.0, r);
        }
    }
}

#[test]
fn walking_advances_and_sways() {
    let mut r = rng(1, 0);
    let mut b = HumanoidBody::new(HUMANOID, Pose::default());
    let mut max_sway: f64 = 0.0;
    for _ in 0..60 {
        run(&mut b, HumanoidCommand::WalkForward, 1, &mut r);
        max_sway = max_sway.max(b.pose().theta_rad().abs());
    }
    assert!(b.pose().x_mm() > 80.0, "{:?}", b.pose());
    assert!(max_sway > deg(2.0), "sway {max_sway}");
}

#[test]
fn shuffle_moves_sideways() {
    let mut r = rng(2, 0);
    let mut b = HumanoidBody::new(HUMANOID, Pose::default());
    run(&mut b, HumanoidCommand::ShuffleLeft, 60, &mut r);
    assert!(b.pose().y_mm() > 30.0 && b.pose().x_mm().abs() < 15.0, "{:?}", b.pose());
}

#[test]
fn kick_leans_back_and_swings_the_foot() {
    let mut r = rng(3, 0);
    let mut b = HumanoidBody::new(HUMANOID, Pose::default());
    let mut foot_seen = false;
    for _ in 0..30 {
        run(&mut b, HumanoidCommand::KickLeft, 1, &mut r);
        let f = b.foot();
        if f.active {
            foot_seen = true;
            assert!(f.pose.y_mm() > 0.0);
        }
    }
    assert!(foot_seen);
    assert!(!b.is_kicking());
    assert!(b.pose().x_mm() < -5.0, "{:?}", b.pose());
}

#[test]
fn turning_about_a_foot_moves_the_centre_on_a_circle_round_it() {
    let params = HumanoidParams { turn_pivot_mm: 28.0, step_yaw_sd_rad: 0.0, ..HUMANOID };
    let mut r = rng(5, 0);
    let mut b = HumanoidBody::new(params, Pose::default());
    let mut c =
        HumanoidBody::new(HumanoidParams { turn_pivot_mm: 0.0, step_yaw_sd_rad: 0.0, ..HUMANOID }, Pose::default());
    // Within the first step it pivots about the left foot, (0, 28) mm.
    run(&mut b, HumanoidCommand::TurnLeft, 10, &mut r);
    run(&mut c, HumanoidCommand::TurnLeft, 10, &mut r);
    let (moved, still) = (b.base.point().dist_mm(Point::new(0.0, 28.0)), c.base.point().dist_mm(Point::default()));
    assert!((moved - 28.0).abs() < 1e-9, "{:?}", b.base);
    assert!(b.base.point().dist_mm(Point::default()) > 1.0 && still < 1e-9, "{:?} {:?}", b.base, c.base);
    assert!((b.base.theta_rad() - c.base.theta_rad()).abs() < 1e-12);
}

#[test]
fn the_foot_lands_off_its_aim_by_a_fresh_error_every_kick() {
    let params = HumanoidParams { foot_aim_sd_mm: 15.0, ..HUMANOID };
    let mut r = rng(6, 0);
    let mut sides = Vec::new();
    for _ in 0..4 {
        let mut b = HumanoidBody::new(params, Pose::default());
        b.command(Command::Humanoid(HumanoidCommand::KickLeft), &mut r).expect("humanoid command");
        while !b.foot().active {
            b.substep(1.0 / 240.0, &mut r);
        }
        sides.push(b.foot().pose.y_mm());
    }
    assert!(sides.iter().all(|y| (y - HUMANOID.foot_side_mm).abs() > 1e-6), "{sides:?}");
    assert!(sides.windows(2).all(|w| w[0] != w[1]), "{sides:?}");
}

#[test]
fn a_camera_blind_while_walking_sees_only_standing() {
    let mut r = rng(7, 0);
    let mut b = HumanoidBody::new(HumanoidParams { blind_gait: 0.5, ..HUMANOID }, Pose::default());
    let ahead = Point::new(300.0, 0.0);
    assert!(b.sees(ahead));
    run(&mut b, HumanoidCommand::WalkForward, 10, &mut r);
    assert!(!b.sees(ahead));
    run(&mut b, HumanoidCommand::Wait, 10, &mut r);
    assert!(b.sees(ahead));
}

#[test]
fn camera_sees_ahead_and_pans() {
    let mut r = rng(4, 0);
    let mut b = HumanoidBody::new(HUMANOID, Pose::default());
    assert!(b.sees(Point::new(300.0, 0.0)));
    assert!(!b.sees(Point::new(0.0, 300.0)));
    run(&mut b, HumanoidCommand::ScanLeft, 15, &mut r);
    assert!(b.sees(Point::new(150.0, 300.0)));
    assert!(b.command(Command::Primitive(crate::Primitive::Forward), &mut r).is_err());
}
