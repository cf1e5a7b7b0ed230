//! The humanoid imitator recognises its own primitive classes (docs/guides/bodies.md): a recogniser trained
//! on the humanoid's self-observation over its own eight tells held-out seconds of each moving
//! class apart.

use polymimic_field::{BodyKind, FieldConfig, PrimitiveSequence, self_observation_of_set};
use polymimic_perceive::{LabelledSequence, Pose, Primitive, PrimitiveSet, Recognizer, RecognizerConfig};

fn observed(n_per_primitive: usize, seed: u64) -> Vec<LabelledSequence> {
    let sequences = self_observation_of_set(
        BodyKind::Humanoid,
        PrimitiveSet::Humanoid,
        n_per_primitive,
        seed,
        &FieldConfig::default(),
    )
    .expect("the humanoid babbles");
    sequences.iter().map(labelled).collect()
}

fn labelled(sequence: &PrimitiveSequence) -> LabelledSequence {
    let poses = sequence.frames.iter().map(|f| Pose::new(f.robot_x_mm, f.robot_y_mm, f.robot_theta_rad)).collect();
    LabelledSequence { primitive: sequence.primitive, poses }
}

fn humanoid_config() -> RecognizerConfig {
    RecognizerConfig { primitives: PrimitiveSet::Humanoid, ..RecognizerConfig::default() }
}

/// Held-out seconds of each moving class it names right, of 40: measured 40 40 39 40 40 40 33
/// (seed 1 trains on 100 of each, seed 2 holds out 40). The kick, a lean back and a small creep
/// forward, is the one it confuses: 5 held-out kicks read as stepping backward, 2 as turning left.
#[test]
fn the_humanoid_imitators_recogniser_tells_its_own_classes_apart() {
    let recognizer = Recognizer::train(&observed(100, 1), humanoid_config()).expect("trains");
    let moving: Vec<Primitive> = recognizer.models().iter().map(|m| m.primitive).collect();
    assert_eq!(moving, PrimitiveSet::Humanoid.moving());
    let held_out = observed(40, 2);
    let mut total = 0;
    for &primitive in PrimitiveSet::Humanoid.moving() {
        let of_it: Vec<&LabelledSequence> = held_out.iter().filter(|s| s.primitive == primitive).collect();
        assert_eq!(of_it.len(), 40);
        let named: Vec<Primitive> = of_it.iter().map(|s| recognizer.classify(&s.poses).expect("scores")).collect();
        let correct = named.iter().filter(|&&p| p == primitive).count();
        let least = if primitive == Primitive::Kick { 30 } else { 36 };
        assert!(correct >= least, "{}: {correct}/40 named right; named {named:?}", primitive.name());
        total += correct;
    }
    assert!(total >= 266, "{total}/280 named right");
    // Its Table 3.1 covers all eight, and a kick ends about 10 mm back (15 leaned, 5 crept).
    let stats = recognizer.motion_stats();
    assert_eq!(stats.iter().map(|s| s.primitive).collect::<Vec<_>>(), Primitive::ALL);
    let kick = stats[Primitive::Kick.index()];
    assert!((-14.0..-6.0).contains(&kick.distance_mean_mm), "{kick:?}");
}

#[test]
fn a_recogniser_refuses_a_primitive_outside_its_set_and_keeps_its_set_in_its_file() {
    let sequences = observed(5, 3);
    let wheeled = Recognizer::train(&sequences, RecognizerConfig { codebook_size: 16, ..RecognizerConfig::default() });
    let Err(error) = wheeled else { panic!("the wheeled set has no side-steps or kick") };
    assert!(error.to_string().contains("not a primitive of the wheeled set"), "{error}");
    let config = RecognizerConfig { codebook_size: 16, ..humanoid_config() };
    let humanoid = Recognizer::train(&sequences, config).expect("trains");
    let text = humanoid.to_json().expect("saves");
    assert!(text.contains(r#"\"primitives\":\"humanoid\""#) || text.contains(r#""primitives":"humanoid""#));
    let again = Recognizer::from_json(&text).expect("reads back");
    assert_eq!(again, humanoid);
    assert_eq!(again.primitive_set(), PrimitiveSet::Humanoid);
    // A file whose models are not its set's is damaged.
    let bare = text.replace(r#""primitives":"humanoid""#, "").replace(r#"\"primitives\":\"humanoid\""#, "");
    assert!(Recognizer::from_json(&bare.replace(",}", "}").replace(",,", ",")).is_err());
}

/// The Humanoid's demonstrations cut by its own recogniser: every kick is a second of its own
/// wherever `min_frames` stands (the stretch before one may be shorter than `min_frames`, then it
/// joins the segment before or stands as a gap), consecutive segments share their boundary frame,
/// and a wheeled recogniser, which knows no kick, cuts none.
#[test]
fn kicks_are_cut_as_seconds_of_their_own_and_segments_still_tile() {
    use polymimic_field::{Configuration, Demonstrator, Frame, LapseRate, record};
    use polymimic_perceive::{KICK_FRAMES, Label, SegmenterConfig, segment};

    let config = FieldConfig::default();
    let humanoid = Recognizer::train(&observed(60, 1), humanoid_config()).expect("trains");
    let wheeled_sequences: Vec<LabelledSequence> =
        observed(60, 1).into_iter().filter(|s| PrimitiveSet::Wheeled.contains(s.primitive)).collect();
    let wheeled = Recognizer::train(&wheeled_sequences, RecognizerConfig::default()).expect("trains");
    let demos = record(Demonstrator::Humanoid, Configuration::One, 10, 0, LapseRate::NONE, &config).expect("records");
    let mut kicks_at_ten = 0;
    for min_frames in [10, 25, 40] {
        let segmenter = SegmenterConfig { min_frames, ..SegmenterConfig::default() };
        for demo in &demos {
            let tracked: Vec<_> = demo.frames.iter().map(Frame::tracked).collect();
            let segments = segment(&tracked, &humanoid, &segmenter).expect("segments");
            assert_eq!(segments.first().map(|s| s.first_frame), Some(0));
            for pair in segments.windows(2) {
                assert_eq!(pair[1].first_frame, pair[0].last_frame, "segments tile");
                assert!(pair[0].last_frame > pair[0].first_frame);
            }
            for kick in segments.iter().filter(|s| s.label == Label::Primitive(Primitive::Kick)) {
                assert_eq!(kick.last_frame - kick.first_frame, KICK_FRAMES - 1);
                kicks_at_ten += usize::from(min_frames == 10);
            }
            if min_frames == 10 {
                let by_wheeled = segment(&tracked, &wheeled, &segmenter).expect("segments");
                assert!(by_wheeled.iter().all(|s| s.label != Label::Primitive(Primitive::Kick)));
            }
        }
    }
    // The Humanoid kicks once or twice in each of these ten demonstrations.
    assert!(kicks_at_ten >= 8, "{kicks_at_ten} kicks cut");
}
