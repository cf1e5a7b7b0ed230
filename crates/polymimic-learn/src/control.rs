//! The imitator's final model driving a robot on the field (thesis §3.4, end), by the
//! thesis's rule or an improved one (see [`ControlMode`]).
//!
//! By the thesis's rule, at each decision the behaviours whose preconditions the current state meets (every
//! measure within one standard deviation of its mean) are considered, or all of them if none
//! applies. Each predicts its outcome and the best by the learning-preference criteria — a
//! predicted goal, then the ball nearer the goal, then the robot nearer the ball — is executed
//! primitive by primitive, stopping early if the next primitive would take the robot off the
//! field.

use polymimic_field::{
    BodyKind, Configuration, Episode, EpisodeSetup, FieldConfig, FieldError, Frame, Outcome, Start, derive_seed,
};
use polymimic_types::{Point, Primitive, TrackedFrame};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::config::LearningConfig;
use crate::model::ForwardModel;
use crate::prediction::{MotionTable, predict};
use crate::prefix_tree::PrefixTree;
use crate::shaping::approach_shaping;
use crate::state::{Pitch, ball_to_goal_mm, robot_to_ball_mm};
use crate::world::WorldModel;

/// One attempt of the imitator at the penalty kick.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Attempt {
    /// The thesis's configuration it started from, if it did.
    pub configuration: Option<Configuration>,
    /// Where it started.
    pub start: Start,
    pub seed: u64,
    pub outcome: Outcome,
    pub frames: Vec<Frame>,
    /// What was executed, in order, as letters: whole behaviours by the thesis's rule, single
    /// primitives by the improved one.
    pub behaviours: Vec<String>,
}

/// How the imitator's model drives the robot.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ControlMode {
    /// The thesis's rule: the applicable behaviours (else all) predict with their own ball
    /// statistics; the best by the LP criteria runs to its end.
    #[default]
    Thesis,
    /// The thesis's future work: every behaviour predicts the ball with the ball response
    /// learned from all the demonstrations (§5.4), and its predicted end is rated by a goal (the
    /// sooner the better, with `prefer_sooner_goals`), then by whether the demonstrations
    /// passing near it ended, on balance, in own goals, then by how much nearer the goal it puts
    /// the ball, then the robot to the ball; only the first primitive runs before choosing
    /// again, so a behaviour that comes to rate better takes over at once (§4.4.1).
    /// Preconditions are not consulted: every behaviour competes. Behaviours push only from
    /// where the demonstrators pushed toward the goal (relative to the ball and the goal,
    /// [`PushRegion`](crate::PushRegion)), or when one predicts a goal; anywhere else the robot
    /// takes the shortest route there in its own primitives
    /// ([`ApproachPlan`](crate::ApproachPlan)), going round the ball rather than through it.
    Improved,
}

/// The imitator's model with what it needs to predict, and the body it drives (on that body's
/// field: [`Self::pitch`]).
#[derive(Clone, Copy)]
pub struct ImitatorPolicy<'a> {
    pub model: &'a ForwardModel,
    pub motion: &'a MotionTable,
    pub config: &'a LearningConfig,
    pub body: BodyKind,
    pub mode: ControlMode,
    /// What the improved mode predicts and rates with (without it the ball is predicted to
    /// stay and every state is safe).
    pub world: Option<&'a WorldModel>,
}

impl ImitatorPolicy<'_> {
    /// The field the imitator's body plays on.
    #[must_use]
    pub const fn pitch(&self) -> Pitch {
        Pitch::of_body(self.body)
    }

    /// The behaviour to execute next from `state`, by the thesis's rule; `None` if every
    /// behaviour's first primitive would leave the field.
    pub fn choose(&self, state: &TrackedFrame, rng: &mut ChaCha8Rng) -> Option<usize> {
        let behaviours = &self.model.behaviours;
        let mut stays = |i: &usize| {
            let first = self.motion.step(state.robot, behaviours[*i].primitives[0], f64::INFINITY, rng);
            self.pitch().contains(first.x_mm(), first.y_mm())
        };
        let mut candidates: Vec<usize> = (0..behaviours.len())
            .filter(|&i| behaviours[i].applies_to(state, &self.pitch()))
            .filter(&mut stays)
            .collect();
        if candidates.is_empty() {
            candidates = (0..behaviours.len()).filter(&mut stays).collect();
        }
        candidates
            .into_iter()
            .map(|i| (self.rate(i, state, rng), i))
            .max_by(|(a, i), (b, j)| {
                a.0.total_cmp(&b.0)
                    .then(a.1.total_cmp(&b.1))
                    .then(behaviours[*j].primitives.len().cmp(&behaviours[*i].primitives.len()))
                    .then(behaviours[*j].age.cmp(&behaviours[*i].age))
            })
            .map(|(_, i)| i)
    }

    /// The LP criteria applied to behaviour `index`'s prediction from `state`, and how much
    /// nearer the ball the robot is predicted to get (mm), to break ties.
    fn rate(&self, index: usize, state: &TrackedFrame, rng: &mut ChaCha8Rng) -> (f64, f64) {
        let config = self.config;
        let prediction = predict(&self.model.behaviours[index], state.robot, self.motion, config, rng);
        let ball = prediction.ball_position().unwrap_or((state.ball_x_mm, state.ball_y_mm));
        let after = TrackedFrame { robot: prediction.end(), ball_x_mm: ball.0, ball_y_mm: ball.1 };
        let (bx, by) = ball;
        if self.pitch().in_target_goal(bx, by) {
            return (config.lp_goal, 0.0);
        }
        if self.pitch().in_own_goal(bx, by) {
            return (-config.lp_goal, 0.0);
        }
        let score = approach_shaping(state, &after, &self.pitch(), config);
        (score, robot_to_ball_mm(state) - robot_to_ball_mm(&after))
    }
}

impl ImitatorPolicy<'_> {
    /// The improved mode's choice from `state`. Where the demonstrators pushed from (or when a
    /// behaviour predicts a goal, or no route is known): the first primitive of the behaviour
    /// whose predicted outcome rates best. Elsewhere: the next primitive of the route there.
    /// `None` if every behaviour would leave the field at once.
    pub(crate) fn choose_primitive(&self, tree: &PrefixTree, state: &TrackedFrame) -> Option<Primitive> {
        let behaviours = &self.model.behaviours;
        let ratings = self.outcomes(tree, state);
        let (rating, best) =
            ratings.iter().enumerate().filter_map(|(i, rating)| rating.map(|rating| (rating, i))).max_by(
                |(a, i), (b, j)| {
                    a.total_cmp(b, self.config.prefer_sooner_goals)
                        .then(behaviours[*j].primitives.len().cmp(&behaviours[*i].primitives.len()))
                        .then(behaviours[*j].age.cmp(&behaviours[*i].age))
                },
            )?;
        let approach = self.world.and_then(|w| w.approach.as_ref()).filter(|_| rating.goal <= 0.0);
        approach.and_then(|plan| plan.next(state, self.motion, &self.pitch())).or(Some(behaviours[best].primitives[0]))
    }

    /// Every behaviour's rated outcome from `state` (see [`Self::walk`]), by index; `tree` holds
    /// the behaviours' sequences, so each beginning they share is predicted once.
    fn outcomes(&self, tree: &PrefixTree, state: &TrackedFrame) -> Vec<Option<Rating>> {
        let mut ratings = vec![None; self.model.behaviours.len()];
        let root = &tree.nodes[0];
        if !root.ending.is_empty() {
            let rating = Some(self.rate_end(state, state, 0));
            root.ending.iter().for_each(|&b| ratings[b] = rating);
        }
        let rng = ChaCha8Rng::seed_from_u64(0);
        for &child in &root.children {
            self.walk(tree, child, state, *state, 0, rng.clone(), &mut ratings);
        }
        ratings
    }

    /// Chains the behaviours below `node` from `now` (reached after `depth` primitives from
    /// `start`) with the mean motion of each primitive and the learned ball response, stopping
    /// where the robot would leave the field or the ball reaches a goal, and rates where each
    /// ends (see [`Self::rate_end`]). A behaviour whose first primitive leaves the field gets no
    /// rating.
    #[allow(clippy::too_many_arguments)]
    fn walk(
        &self,
        tree: &PrefixTree,
        node: usize,
        start: &TrackedFrame,
        now: TrackedFrame,
        depth: usize,
        mut rng: ChaCha8Rng,
        ratings: &mut [Option<Rating>],
    ) {
        let here = &tree.nodes[node];
        let Some(primitive) = here.primitive else { return };
        let mut settle =
            |behaviours: &[usize], rating: Option<Rating>| behaviours.iter().for_each(|&b| ratings[b] = rating);
        let robot = self.motion.step(now.robot, primitive, f64::INFINITY, &mut rng);
        if !self.pitch().contains(robot.x_mm(), robot.y_mm()) {
            settle(&here.below, (depth > 0).then(|| self.rate_end(start, &now, depth)));
            return;
        }
        let ball = self.world.map_or((now.ball_x_mm, now.ball_y_mm), |w| w.ball_response.predict(&now, primitive));
        let next = TrackedFrame { robot, ball_x_mm: ball.0, ball_y_mm: ball.1 };
        if self.pitch().in_target_goal(ball.0, ball.1) || self.pitch().in_own_goal(ball.0, ball.1) {
            settle(&here.below, Some(self.rate_end(start, &next, depth + 1)));
            return;
        }
        if !here.ending.is_empty() {
            settle(&here.ending, Some(self.rate_end(start, &next, depth + 1)));
        }
        for &child in &here.children {
            self.walk(tree, child, start, next, depth + 1, rng.clone(), ratings);
        }
    }

    /// The rating of a chain of `primitives` from `start` that ended at `end`: a goal (the
    /// sooner the better, with `prefer_sooner_goals`), then a state the demonstrations do not
    /// tie to own goals, then millimetres the ball comes nearer the goal (beyond the dead band),
    /// then millimetres the robot comes nearer the ball.
    fn rate_end(&self, start: &TrackedFrame, end: &TrackedFrame, primitives: usize) -> Rating {
        let value = self.world.map_or(0.0, |w| w.state_value.estimate(end));
        Rating::of(start, end, value, primitives, &self.pitch(), self.config)
    }
}

/// The improved mode's rating of a predicted outcome, compared lexicographically.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Rating {
    /// +1 a goal, −1 an own goal, else 0.
    goal: f64,
    /// Primitives chained to the end: with `prefer_sooner_goals`, of two predicted goals the
    /// sooner wins, so the robot does not turn one way for a goal three pushes later, then back
    /// for another.
    primitives: usize,
    /// Whether the demonstrations that passed near the predicted state did not, on balance,
    /// end in own goals (its learned value is not negative).
    safe: bool,
    ball_nearer_goal_mm: f64,
    robot_nearer_ball_mm: f64,
}

impl Rating {
    fn of(
        before: &TrackedFrame,
        after: &TrackedFrame,
        value: f64,
        primitives: usize,
        pitch: &Pitch,
        config: &LearningConfig,
    ) -> Self {
        let goal = if pitch.in_target_goal(after.ball_x_mm, after.ball_y_mm) {
            1.0
        } else if pitch.in_own_goal(after.ball_x_mm, after.ball_y_mm) {
            -1.0
        } else {
            0.0
        };
        let ball = ball_to_goal_mm(before, pitch) - ball_to_goal_mm(after, pitch);
        Self {
            goal,
            primitives,
            safe: value >= 0.0,
            ball_nearer_goal_mm: if ball.abs() > config.ball_dead_band_mm { ball } else { 0.0 },
            robot_nearer_ball_mm: robot_to_ball_mm(before) - robot_to_ball_mm(after),
        }
    }

    fn total_cmp(&self, other: &Self, sooner_goals: bool) -> std::cmp::Ordering {
        let sooner = if sooner_goals && self.goal > 0.0 && other.goal > 0.0 {
            other.primitives.cmp(&self.primitives)
        } else {
            std::cmp::Ordering::Equal
        };
        self.goal
            .total_cmp(&other.goal)
            .then(sooner)
            .then(self.safe.cmp(&other.safe))
            .then(self.ball_nearer_goal_mm.total_cmp(&other.ball_nearer_goal_mm))
            .then(self.robot_nearer_ball_mm.total_cmp(&other.robot_nearer_ball_mm))
    }
}

impl ImitatorPolicy<'_> {
    /// One attempt from `configuration` with the imitator's body (a primitive runs as
    /// [`primitive_command`](polymimic_field::controller::primitive_command) has the body
    /// execute it).
    ///
    /// # Errors
    /// A field configuration that does not validate.
    pub fn attempt(&self, configuration: Configuration, field: &FieldConfig, seed: u64) -> Result<Attempt, FieldError> {
        let setup = EpisodeSetup::configuration(self.body, configuration, field);
        self.attempt_from(&setup, Some(configuration), field, seed)
    }

    /// One attempt from a chosen `start` (see [`Start::check`]).
    ///
    /// # Errors
    /// A start the body cannot play from, or a field configuration that does not validate.
    pub fn attempt_at(&self, start: Start, field: &FieldConfig, seed: u64) -> Result<Attempt, FieldError> {
        let setup = EpisodeSetup::starting(self.body, start, field)?;
        self.attempt_from(&setup, None, field, seed)
    }

    /// The player stepped through the field from `setup`, one tracker reading at a time.
    fn attempt_from(
        &self,
        setup: &EpisodeSetup,
        configuration: Option<Configuration>,
        field: &FieldConfig,
        seed: u64,
    ) -> Result<Attempt, FieldError> {
        let mut episode = Episode::new(setup, field, seed)?;
        let start = Start { robot: setup.robot, ball: setup.ball.unwrap_or(Point::new(0.0, 0.0)) };
        let mut stepping = self.start(&start, seed);
        while !episode.is_finished() {
            let command = self.act(&mut stepping, &episode.observation());
            episode.step(command)?;
        }
        let outcome = episode.outcome().unwrap_or(Outcome::TimeUp);
        Ok(Attempt {
            configuration,
            start,
            seed,
            outcome,
            frames: episode.into_frames(),
            behaviours: stepping.into_executed(),
        })
    }

    /// `attempts_per_configuration` attempts from each configuration, in parallel; attempt i
    /// of configuration c runs with a seed derived from (`seed`, c, i).
    ///
    /// # Errors
    /// A field configuration that does not validate.
    pub fn evaluate(
        &self,
        attempts_per_configuration: usize,
        field: &FieldConfig,
        seed: u64,
    ) -> Result<Vec<Attempt>, FieldError> {
        let named = [StartAt::Configuration(Configuration::One), StartAt::Configuration(Configuration::Two)];
        self.evaluate_from(&named, attempts_per_configuration, field, seed)
    }

    /// `attempts_per_start` attempts from each of `starts`, in parallel, in order; a named
    /// configuration's attempts run with the seeds [`Self::evaluate`] gives it, the k-th chosen
    /// start's with seeds of their own (see [`start_attempt_seeds`]).
    ///
    /// # Errors
    /// A chosen start the body cannot play from, or a field configuration that does not
    /// validate.
    pub fn evaluate_from(
        &self,
        starts: &[StartAt],
        attempts_per_start: usize,
        field: &FieldConfig,
        seed: u64,
    ) -> Result<Vec<Attempt>, FieldError> {
        for start in starts {
            if let StartAt::Chosen(start) = start {
                start.check(self.body)?;
            }
        }
        let jobs = start_attempt_seeds(starts, attempts_per_start, seed);
        jobs.par_iter()
            .map(|&(start, s)| match start {
                StartAt::Configuration(configuration) => self.attempt(configuration, field, s),
                StartAt::Chosen(start) => self.attempt_at(start, field, s),
            })
            .collect()
    }
}

/// Where an evaluated attempt starts: one of the thesis's two configurations, or a start of
/// one's own.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StartAt {
    /// Configuration 1 or 2 (Fig 4.4) on the body's field.
    Configuration(Configuration),
    /// A chosen robot pose and ball position.
    Chosen(Start),
}

/// The start and episode seed of every attempt an evaluation from `starts` under `seed` makes,
/// `attempts_per_start` from each in order: configuration c's attempt i with a seed derived
/// from (`seed`, 100 + c − 1, i), as [`attempt_seeds`] gives; the k-th chosen start's (counting
/// chosen starts only) from (`seed`, 1000 + k, i).
#[must_use]
pub fn start_attempt_seeds(starts: &[StartAt], attempts_per_start: usize, seed: u64) -> Vec<(StartAt, u64)> {
    let mut chosen = 0_u64;
    let mut jobs = Vec::with_capacity(starts.len() * attempts_per_start);
    for &start in starts {
        let stream = match start {
            StartAt::Configuration(c) => 99 + u64::from(c.number()),
            StartAt::Chosen(_) => {
                chosen += 1;
                999 + chosen
            }
        };
        jobs.extend((0..attempts_per_start as u64).map(|i| (start, derive_seed(seed, stream, i))));
    }
    jobs
}

/// The configuration and episode seed of every attempt an evaluation under `seed` makes:
/// `attempts_per_configuration` from configuration 1, then as many from configuration 2;
/// attempt i of configuration c runs with a seed derived from (`seed`, c, i). Any policy
/// evaluated on these meets the same starts and the same noise.
#[must_use]
pub fn attempt_seeds(attempts_per_configuration: usize, seed: u64) -> Vec<(Configuration, u64)> {
    Configuration::ALL
        .iter()
        .enumerate()
        .flat_map(|(c, &configuration)| {
            (0..attempts_per_configuration as u64).map(move |i| (configuration, derive_seed(seed, 100 + c as u64, i)))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use polymimic_field::Demonstrator;

    use super::*;
    use crate::{Laboratory, PhaseOne};

    impl ImitatorPolicy<'_> {
        /// Behaviour `index`'s rated outcome chained on its own, primitive by primitive: what
        /// [`Self::outcomes`] must give every behaviour, sharing beginnings or not.
        fn outcome_by_chaining(&self, index: usize, state: &TrackedFrame) -> Option<Rating> {
            let mut rng = ChaCha8Rng::seed_from_u64(0);
            let mut now = *state;
            let mut chained = 0;
            for (k, &primitive) in self.model.behaviours[index].primitives.iter().enumerate() {
                let robot = self.motion.step(now.robot, primitive, f64::INFINITY, &mut rng);
                if !self.pitch().contains(robot.x_mm(), robot.y_mm()) {
                    if k == 0 {
                        return None;
                    }
                    break;
                }
                let ball =
                    self.world.map_or((now.ball_x_mm, now.ball_y_mm), |w| w.ball_response.predict(&now, primitive));
                now = TrackedFrame { robot, ball_x_mm: ball.0, ball_y_mm: ball.1 };
                chained = k + 1;
                if self.pitch().in_target_goal(ball.0, ball.1) || self.pitch().in_own_goal(ball.0, ball.1) {
                    break;
                }
            }
            Some(self.rate_end(state, &now, chained))
        }
    }

    #[test]
    fn of_two_predicted_goals_the_sooner_rates_better_if_asked_and_otherwise_length_does_not_count() {
        use std::cmp::Ordering;
        let rating = |goal, primitives, ball_nearer_goal_mm| Rating {
            goal,
            primitives,
            safe: true,
            ball_nearer_goal_mm,
            robot_nearer_ball_mm: 0.0,
        };
        // A goal in one push beats a goal four primitives away that carries the ball further…
        assert_eq!(rating(1.0, 1, 100.0).total_cmp(&rating(1.0, 4, 300.0), true), Ordering::Greater);
        // …unless sooner goals are not preferred (the default): then the further wins.
        assert_eq!(rating(1.0, 1, 100.0).total_cmp(&rating(1.0, 4, 300.0), false), Ordering::Less);
        for sooner in [true, false] {
            // With no goal predicted, how far the ball comes decides, however long the chain.
            assert_eq!(rating(0.0, 1, 100.0).total_cmp(&rating(0.0, 4, 300.0), sooner), Ordering::Less);
            assert_eq!(rating(-1.0, 1, 0.0).total_cmp(&rating(-1.0, 4, 0.0), sooner), Ordering::Equal);
            // A goal however late beats none.
            assert_eq!(rating(1.0, 9, 0.0).total_cmp(&rating(0.0, 1, 500.0), sooner), Ordering::Greater);
        }
    }

    /// A trial's imitator (behaviours grown from each other, so sharing beginnings) rates every
    /// state the Expert passed through the same, bit for bit, by the tree as by chaining each
    /// behaviour alone.
    #[test]
    fn the_tree_of_shared_beginnings_rates_every_behaviour_as_chaining_it_alone_does() {
        let lab = Laboratory::new(200, 3, LearningConfig::default()).expect("the recogniser trains");
        let demos = lab.record(&[Demonstrator::Expert, Demonstrator::Poor], 4, 2).expect("demonstrations record");
        let trial = &lab.trials(&demos, &["expert", "poor"], PhaseOne::ByModel, 1).expect("a trial runs")[0];
        let world = WorldModel::learn(&demos, &Pitch::LARGE, &lab.motion, &lab.config);
        let policy = ImitatorPolicy {
            model: &trial.imitator,
            motion: &lab.motion,
            config: &lab.config,
            body: BodyKind::Lego,
            mode: ControlMode::Improved,
            world: Some(&world),
        };
        let behaviours = &trial.imitator.behaviours;
        let tree = PrefixTree::new(behaviours.iter().map(|b| b.primitives.as_slice()));
        let primitives: usize = behaviours.iter().map(|b| b.primitives.len()).sum();
        assert!(
            tree.nodes.len() - 1 < primitives,
            "no beginning shared: {} nodes, {primitives} primitives",
            tree.nodes.len()
        );
        let mut compared = 0;
        for segment in demos.iter().flat_map(|d| &d.segments) {
            let together = policy.outcomes(&tree, &segment.start);
            for (i, rating) in together.iter().enumerate() {
                assert_eq!(format!("{rating:?}"), format!("{:?}", policy.outcome_by_chaining(i, &segment.start)));
                compared += 1;
            }
        }
        assert!(compared > 1000, "{compared} ratings compared");
    }
}
