//! Demonstrator skill regression (Table 4.6 shape): 25 valid demonstrations per configuration
//! (50 per demonstrator) with fixed seeds. The Expert scores most and rarely on itself; Poor,
//! driving straight at the ball, scores on itself whenever the ball sits before its own goal;
//! the tiny robot and the humanoid score often with few own goals.

use polymimic_field::{Demonstrator, FieldConfig, LapseRate, Outcome, record_all};

#[test]
fn demonstrators_have_the_thesis_skill_ordering() {
    let config = FieldConfig::default();
    let demos = record_all(&Demonstrator::ALL, 25, 2024, LapseRate::NONE, &config).expect("records");
    assert_eq!(demos.len(), Demonstrator::ALL.len() * 50);
    let count = |d: Demonstrator, o: Outcome| demos.iter().filter(|x| x.demonstrator == d && x.outcome == o).count();
    for d in Demonstrator::ALL {
        println!(
            "{:9} goals {:2}  own goals {:2}  ball out {:2}  robot out {:2}  time up {:2}",
            d.name(),
            count(d, Outcome::Goal),
            count(d, Outcome::OwnGoal),
            count(d, Outcome::BallOut),
            count(d, Outcome::RobotOut),
            count(d, Outcome::TimeUp)
        );
    }
    assert!(demos.iter().all(|d| d.valid && !d.frames.is_empty()));
    let goals = |d| count(d, Outcome::Goal);
    let own = |d| count(d, Outcome::OwnGoal);
    assert!(goals(Demonstrator::Expert) >= 25 && own(Demonstrator::Expert) <= 6);
    assert!(own(Demonstrator::Poor) >= 15);
    for d in [Demonstrator::Expert, Demonstrator::Tiny, Demonstrator::Humanoid] {
        assert!(own(Demonstrator::Poor) > own(d), "{d:?}");
    }
    for d in [Demonstrator::Tiny, Demonstrator::Humanoid] {
        assert!(goals(d) >= 10 && own(d) <= 6, "{d:?}");
    }
}

#[test]
fn recording_is_identical_across_thread_counts() {
    let config = FieldConfig::default();
    let run = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("pool")
            .install(|| record_all(&[Demonstrator::Expert, Demonstrator::Humanoid], 3, 5, LapseRate::NONE, &config))
            .expect("records")
    };
    let (one, two) = (run(1), run(2));
    assert_eq!(one.len(), two.len());
    for (a, b) in one.iter().zip(&two) {
        assert_eq!(a.seed, b.seed);
        assert_eq!(a.outcome, b.outcome);
        let bits = |f: &polymimic_field::Frame| {
            [f.robot_x_mm, f.robot_y_mm, f.robot_theta_rad, f.ball_x_mm, f.ball_y_mm].map(f64::to_bits)
        };
        assert!(a.frames.iter().map(bits).eq(b.frames.iter().map(bits)));
    }
}
