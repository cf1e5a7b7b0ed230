//! The improved control (see [`ControlMode::Improved`](crate::ControlMode::Improved)): every
//! behaviour's outcome predicted along the tree of their shared beginnings, rated, and the first
//! primitive of the best run, or the next primitive of the route to where the demonstrators pushed.

use polymimic_types::{Primitive, TrackedFrame};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

use super::policy::ImitatorPolicy;
use crate::config::LearningConfig;
use crate::prefix_tree::PrefixTree;
use crate::state::{Pitch, ball_to_goal_mm, robot_to_ball_mm};

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

#[cfg(test)]
mod tests {
    use polymimic_field::{BodyKind, Demonstrator};

    use super::*;
    use crate::{ControlMode, Laboratory, PhaseOne, WorldModel};

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
