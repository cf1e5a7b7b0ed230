//! Cutting a demonstration into segments the imitator can name (thesis §3.2.2).
//!
//! Left to right, a segment takes at least `min_frames` frames. If by then the robot has
//! barely moved it is a stop (and a stop right after a stop extends it). Otherwise it grows
//! until its motion since its first frame is more than any primitive can produce, and ends on
//! the frame before; the recogniser then names it, or calls it a gap when the best two models
//! score within `gap_margin` of each other. Consecutive segments share their boundary frame,
//! so each starts where the last one ended. A recogniser that knows a kick first finds the
//! demonstration's kicks by the ball ([`crate::kick`]): each is a segment of its own, a second
//! long whatever `min_frames`, and the segment before it ends where it starts (a stretch too
//! short to be a segment joins the one before, or is a gap after a kick).

use polymimic_types::{Pose, Primitive, TrackedFrame};
use serde::{Deserialize, Serialize};

use crate::error::PerceiveError;
use crate::kick::{KICK_FRAMES, kick_starts};
use crate::label::Label;
use crate::motion::MotionLimits;
use crate::recognizer::{NO_SCORES, Recognizer, Scores, best_two, check_poses};

/// The segmenter's thresholds; the defaults are the thesis's.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SegmenterConfig {
    pub min_frames: usize,
    /// A segment that moved less than this…
    pub stop_distance_mm: f64,
    /// …and turned less than this by `min_frames` frames is a stop.
    pub stop_rotation_deg: f64,
    /// A segment is cut once it moves or turns more than mean + this many standard
    /// deviations of the largest primitive's motion (Table 3.1).
    pub limit_sds: f64,
    /// Best two log-likelihoods closer than this make a gap.
    pub gap_margin: f64,
}

impl Default for SegmenterConfig {
    fn default() -> Self {
        Self { min_frames: 10, stop_distance_mm: 1.0, stop_rotation_deg: 20.0, limit_sds: 2.0, gap_margin: 2.0 }
    }
}

impl SegmenterConfig {
    fn check(&self) -> Result<(), PerceiveError> {
        let bad = |name, value: f64, why| Err(PerceiveError::Parameter { name, value, why });
        if self.min_frames < 2 {
            return bad("min_frames", self.min_frames as f64, "at least 2");
        }
        for (name, value) in [
            ("stop_distance_mm", self.stop_distance_mm),
            ("stop_rotation_deg", self.stop_rotation_deg),
            ("limit_sds", self.limit_sds),
            ("gap_margin", self.gap_margin),
        ] {
            if !(value.is_finite() && value >= 0.0) {
                return bad(name, value, "a finite number ≥ 0");
            }
        }
        Ok(())
    }
}

/// A named stretch of a demonstration.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Segment {
    pub label: Label,
    pub first_frame: usize,
    pub last_frame: usize,
    pub start: TrackedFrame,
    pub end: TrackedFrame,
    /// log-likelihoods of every moving primitive in [`Scores`]' slots (all −inf for a stop,
    /// never scored).
    pub scores: Scores,
}

/// Segments `frames` with `recognizer`. A tail shorter than `min_frames` after the last
/// segment is left unsegmented.
///
/// # Errors
/// Fewer than `min_frames` frames, a non-finite frame, or a threshold out of range.
pub fn segment(
    frames: &[TrackedFrame],
    recognizer: &Recognizer,
    config: &SegmenterConfig,
) -> Result<Vec<Segment>, PerceiveError> {
    config.check()?;
    let poses: Vec<Pose> = frames.iter().map(|f| f.robot).collect();
    check_poses(&poses, "demonstration", config.min_frames)?;
    if let Some(frame) = frames.iter().position(|f| !(f.ball_x_mm.is_finite() && f.ball_y_mm.is_finite())) {
        return Err(PerceiveError::NotFinite { what: "demonstration (ball)".to_owned(), frame });
    }
    let limits = MotionLimits::from_stats(recognizer.motion_stats(), config.limit_sds);
    let mut kicks = kick_starts(frames, &poses, recognizer, config.gap_margin).into_iter().peekable();
    let scored = |first: usize, last: usize| {
        let scores = recognizer.scores_unchecked(&poses[first..=last]);
        Segment {
            label: named(&scores, config.gap_margin),
            first_frame: first,
            last_frame: last,
            start: frames[first],
            end: frames[last],
            scores,
        }
    };
    let mut segments: Vec<Segment> = Vec::new();
    let mut first = 0;
    while first + config.min_frames <= frames.len() {
        let next_kick = kicks.peek().copied();
        if next_kick == Some(first) {
            kicks.next();
            // Named a kick: its window was chosen for leading the others by the gap margin.
            segments.push(scored(first, first + KICK_FRAMES - 1));
            first += KICK_FRAMES - 1;
            continue;
        }
        // The last frame this segment may reach: a kick ahead ends it.
        let end = next_kick.unwrap_or(frames.len() - 1);
        if first + config.min_frames - 1 > end {
            // Too little before a kick for a segment of its own: the one before grows to the kick
            // (a stop stays a stop, a moving one is named again); after a kick or at the start,
            // it stands alone as a gap.
            match segments.last_mut() {
                Some(previous) if previous.label == Label::Primitive(Primitive::Stop) => {
                    previous.last_frame = end;
                    previous.end = frames[end];
                }
                Some(previous) if previous.label != Label::Primitive(Primitive::Kick) => {
                    *previous = scored(previous.first_frame, end);
                }
                _ => segments.push(Segment { label: Label::Gap, ..scored(first, end) }),
            }
            first = end;
            continue;
        }
        let mut last = first + config.min_frames - 1;
        let origin = &poses[first];
        let is_stop = poses[last].distance_from_mm(origin) < config.stop_distance_mm
            && poses[last].rotation_from_rad(origin).to_degrees().abs() < config.stop_rotation_deg;
        if is_stop {
            match segments.last_mut() {
                Some(previous) if previous.label == Label::Primitive(Primitive::Stop) => {
                    previous.last_frame = last;
                    previous.end = frames[last];
                }
                _ => segments.push(Segment {
                    label: Label::Primitive(Primitive::Stop),
                    first_frame: first,
                    last_frame: last,
                    start: frames[first],
                    end: frames[last],
                    scores: NO_SCORES,
                }),
            }
        } else {
            while last < end && within(&poses[last + 1], origin, &limits) {
                last += 1;
            }
            segments.push(scored(first, last));
        }
        first = last;
    }
    Ok(segments)
}

/// [`segment`] for many demonstrations, in parallel; results in the input's order.
///
/// # Errors
/// As [`segment`], for the first demonstration (in order) that fails.
pub fn segment_many(
    demonstrations: &[&[TrackedFrame]],
    recognizer: &Recognizer,
    config: &SegmenterConfig,
) -> Result<Vec<Vec<Segment>>, PerceiveError> {
    use rayon::prelude::*;
    demonstrations
        .par_iter()
        .enumerate()
        .map(|(index, frames)| {
            segment(frames, recognizer, config).map_err(|e| match e {
                PerceiveError::TooFewFrames { frames, needed, .. } => {
                    PerceiveError::TooFewFrames { what: format!("demonstration {index}"), frames, needed }
                }
                PerceiveError::NotFinite { frame, .. } => {
                    PerceiveError::NotFinite { what: format!("demonstration {index}"), frame }
                }
                other => other,
            })
        })
        .collect()
}

/// A moving segment's name: the best-scoring primitive, or a gap when the best two score within
/// `gap_margin` of each other (or none can have produced it).
fn named(scores: &Scores, gap_margin: f64) -> Label {
    let (best, best_score, second_score) = best_two(scores);
    if best_score - second_score < gap_margin || best_score == f64::NEG_INFINITY {
        Label::Gap
    } else {
        Label::Primitive(best)
    }
}

fn within(pose: &Pose, origin: &Pose, limits: &MotionLimits) -> bool {
    pose.distance_from_mm(origin) <= limits.max_distance_mm
        && pose.rotation_from_rad(origin).to_degrees().abs() <= limits.max_rotation_deg
}
