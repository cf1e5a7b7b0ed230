//! Processing one demonstration by prediction rounds (thesis §3.4, Fig 3.17).
//!
//! From the end of the current segment every behaviour predicts once. The predictions are
//! compared with the end of the next segment, then the one after, for as long as at least
//! one still matches; among those matching the furthest segment reached, behaviours with an
//! accurate ball prediction are preferred, then the fewest primitives, then the oldest.

use polymimic_perceive::{Label, Segment};
use polymimic_types::{Primitive, TrackedFrame, wrap_angle_euclid_rad};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use crate::config::{LearningConfig, LpApproachWeight, LpScope};
use crate::model::{Event, ForwardModel};
use crate::prediction::{MotionTable, Prediction, matches, predict};
use crate::shaping::{LpCause, approach_causes};
use crate::state::{Pitch, range_bearing};

/// How a demonstration ended, as far as learning is concerned.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Ending {
    Goal,
    OwnGoal,
    Other,
}

impl From<polymimic_field::Outcome> for Ending {
    fn from(outcome: polymimic_field::Outcome) -> Self {
        match outcome {
            polymimic_field::Outcome::Goal => Ending::Goal,
            polymimic_field::Outcome::OwnGoal => Ending::OwnGoal,
            _ => Ending::Other,
        }
    }
}

/// A demonstration as the learner sees it: who, where, how it ended, and its segments.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SegmentedDemonstration {
    pub demonstrator: String,
    pub pitch: Pitch,
    /// How far from its centre the demonstrator's body moves the ball (see
    /// [`crate::reach_mm`]), where known.
    #[serde(default)]
    pub reach_mm: Option<f64>,
    pub ending: Ending,
    pub segments: Vec<Segment>,
}

fn primitive_of(segment: &Segment) -> Option<Primitive> {
    match segment.label {
        Label::Primitive(p) => Some(p),
        Label::Gap => None,
    }
}

/// The next segment at or after `from` named by a primitive, with that primitive.
fn next_primitive(segments: &[Segment], from: usize) -> Option<(usize, Primitive)> {
    segments.iter().enumerate().skip(from).find_map(|(i, s)| primitive_of(s).map(|p| (i, p)))
}

/// How far one round's predictions held: the last segment reached and the behaviours whose
/// predictions matched it.
struct Span {
    reached: usize,
    matched: Vec<usize>,
}

impl ForwardModel {
    /// Learns from one demonstration; returns the events the trial must act on.
    pub fn process(
        &mut self,
        demo: &SegmentedDemonstration,
        motion: &MotionTable,
        config: &LearningConfig,
        rng: &mut ChaCha8Rng,
    ) -> Vec<Event> {
        self.process_weighted(demo, 1.0, motion, config, rng)
    }

    /// [`Self::process`] with what the demonstration gives scaled by `weight`: every
    /// frequency step (eq 3.11) and permanency step it earns, not the decay (eq 3.12), so a
    /// behaviour seen only in demonstrations of small weight gains little and decays away.
    /// A weight of 1 is [`Self::process`].
    pub fn process_weighted(
        &mut self,
        demo: &SegmentedDemonstration,
        weight: f64,
        motion: &MotionTable,
        config: &LearningConfig,
        rng: &mut ChaCha8Rng,
    ) -> Vec<Event> {
        let segments = &demo.segments;
        let mut events = Vec::new();
        let Some((mut c, first)) = next_primitive(segments, 0) else { return events };
        let mut current: Vec<Primitive> = vec![first];
        // What happens in a demonstration says something of its demonstrator only.
        let shapes_lp = config.lp_scope == LpScope::Every || demo.demonstrator == self.name;
        while c + 1 < segments.len() {
            self.metrics.rounds += 1;
            let start = segments[c].end;
            let predictions: Vec<Prediction> =
                self.behaviours.iter().map(|b| predict(b, start.robot, motion, config, rng)).collect();
            let Some(span) = self.longest_span(segments, c, &predictions, config) else {
                // Nobody spans even the next segment: start over from its primitive.
                match next_primitive(segments, c + 1) {
                    Some((next, p)) => {
                        c = next;
                        current = vec![p];
                        continue;
                    }
                    None => break,
                }
            };
            self.metrics.rounds_matched += 1;
            let end = segments[span.reached].end;
            let ball_accurate = accurate_ball_predictions(&span.matched, &predictions, &start, &end, config);
            let selected = self.choose_behaviour(&span.matched, &ball_accurate);
            let selected_primitives = self.behaviours[selected].primitives.clone();
            self.count_what_followed(&current, selected, &ball_accurate, shapes_lp, weight, config);
            let selected = self.index_of(&selected_primitives).unwrap_or(selected);
            self.reinforce(selected, weight, config);
            self.behaviours[selected].record_span(&start, &end, &demo.pitch, config);
            self.decay(config);
            if shapes_lp {
                self.shape_lp_over_span(demo, c, span.reached, config);
            }
            events.extend(self.settle(config));
            c = span.reached;
            current = self.next_current(selected_primitives, &segments[span.reached]);
        }
        events
    }

    /// The behaviours whose predictions match the end of `segment` (on a gap, only those of
    /// more than one primitive).
    fn matching(&self, predictions: &[Prediction], segment: &Segment, config: &LearningConfig) -> Vec<usize> {
        let gap = segment.label == Label::Gap;
        (0..predictions.len())
            .filter(|&i| !(gap && self.behaviours[i].is_primitive()))
            .filter(|&i| matches(&predictions[i].end(), &segment.end.robot, config))
            .collect()
    }

    /// The longest span of segments after `current` that some prediction still matches, and
    /// who matched its last segment; `None` if nobody matches even the next segment.
    fn longest_span(
        &self,
        segments: &[Segment],
        current: usize,
        predictions: &[Prediction],
        config: &LearningConfig,
    ) -> Option<Span> {
        let mut reached = current + 1;
        let mut matched = self.matching(predictions, &segments[reached], config);
        if matched.is_empty() {
            return None;
        }
        while reached + 1 < segments.len() {
            let further = self.matching(predictions, &segments[reached + 1], config);
            if further.is_empty() {
                break;
            }
            reached += 1;
            matched = further;
        }
        Some(Span { reached, matched })
    }

    /// Of the behaviours that matched, those that also predicted the ball accurately if any
    /// did, and of those the one with the fewest primitives, the oldest on a tie.
    fn choose_behaviour(&self, matched: &[usize], ball_accurate: &[usize]) -> usize {
        let pool = if ball_accurate.is_empty() { matched } else { ball_accurate };
        *pool
            .iter()
            .min_by_key(|&&i| (self.behaviours[i].primitives.len(), self.behaviours[i].age))
            .unwrap_or(&matched[0])
    }

    /// Eq 3.11 for every behaviour that followed the current one: the selected one, and each
    /// that predicted the ball accurately, each of those also raising the LP.
    fn count_what_followed(
        &mut self,
        current: &[Primitive],
        selected: usize,
        ball_accurate: &[usize],
        shapes_lp: bool,
        weight: f64,
        config: &LearningConfig,
    ) {
        let from = self.index_of(current);
        for &i in ball_accurate.iter().filter(|&&i| i != selected) {
            if shapes_lp {
                self.shape_lp(LpCause::BallPredicted, config);
            }
            if let Some(from) = from {
                self.follow(from, i, weight, config);
            }
        }
        if ball_accurate.contains(&selected) && shapes_lp {
            self.shape_lp(LpCause::BallPredicted, config);
        }
        if let Some(from) = from {
            self.follow(from, selected, weight, config);
        }
    }

    /// Eq 3.13 over the span from segment `from` to segment `reached`. Under
    /// `PerDemonstration`, a span's approach criteria weigh by the share of the demonstration
    /// it covers, so each demonstration weighs the same.
    fn shape_lp_over_span(
        &mut self,
        demo: &SegmentedDemonstration,
        from: usize,
        reached: usize,
        config: &LearningConfig,
    ) {
        let segments = &demo.segments;
        let last = reached + 1 == segments.len();
        let share = (reached - from) as f64 / (segments.len() - 1) as f64;
        for cause in span_causes(demo, &segments[from], &segments[reached], last, config).into_iter().flatten() {
            let weight = match (config.lp_approach_weight, cause) {
                (_, LpCause::Goal | LpCause::OwnGoal) | (LpApproachWeight::PerSpan, _) => 1.0,
                (LpApproachWeight::PerDemonstration, _) => share,
            };
            self.shape_lp_weighted(cause, weight, config);
        }
    }

    /// The behaviour the next round starts from: the selected one if it survived settling,
    /// else the primitive the span's last segment was named by (or the selected one's first).
    fn next_current(&self, selected_primitives: Vec<Primitive>, reached: &Segment) -> Vec<Primitive> {
        if self.index_of(&selected_primitives).is_some() {
            selected_primitives
        } else {
            primitive_of(reached).map_or_else(|| vec![selected_primitives[0]], |p| vec![p])
        }
    }

    /// Behaviour `to` followed behaviour `from`: eq 3.11, and past the creation threshold
    /// their concatenation is created (or, if it exists, reinforced), the steps scaled by
    /// `weight`.
    fn follow(&mut self, from: usize, to: usize, weight: f64, config: &LearningConfig) {
        if !self.strengthen(from, to, weight, config) {
            return;
        }
        self.frequency[from][to] = 0.0;
        let mut joined = self.behaviours[from].primitives.clone();
        joined.extend_from_slice(&self.behaviours[to].primitives);
        match self.index_of(&joined) {
            Some(existing) => self.reinforce(existing, weight, config),
            None => {
                self.insert(joined, config);
            }
        }
    }
}

/// The matched behaviours whose ball prediction came true: the ball moved over the span, and
/// the predicted bearing of the ball from the robot is within the ball angle tolerance of
/// where it ended.
fn accurate_ball_predictions(
    matched: &[usize],
    predictions: &[Prediction],
    start: &TrackedFrame,
    end: &TrackedFrame,
    config: &LearningConfig,
) -> Vec<usize> {
    let ball_moved = (end.ball_x_mm - start.ball_x_mm).hypot(end.ball_y_mm - start.ball_y_mm) > config.ball_moved_mm;
    let actual_bearing = range_bearing(&end.robot, end.ball_x_mm, end.ball_y_mm).1;
    matched
        .iter()
        .copied()
        .filter(|&i| {
            ball_moved
                && predictions[i].ball.is_some_and(|(bearing, _)| {
                    wrap_angle_euclid_rad((bearing - actual_bearing).to_radians()).to_degrees().abs()
                        <= config.ball_angle_tolerance_deg
                })
        })
        .collect()
}

/// Eq 3.13 over a span: a goal or own goal outweighs everything; otherwise the approach
/// criteria count.
fn span_causes(
    demo: &SegmentedDemonstration,
    from: &Segment,
    to: &Segment,
    last: bool,
    config: &LearningConfig,
) -> [Option<LpCause>; 2] {
    match demo.ending {
        Ending::Goal if last => [Some(LpCause::Goal), None],
        Ending::OwnGoal if last => [Some(LpCause::OwnGoal), None],
        _ => approach_causes(&from.end, &to.end, &demo.pitch, config),
    }
}
