//! Finding kicks in a demonstration. A kick hardly moves the body (it leans back and creeps
//! forward again), so the segmenter's motion limits never end a segment at one: it vanishes
//! inside whatever the robot does next. What marks it is the ball, which starts to roll while
//! the body stands. Where it does, the second of frames around that start that the recogniser
//! names a kick most surely is cut out as a kick.

use polymimic_types::{Pose, Primitive, TrackedFrame};

use crate::recognizer::{Recognizer, best_two};

/// A self-observed kick lasts one second of the tracker's 30 frames (the babbler's primitive),
/// so the recogniser's kick model knows windows of that length.
pub const KICK_FRAMES: usize = 30;

/// Frames over which the ball's start is judged: a tenth of a second.
const BALL_WINDOW_FRAMES: usize = 3;

/// The ball has started to roll once it moves this far over the window (100 mm/s)…
const BALL_ROLLING_MM: f64 = 10.0;

/// …having moved less than this over the window before (at rest, up to the tracker's noise).
const BALL_RESTING_MM: f64 = 3.0;

/// The first frames of the kicks in `frames`, in order and never overlapping: for every frame
/// where the ball starts to roll, the window of [`KICK_FRAMES`] that contains it and whose kick
/// score leads every other primitive's by the most, if that lead is at least `gap_margin`.
/// Empty for a recogniser whose set has no kick.
pub(crate) fn kick_starts(
    frames: &[TrackedFrame],
    poses: &[Pose],
    recognizer: &Recognizer,
    gap_margin: f64,
) -> Vec<usize> {
    let set = recognizer.primitive_set();
    if !set.contains(Primitive::Kick) || frames.len() < KICK_FRAMES {
        return Vec::new();
    }
    let ball_moved_mm = |from: usize, to: usize| {
        (frames[to].ball_x_mm - frames[from].ball_x_mm).hypot(frames[to].ball_y_mm - frames[from].ball_y_mm)
    };
    let mut starts: Vec<usize> = Vec::new();
    let w = BALL_WINDOW_FRAMES;
    for rolls in w..frames.len() - w {
        if !(ball_moved_mm(rolls, rolls + w) > BALL_ROLLING_MM && ball_moved_mm(rolls - w, rolls) < BALL_RESTING_MM) {
            continue;
        }
        let free_from = starts.last().map_or(0, |&s| s + KICK_FRAMES - 1);
        let first = rolls.saturating_sub(KICK_FRAMES - 1).max(free_from);
        let last = rolls.min(frames.len() - KICK_FRAMES);
        let best = (first..=last)
            .filter_map(|start| {
                let (named, best_score, second_score) =
                    best_two(&recognizer.scores_unchecked(&poses[start..start + KICK_FRAMES]));
                (named == Primitive::Kick).then_some((start, best_score - second_score))
            })
            .filter(|&(_, lead)| lead >= gap_margin)
            // The surest window; the earliest of equals.
            .max_by(|a, b| a.1.total_cmp(&b.1).then(b.0.cmp(&a.0)));
        if let Some((start, _)) = best {
            starts.push(start);
        }
    }
    starts
}
