//! Lapsing demonstrators on the field (docs/guides/crowd.md): ε = 0 is each controller bit for bit, ε = 1
//! is a random primitive every second in the body's own language, and a seed repeats its lapses.

use polymimic_field::controller::primitive_command;
use polymimic_field::{
    Command, Configuration, Demonstration, Demonstrator, Episode, EpisodeSetup, FieldConfig, FieldError,
    FieldParamError, Frame, LapseRate, Primitive, demonstrate, derive_seed, record, run_controller,
};

fn bits(frames: &[Frame]) -> Vec<[u64; 7]> {
    frames
        .iter()
        .map(|f| {
            [f.t_s, f.robot_x_mm, f.robot_y_mm, f.robot_theta_rad, f.ball_x_mm, f.ball_y_mm, f64::from(f.command)]
                .map(f64::to_bits)
        })
        .collect()
}

/// The demonstrator's controller alone, driving the episode as recording did before lapses.
fn unwrapped(d: Demonstrator, c: Configuration, seed: u64, config: &FieldConfig) -> Vec<Frame> {
    let setup = EpisodeSetup::configuration(d.body(), c, config);
    let mut episode = Episode::new(&setup, config, seed).expect("starts");
    let mut controller = d.controller(&polymimic_field::body::HUMANOID);
    let max_frames = (config.time_limit_s * 30.0).ceil() as usize + 1;
    run_controller(&mut episode, controller.as_mut(), max_frames).expect("runs");
    episode.into_frames()
}

fn rate(epsilon: f64) -> LapseRate {
    LapseRate::new(epsilon).expect("in [0, 1]")
}

#[test]
fn zero_lapse_gives_every_controllers_own_bits() {
    let config = FieldConfig::default();
    for d in Demonstrator::ALL {
        for c in Configuration::ALL {
            for seed in [0, 7, u64::MAX] {
                let lapsed = demonstrate(d, c, seed, LapseRate::NONE, &config).expect("runs");
                assert_eq!(bits(&lapsed.frames), bits(&unwrapped(d, c, seed, &config)), "{d:?} {c:?} {seed}");
            }
        }
    }
}

/// The commands of each second (30 frames from frame 0), asserting each second holds one.
fn seconds(demo: &Demonstration) -> Vec<u16> {
    demo.frames
        .chunks(30)
        .map(|s| {
            assert!(s.iter().all(|f| f.command == s[0].command), "{:?}: a second changes command", demo.demonstrator);
            s[0].command
        })
        .collect()
}

#[test]
fn full_lapse_is_a_random_primitive_each_second_in_the_bodys_language() {
    let config = FieldConfig::default();
    for d in Demonstrator::ALL {
        let mut counts = [0usize; 5];
        for i in 0..12 {
            let demo = demonstrate(d, Configuration::ALL[i % 2], derive_seed(3, 1, i as u64), rate(1.0), &config)
                .expect("runs");
            for id in seconds(&demo) {
                let p = Command::from_id(id).expect("a known command").primitive();
                assert_eq!(id, primitive_command(p, d.body()).id(), "{d:?}: {id} is not a lapse's command");
                counts[p.index()] += 1;
            }
        }
        // Every primitive shows up, none crowds out the rest (≈ 1/5 each, seen loosely here;
        // the lapse's own unit tests check uniformity over thousands of seconds).
        let total: usize = counts.iter().sum();
        assert!(total >= 60, "{d:?}: only {total} seconds");
        for (p, &n) in Primitive::WHEELED.iter().zip(&counts) {
            assert!(n > total / 20 && n < total / 2, "{d:?} {p:?}: {n} of {total} seconds ({counts:?})");
        }
    }
}

#[test]
fn the_humanoid_lapses_only_into_its_five_primitive_commands() {
    let demo =
        demonstrate(Demonstrator::Humanoid, Configuration::One, 4, rate(1.0), &FieldConfig::default()).expect("runs");
    // Walk Forward, Walk Backward, Turn Left, Turn Right, Wait: the humanoid takes no primitive.
    let ids = seconds(&demo);
    assert!(ids.iter().all(|id| [211, 214, 215, 216, 200].contains(id)), "{ids:?}");
}

#[test]
fn half_lapse_sends_primitives_in_about_half_of_the_experts_seconds() {
    // The Expert's own commands are of its wheel-speed language (ids ≥ 100): a second of
    // primitives (ids 0–4) is a lapse.
    let config = FieldConfig::default();
    let demos = record(Demonstrator::Expert, Configuration::Two, 40, 11, rate(0.5), &config).expect("records");
    let (mut lapsed, mut total) = (0, 0);
    for second in demos.iter().flat_map(|d| d.frames.chunks(30)) {
        total += 1;
        if second[0].command < 5 {
            lapsed += 1;
            assert!(second.iter().all(|f| f.command == second[0].command), "a lapse changes primitive");
        } else {
            assert!(second.iter().all(|f| f.command >= 100), "a primitive inside the Expert's own second");
        }
    }
    let share = f64::from(lapsed) / f64::from(total);
    assert!(total >= 1000, "only {total} seconds");
    assert!((share - 0.5).abs() < 0.05, "{lapsed} of {total} seconds lapsed");
}

#[test]
fn the_same_seed_repeats_the_lapses_and_another_changes_them() {
    let config = FieldConfig::default();
    for d in Demonstrator::ALL {
        let run = |seed| demonstrate(d, Configuration::One, seed, rate(0.5), &config).expect("runs");
        assert_eq!(bits(&run(21).frames), bits(&run(21).frames), "{d:?}");
        assert_ne!(bits(&run(21).frames), bits(&run(22).frames), "{d:?}");
        let own = demonstrate(d, Configuration::One, 21, LapseRate::NONE, &config).expect("runs");
        assert_ne!(bits(&run(21).frames), bits(&own.frames), "{d:?}: ε = 0.5 changed nothing");
        assert_eq!(run(21).lapse, rate(0.5));
    }
}

#[test]
fn recording_at_any_lapse_keeps_the_episode_seeds() {
    let mut config = FieldConfig::default();
    config.tracker.loss_probability = 0.0;
    let own = record(Demonstrator::Poor, Configuration::One, 3, 5, LapseRate::NONE, &config).expect("records");
    let lapsed = record(Demonstrator::Poor, Configuration::One, 3, 5, rate(0.9), &config).expect("records");
    // Poor's stream for configuration 1 is 111 (100 + 10 × its rank + the configuration).
    let seeds: Vec<u64> = (0..3).map(|i| derive_seed(5, 111, i)).collect();
    assert_eq!(own.iter().map(|d| d.seed).collect::<Vec<_>>(), seeds);
    assert_eq!(lapsed.iter().map(|d| d.seed).collect::<Vec<_>>(), seeds);
    assert_ne!(bits(&own[0].frames), bits(&lapsed[0].frames));
}

#[test]
fn an_out_of_range_lapse_is_refused_by_name() {
    for bad in [1.5, f64::NAN, -0.5] {
        let e = LapseRate::new(bad).expect_err("refused");
        assert!(matches!(e, FieldParamError::OutOfRange { name: "lapse", .. }), "{e:?}");
        let message = FieldError::from(e).to_string();
        assert!(message.contains("lapse") && message.contains("[0, 1]"), "{message}");
    }
}
