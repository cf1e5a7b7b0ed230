//! The primitive recogniser: one codebook per representation, one HMM per moving primitive of
//! the imitator's own set, each HMM reading frames through its own representation and codebook
//! (thesis §3.1.4).

use std::collections::BTreeMap;

use polymimic_hmm::{DiscreteHmm, GaussianHmm, GaussianHmmParams, HmmParams, Init, Topology};
use polymimic_types::{MotionStats, Pose, Primitive, PrimitiveSet};
use polymimic_vq::{Codebook, LbgParams};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::error::PerceiveError;
use crate::motion::{motion_stats, motion_stats_with_sideways};
use crate::representation::Representation;

const FORMAT: &str = "polymimic.PrimitiveRecognizer";
const VERSION: u32 = 1;

/// log-likelihoods of a sequence under every moving primitive's model, one slot per primitive
/// of [`Primitive::ALL_MOVING`] (F B L R A D K); −inf where the recogniser has no model (the
/// wheeled set's are the first four).
pub type Scores = [f64; Primitive::ALL_MOVING.len()];

/// Scores of no model at all.
pub const NO_SCORES: Scores = [f64::NEG_INFINITY; Primitive::ALL_MOVING.len()];

/// One self-observed primitive: the poses the tracker saw while it ran.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LabelledSequence {
    pub primitive: Primitive,
    pub poses: Vec<Pose>,
}

/// What the HMMs emit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Emissions {
    /// Codebook symbols (the thesis's way).
    #[default]
    Discrete,
    /// The 3-D points themselves, through diagonal Gaussians: no codebook (beyond the thesis).
    Gaussian,
}

/// How the recogniser is trained. Defaults are the thesis's.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RecognizerConfig {
    /// States of every HMM. The thesis found one state as accurate as 5 to 20 and settled on
    /// it; here too one state is the most accurate on the simulated field.
    pub n_states: usize,
    /// Forward links of the left-right topology.
    pub links: usize,
    /// Codewords per representation.
    pub codebook_size: usize,
    pub max_iter: usize,
    pub tol: f64,
    /// Relative distortion drop at which LBG's k-means stops at each size.
    pub codebook_tol: f64,
    /// Probability given to a symbol a model never saw in training, so that one unfamiliar
    /// frame lowers a score instead of ruling the model out.
    pub emission_floor: f64,
    /// The representation of the forward and backward models.
    pub forward_backward_representation: Representation,
    /// The representation of the left and right models.
    pub left_right_representation: Representation,
    #[serde(default)]
    pub emissions: Emissions,
    /// Lower bound on a Gaussian model's variances (in squared representation units).
    #[serde(default = "default_min_variance")]
    pub min_variance: f64,
    pub seed: u64,
    /// The imitator's own primitives: one HMM per moving one. Left out of saved files when
    /// wheeled, so that those read and write as they always have.
    #[serde(default, skip_serializing_if = "PrimitiveSet::is_wheeled")]
    pub primitives: PrimitiveSet,
}

fn default_min_variance() -> f64 {
    0.01
}

impl Default for RecognizerConfig {
    fn default() -> Self {
        Self {
            n_states: 1,
            links: 2,
            codebook_size: 512,
            max_iter: 100,
            tol: 1e-4,
            codebook_tol: 1e-4,
            emission_floor: 1e-8,
            forward_backward_representation: Representation::Positional,
            left_right_representation: Representation::Rotational,
            emissions: Emissions::Discrete,
            min_variance: default_min_variance(),
            seed: 0,
            primitives: PrimitiveSet::Wheeled,
        }
    }
}

impl RecognizerConfig {
    /// The representation a primitive's model reads: turns read the left-right one, every
    /// other motion (walking, side-stepping, kicking) the forward-backward one, whose absolute
    /// heading tells a step along it from a step across it.
    #[must_use]
    pub fn representation_of(&self, primitive: Primitive) -> Representation {
        match primitive {
            Primitive::Left | Primitive::Right => self.left_right_representation,
            Primitive::Forward
            | Primitive::Backward
            | Primitive::Stop
            | Primitive::SidestepLeft
            | Primitive::SidestepRight
            | Primitive::Kick => self.forward_backward_representation,
        }
    }

    fn check(&self) -> Result<(), PerceiveError> {
        if self.n_states == 0 {
            return Err(PerceiveError::Parameter { name: "n_states", value: 0.0, why: "at least 1" });
        }
        if self.codebook_size == 0 {
            return Err(PerceiveError::Parameter { name: "codebook_size", value: 0.0, why: "at least 1" });
        }
        if !(0.0..1.0).contains(&self.emission_floor) {
            return Err(PerceiveError::Parameter {
                name: "emission_floor",
                value: self.emission_floor,
                why: "in [0, 1)",
            });
        }
        Ok(())
    }
}

/// The HMM behind one primitive.
#[derive(Debug, Clone, PartialEq)]
pub enum PrimitiveHmm {
    Discrete(DiscreteHmm),
    Gaussian(GaussianHmm),
}

/// An HMM for one primitive, with the representation it reads.
#[derive(Debug, Clone, PartialEq)]
pub struct PrimitiveModel {
    pub primitive: Primitive,
    pub representation: Representation,
    pub hmm: PrimitiveHmm,
}

/// An HMM per moving primitive of its set (forward, backward, left, right for a wheeled body;
/// side-steps and the kick too for the humanoid) and the codebooks they read through.
#[derive(Debug, Clone, PartialEq)]
pub struct Recognizer {
    config: RecognizerConfig,
    codebooks: BTreeMap<Representation, Codebook>,
    models: Vec<PrimitiveModel>,
    motion: Vec<MotionStats>,
}

impl Recognizer {
    /// Trains the codebooks on every frame of every sequence and each primitive's HMM on its
    /// own sequences; also measures Table 3.1.
    ///
    /// # Errors
    /// A moving primitive of the set without sequences, a sequence of a primitive outside the
    /// set, a sequence with a non-finite or missing frame, or a parameter out of range.
    pub fn train(sequences: &[LabelledSequence], config: RecognizerConfig) -> Result<Self, PerceiveError> {
        config.check()?;
        let set = config.primitives;
        for (index, seq) in sequences.iter().enumerate() {
            check_poses(&seq.poses, &format!("training sequence {index}"), 1)?;
            if !set.contains(seq.primitive) {
                return Err(PerceiveError::NotInSet { index, primitive: seq.primitive.name(), set: set.name() });
            }
        }
        for &primitive in set.moving() {
            if !sequences.iter().any(|s| s.primitive == primitive) {
                return Err(PerceiveError::MissingPrimitive(primitive.name()));
            }
        }
        let representations: Vec<Representation> =
            [config.forward_backward_representation, config.left_right_representation]
                .into_iter()
                .collect::<std::collections::BTreeSet<_>>()
                .into_iter()
                .collect();
        let quantised = if config.emissions == Emissions::Discrete { representations.as_slice() } else { &[] };
        let codebooks: BTreeMap<Representation, Codebook> = quantised
            .par_iter()
            .map(|&representation| {
                let points: Vec<f64> = sequences.iter().flat_map(|s| representation.points(&s.poses)).collect();
                let mut lbg = LbgParams::new(config.codebook_size);
                lbg.tol = config.codebook_tol;
                lbg.seed = config.seed;
                Codebook::fit(&points, 3, lbg).map(|codebook| (representation, codebook))
            })
            .collect::<Result<_, _>>()?;
        let models = set
            .moving()
            .par_iter()
            .map(|&primitive| train_model(primitive, sequences, &codebooks, &config))
            .collect::<Result<Vec<_>, _>>()?;
        // A body that side-steps has its steps across its heading measured too.
        let sideways = set != PrimitiveSet::Wheeled;
        let motion = set
            .primitives()
            .iter()
            .map(|&p| {
                let own = sequences.iter().filter(|s| s.primitive == p).map(|s| s.poses.as_slice());
                if sideways { motion_stats_with_sideways(p, own) } else { motion_stats(p, own) }
            })
            .collect();
        Ok(Self { config, codebooks, models, motion })
    }

    #[must_use]
    pub fn config(&self) -> &RecognizerConfig {
        &self.config
    }

    /// The imitator's own primitives it recognises.
    #[must_use]
    pub fn primitive_set(&self) -> PrimitiveSet {
        self.config.primitives
    }

    #[must_use]
    pub fn models(&self) -> &[PrimitiveModel] {
        &self.models
    }

    #[must_use]
    pub fn codebook(&self, representation: Representation) -> Option<&Codebook> {
        self.codebooks.get(&representation)
    }

    /// Table 3.1 of the training set, for every primitive of its set.
    #[must_use]
    pub fn motion_stats(&self) -> &[MotionStats] {
        &self.motion
    }

    /// log P(poses | model) for every moving primitive, in [`Scores`]' slots (forward,
    /// backward, left, right, then the humanoid's); −inf where a model cannot have produced
    /// the poses and in the slots of primitives outside its set.
    ///
    /// # Errors
    /// No poses, or a non-finite one.
    pub fn log_likelihoods(&self, poses: &[Pose]) -> Result<Scores, PerceiveError> {
        check_poses(poses, "sequence", 1)?;
        Ok(self.scores_unchecked(poses))
    }

    pub(crate) fn scores_unchecked(&self, poses: &[Pose]) -> Scores {
        let mut scores = NO_SCORES;
        // Moving sets are prefixes of the slots, so the models fill the first ones in order.
        for (score, model) in scores.iter_mut().zip(&self.models) {
            let points = model.representation.points(poses);
            let log_p = match &model.hmm {
                PrimitiveHmm::Discrete(hmm) => self.codebooks[&model.representation]
                    .encode(&points, 3)
                    .map_err(|e| e.to_string())
                    .and_then(|symbols| hmm.score(&symbols).map_err(|e| e.to_string())),
                PrimitiveHmm::Gaussian(hmm) => hmm.score(&points).map_err(|e| e.to_string()),
            };
            *score = log_p.unwrap_or(f64::NEG_INFINITY);
        }
        scores
    }

    /// The moving primitive whose model scores `poses` highest.
    ///
    /// # Errors
    /// As [`Self::log_likelihoods`].
    pub fn classify(&self, poses: &[Pose]) -> Result<Primitive, PerceiveError> {
        Ok(best_two(&self.log_likelihoods(poses)?).0)
    }

    /// [`Self::log_likelihoods`] of many sequences, in parallel.
    ///
    /// # Errors
    /// As [`Self::log_likelihoods`], naming the sequence.
    pub fn log_likelihoods_many(&self, sequences: &[&[Pose]]) -> Result<Vec<Scores>, PerceiveError> {
        for (index, poses) in sequences.iter().enumerate() {
            check_poses(poses, &format!("sequence {index}"), 1)?;
        }
        Ok(sequences.par_iter().map(|poses| self.scores_unchecked(poses)).collect())
    }

    /// The recogniser as versioned JSON.
    ///
    /// # Errors
    /// Never in practice.
    pub fn to_json(&self) -> Result<String, PerceiveError> {
        let saved = Saved {
            config: self.config.clone(),
            codebooks: self.codebooks.iter().map(|(r, c)| (*r, c.to_json().unwrap_or_default())).collect(),
            models: self
                .models
                .iter()
                .map(|m| SavedModel {
                    primitive: m.primitive,
                    representation: m.representation,
                    hmm: match &m.hmm {
                        PrimitiveHmm::Discrete(hmm) => hmm.to_json(),
                        PrimitiveHmm::Gaussian(hmm) => hmm.to_json(),
                    }
                    .unwrap_or_default(),
                })
                .collect(),
            motion: self.motion.clone(),
        };
        polymimic_persist::to_envelope(FORMAT, VERSION, &saved).map_err(PerceiveError::Corrupt)
    }

    /// A recogniser from [`Self::to_json`] text.
    ///
    /// # Errors
    /// Another format or version, or parts that do not validate.
    pub fn from_json(text: &str) -> Result<Self, PerceiveError> {
        let saved: Saved = polymimic_persist::from_envelope(text, FORMAT, VERSION).map_err(PerceiveError::Corrupt)?;
        let corrupt = |e: &dyn std::fmt::Display| PerceiveError::Corrupt(e.to_string());
        let codebooks = saved
            .codebooks
            .iter()
            .map(|(r, text)| Codebook::from_json(text).map(|c| (*r, c)).map_err(|e| corrupt(&e)))
            .collect::<Result<BTreeMap<_, _>, _>>()?;
        let models = saved
            .models
            .iter()
            .map(|m| {
                let hmm = match saved.config.emissions {
                    Emissions::Discrete => {
                        let hmm = DiscreteHmm::from_json(&m.hmm).map_err(|e| corrupt(&e))?;
                        let codebook = codebooks
                            .get(&m.representation)
                            .ok_or_else(|| corrupt(&"a model's codebook is missing"))?;
                        if hmm.params().n_symbols != codebook.len() {
                            return Err(corrupt(&"a model's symbols do not match its codebook"));
                        }
                        PrimitiveHmm::Discrete(hmm)
                    }
                    Emissions::Gaussian => {
                        PrimitiveHmm::Gaussian(GaussianHmm::from_json(&m.hmm).map_err(|e| corrupt(&e))?)
                    }
                };
                Ok(PrimitiveModel { primitive: m.primitive, representation: m.representation, hmm })
            })
            .collect::<Result<Vec<_>, _>>()?;
        let set = saved.config.primitives;
        if models.iter().map(|m| m.primitive).ne(set.moving().iter().copied()) {
            return Err(corrupt(&format!(
                "expected a model for each moving primitive of the {} set, in order",
                set.name()
            )));
        }
        // Table 3.1 of its own training set bounds every segment: a file without it is damaged.
        if saved.motion.iter().map(|m| m.primitive).ne(set.primitives().iter().copied()) {
            return Err(corrupt(&format!(
                "expected the motion statistics of every primitive of the {} set, in order",
                set.name()
            )));
        }
        if saved.motion.iter().any(|m| {
            let sideways = m.sideways.map_or([0.0; 2], |s| [s.mean_mm, s.sd_mm]);
            ![m.distance_mean_mm, m.distance_sd_mm, m.rotation_mean_deg, m.rotation_sd_deg, sideways[0], sideways[1]]
                .iter()
                .all(|v| v.is_finite())
                || m.distance_sd_mm < 0.0
                || m.rotation_sd_deg < 0.0
                || sideways[1] < 0.0
        }) {
            return Err(corrupt(&"motion statistics must be finite numbers with sds ≥ 0"));
        }
        Ok(Self { config: saved.config, codebooks, models, motion: saved.motion })
    }
}

#[derive(Serialize, Deserialize)]
struct Saved {
    config: RecognizerConfig,
    codebooks: Vec<(Representation, String)>,
    models: Vec<SavedModel>,
    motion: Vec<MotionStats>,
}

#[derive(Serialize, Deserialize)]
struct SavedModel {
    primitive: Primitive,
    representation: Representation,
    hmm: String,
}

fn train_model(
    primitive: Primitive,
    sequences: &[LabelledSequence],
    codebooks: &BTreeMap<Representation, Codebook>,
    config: &RecognizerConfig,
) -> Result<PrimitiveModel, PerceiveError> {
    let representation = config.representation_of(primitive);
    let own: Vec<&LabelledSequence> = sequences.iter().filter(|s| s.primitive == primitive).collect();
    if config.emissions == Emissions::Gaussian {
        let points: Vec<Vec<f64>> = own.iter().map(|s| representation.points(&s.poses)).collect();
        let refs: Vec<&[f64]> = points.iter().map(Vec::as_slice).collect();
        let mut params = GaussianHmmParams::new(config.n_states, 3);
        params.topology = Topology::LeftRight { links: config.links };
        params.max_iter = config.max_iter;
        params.tol = config.tol;
        params.min_variance = config.min_variance;
        params.seed = config.seed;
        let mut hmm = GaussianHmm::new(params).map_err(polymimic_hmm::HmmError::from)?;
        hmm.fit(&refs)?;
        return Ok(PrimitiveModel { primitive, representation, hmm: PrimitiveHmm::Gaussian(hmm) });
    }
    let codebook = &codebooks[&representation];
    let symbols: Vec<Vec<u32>> =
        own.iter().map(|s| codebook.encode(&representation.points(&s.poses), 3)).collect::<Result<_, _>>()?;
    let refs: Vec<&[u32]> = symbols.iter().map(Vec::as_slice).collect();
    let mut params = HmmParams::new(config.n_states, codebook.len());
    params.topology = Topology::LeftRight { links: config.links };
    params.max_iter = config.max_iter;
    params.tol = config.tol;
    params.emission_floor = config.emission_floor.min(1.0 / codebook.len() as f64);
    params.seed = config.seed;
    let mut hmm = DiscreteHmm::new(params.check().map_err(polymimic_hmm::HmmError::from)?);
    hmm.fit(&refs, Init::Segments)?;
    let hmm = hmm.with_emission_floor(config.emission_floor)?;
    Ok(PrimitiveModel { primitive, representation, hmm: PrimitiveHmm::Discrete(hmm) })
}

/// The best and second-best primitives by score, with their scores (ties go to the earlier
/// slot).
#[must_use]
pub fn best_two(scores: &Scores) -> (Primitive, f64, f64) {
    let mut order: [usize; Primitive::ALL_MOVING.len()] = std::array::from_fn(|slot| slot);
    order.sort_by(|&a, &b| scores[b].total_cmp(&scores[a]).then(a.cmp(&b)));
    (Primitive::ALL_MOVING[order[0]], scores[order[0]], scores[order[1]])
}

/// Poses must be at least `needed` and all finite.
pub(crate) fn check_poses(poses: &[Pose], what: &str, needed: usize) -> Result<(), PerceiveError> {
    if poses.len() < needed {
        return Err(PerceiveError::TooFewFrames { what: what.to_owned(), frames: poses.len(), needed });
    }
    if let Some(frame) = poses.iter().position(|p| !p.is_finite()) {
        return Err(PerceiveError::NotFinite { what: what.to_owned(), frame });
    }
    Ok(())
}
