//! A codebook: codewords, encoding by nearest codeword, and saved files.

use std::sync::OnceLock;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::error::{VqError, VqParamsError};
use crate::kdtree::KdTree;
use crate::lbg::{LbgParams, LbgReport, grow};
use crate::lloyd::{Refinement, Stopping, refine};
use crate::points::Points;

const FORMAT: &str = "polymimic.Codebook";
const VERSION: u32 = 1;
const POINTS_PER_TASK: usize = 4096;

/// Codewords of one dimension, stored row-major.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Codebook {
    dim: usize,
    codewords: Vec<f64>,
    report: LbgReport,
    /// The search tree, built on first use and kept: encoding short sequences one at a time
    /// (as the segmenter does) must not rebuild it every call.
    #[serde(skip)]
    tree: OnceLock<KdTree>,
}

impl PartialEq for Codebook {
    fn eq(&self, other: &Self) -> bool {
        self.dim == other.dim && self.codewords == other.codewords && self.report == other.report
    }
}

impl Codebook {
    /// Grows a codebook on row-major `data` of dimension `dim` by LBG.
    ///
    /// # Errors
    /// Bad data (empty, ragged, not finite) or parameters, or fewer points than codewords.
    pub fn fit(data: &[f64], dim: usize, params: LbgParams) -> Result<Self, VqParamsError> {
        let points = Points::new(data, dim)?;
        let (codewords, report) = grow(points, params)?;
        Ok(Self { dim, codewords, report, tree: OnceLock::new() })
    }

    /// A codebook with the given row-major codewords.
    ///
    /// # Errors
    /// As for points: empty, ragged, or not finite.
    pub fn from_codewords(codewords: Vec<f64>, dim: usize) -> Result<Self, VqParamsError> {
        Points::new(&codewords, dim)?;
        Ok(Self { dim, codewords, report: LbgReport::default(), tree: OnceLock::new() })
    }

    /// Lloyd iterations from the current codewords (the refinement stage of LBG on its own).
    ///
    /// # Errors
    /// Bad data or a dimension other than the codebook's.
    pub fn refine(&mut self, data: &[f64], dim: usize, tol: f64, max_iter: usize) -> Result<Refinement, VqParamsError> {
        let points = self.points(data, dim)?;
        if !(tol.is_finite() && tol >= 0.0) {
            return Err(VqParamsError::BadTolerance(tol));
        }
        let mut labels = vec![0; points.len()];
        let refinement = refine(points, &mut self.codewords, &mut labels, Stopping { tol, max_iter });
        self.tree = OnceLock::new();
        self.report = LbgReport {
            distortion: refinement.distortion,
            lloyd_iterations: refinement.iterations,
            reseeded_cells: refinement.reseeded,
        };
        Ok(refinement)
    }

    fn points<'a>(&self, data: &'a [f64], dim: usize) -> Result<Points<'a>, VqParamsError> {
        if dim != self.dim {
            return Err(VqParamsError::DimensionMismatch { actual: dim, expected: self.dim });
        }
        Points::new(data, dim)
    }

    #[must_use]
    pub fn dim(&self) -> usize {
        self.dim
    }

    #[must_use]
    pub fn len(&self) -> usize {
        self.codewords.len() / self.dim
    }

    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.codewords.is_empty()
    }

    /// Row-major codewords.
    #[must_use]
    pub fn codewords(&self) -> &[f64] {
        &self.codewords
    }

    /// What the last fit or refinement did.
    #[must_use]
    pub fn report(&self) -> LbgReport {
        self.report
    }

    /// The index of the nearest codeword of every point (row-major `data` of dimension `dim`).
    ///
    /// # Errors
    /// Bad data or a dimension other than the codebook's.
    pub fn encode(&self, data: &[f64], dim: usize) -> Result<Vec<u32>, VqParamsError> {
        Ok(self.nearest(data, dim)?.into_iter().map(|(c, _)| c as u32).collect())
    }

    /// Mean squared distance of the points to their nearest codewords.
    ///
    /// # Errors
    /// Bad data or a dimension other than the codebook's.
    pub fn distortion(&self, data: &[f64], dim: usize) -> Result<f64, VqParamsError> {
        let nearest = self.nearest(data, dim)?;
        Ok(nearest.iter().map(|(_, d2)| d2).sum::<f64>() / nearest.len() as f64)
    }

    fn nearest(&self, data: &[f64], dim: usize) -> Result<Vec<(usize, f64)>, VqParamsError> {
        let points = self.points(data, dim)?;
        let tree = self.tree.get_or_init(|| KdTree::new(&self.codewords, self.dim));
        Ok(points
            .raw()
            .par_chunks(POINTS_PER_TASK * self.dim)
            .flat_map_iter(|chunk| {
                let mut hint = 0;
                chunk.chunks_exact(self.dim).map(move |point| {
                    let found = tree.nearest(point, hint);
                    hint = found.0;
                    found
                })
            })
            .collect())
    }

    /// The codebook as JSON text (floats round-trip exactly).
    ///
    /// # Errors
    /// Never in practice.
    pub fn to_json(&self) -> Result<String, VqError> {
        polymimic_persist::to_envelope(FORMAT, VERSION, self).map_err(VqError::Corrupt)
    }

    /// A codebook from [`Self::to_json`] text, re-validated.
    ///
    /// # Errors
    /// Text that is not JSON, another format or version, or codewords that do not validate.
    pub fn from_json(text: &str) -> Result<Self, VqError> {
        let codebook: Self = polymimic_persist::from_envelope(text, FORMAT, VERSION).map_err(VqError::Corrupt)?;
        Points::new(&codebook.codewords, codebook.dim).map_err(|e| VqError::Corrupt(e.to_string()))?;
        Ok(codebook)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn encodes_to_the_nearest_codeword() {
        let codebook = Codebook::from_codewords(vec![0.0, 0.0, 10.0, 0.0, 0.0, 10.0], 2).unwrap();
        assert_eq!(codebook.encode(&[1.0, 1.0, 9.0, 2.0, 2.0, 8.0], 2).unwrap(), vec![0, 1, 2]);
        assert!((codebook.distortion(&[1.0, 1.0], 2).unwrap() - 2.0).abs() < 1e-15);
    }

    #[test]
    fn refuses_points_of_another_dimension() {
        let codebook = Codebook::from_codewords(vec![0.0, 0.0], 2).unwrap();
        assert_eq!(
            codebook.encode(&[1.0, 2.0, 3.0], 3).unwrap_err(),
            VqParamsError::DimensionMismatch { actual: 3, expected: 2 }
        );
    }

    #[test]
    fn round_trips_through_json_and_refuses_foreign_files() {
        let data: Vec<f64> = (0..300).map(|i| f64::from(i).sin() * 7.3).collect();
        let codebook = Codebook::fit(&data, 3, LbgParams::new(8)).unwrap();
        let text = codebook.to_json().unwrap();
        assert_eq!(Codebook::from_json(&text).unwrap(), codebook);
        assert!(Codebook::from_json("[]").is_err());
        assert!(Codebook::from_json(&text.replace("\"version\":1", "\"version\":2")).is_err());
    }
}
