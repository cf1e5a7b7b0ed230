//! A codebook: codewords, encoding by nearest codeword, and saved files.

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::error::{VqError, VqParamsError};
use crate::kdtree::KdTree;
use crate::lbg::{grow, LbgParams, LbgReport};
use crate::lloyd::{refine, Refinement, Stopping};
use crate::points::Points;

const FORMAT: &str = "polymimic.Codebook";
const VERSION: u32 = 1;
const POINTS_PER_TASK: usize = 4096;

/// Codewords of one dimension, stored row-major.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Codebook {
    dim: usize,
    codewords: Vec<f64>,
    report: LbgReport,
}

impl Codebook {
    /// Grows a codebook on row-major `data` of dimension `dim` by LBG.
    ///
    /// # Errors
    /// Bad data (empty, ragged, not finite) or parameters, or fewer points than codewords.
    pub fn fit(data: &[f64], dim: usize, params: LbgParams) -> Result<Self, VqParamsError> {
        let points = Points::new(data, dim)?;
        let (codewords, report) = grow(points, params)?;
        Ok(Self { dim, codewords, report })
    }

    /// A codebook with the given row-major codewords.
    ///
    /// # Errors
    /// As for points: empty, ragged, or not finite.
    pub fn from_codewords(codewords: Vec<f64>, dim: usize) -> Result<Self, VqParamsError> {
        Points::new(&codewords, dim)?;
        Ok(Self { dim, codewords, report: LbgReport::default() })
    }

    /// Lloyd iterations from the current codewords (the refinement stage of LBG on its own).
    ///
    /// # Errors
    /// Bad data or a dimension other than the codebook's.
    pub fn refine(&mut self, data: &[f64], tol: f64, max_iter: usize) -> Result<Refinement, VqParamsError> {
        let points = self.points(data)?;
        if !(tol.is_finite() && tol >= 0.0) {
            return Err(VqParamsError::BadTolerance(tol));
        }
        let mut labels = vec![0; points.len()];
        let refinement = refine(points, &mut self.codewords, &mut labels, Stopping { tol, max_iter });
        self.report = LbgReport {
            distortion: refinement.distortion,
            lloyd_iterations: refinement.iterations,
            reseeded_cells: refinement.reseeded,
        };
        Ok(refinement)
    }

    fn points<'a>(&self, data: &'a [f64]) -> Result<Points<'a>, VqParamsError> {
        let points = Points::new(data, self.dim)?;
        Ok(points)
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

    /// The index of the nearest codeword of every point.
    ///
    /// # Errors
    /// Bad data or a dimension other than the codebook's.
    pub fn encode(&self, data: &[f64]) -> Result<Vec<u32>, VqParamsError> {
        Ok(self.nearest(data)?.into_iter().map(|(c, _)| c as u32).collect())
    }

    /// Mean squared distance of the points to their nearest codewords.
    ///
    /// # Errors
    /// Bad data or a dimension other than the codebook's.
    pub fn distortion(&self, data: &[f64]) -> Result<f64, VqParamsError> {
        let nearest = self.nearest(data)?;
        Ok(nearest.iter().map(|(_, d2)| d2).sum::<f64>() / nearest.len() as f64)
    }

    fn nearest(&self, data: &[f64]) -> Result<Vec<(usize, f64)>, VqParamsError> {
        if data.len() % self.dim != 0 {
            return Err(VqParamsError::DimensionMismatch { actual: data.len(), expected: self.dim });
        }
        let points = self.points(data)?;
        let tree = &KdTree::new(&self.codewords, self.dim);
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
        let value = serde_json::json!({ "format": FORMAT, "version": VERSION, "codebook": self });
        serde_json::to_string(&value).map_err(|e| VqError::Corrupt(e.to_string()))
    }

    /// A codebook from [`Self::to_json`] text, re-validated.
    ///
    /// # Errors
    /// Text that is not JSON, another format or version, or codewords that do not validate.
    pub fn from_json(text: &str) -> Result<Self, VqError> {
        let value: serde_json::Value =
            serde_json::from_str(text).map_err(|e| VqError::Corrupt(format!("not a saved codebook ({e})")))?;
        let format = value.get("format").and_then(serde_json::Value::as_str);
        if format != Some(FORMAT) {
            return Err(VqError::Corrupt(format!("expected format {FORMAT:?}, found {format:?}")));
        }
        let version = value.get("version").and_then(serde_json::Value::as_u64);
        if version != Some(u64::from(VERSION)) {
            return Err(VqError::Corrupt(format!(
                "format version {version:?} is not supported by this polymimic (it reads version {VERSION})"
            )));
        }
        let codebook: Self = value
            .get("codebook")
            .cloned()
            .ok_or_else(|| VqError::Corrupt("no codebook in the file".to_owned()))
            .and_then(|c| serde_json::from_value(c).map_err(|e| VqError::Corrupt(e.to_string())))?;
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
        assert_eq!(codebook.encode(&[1.0, 1.0, 9.0, 2.0, 2.0, 8.0]).unwrap(), vec![0, 1, 2]);
        assert!((codebook.distortion(&[1.0, 1.0]).unwrap() - 2.0).abs() < 1e-15);
    }

    #[test]
    fn refuses_points_of_another_dimension() {
        let codebook = Codebook::from_codewords(vec![0.0, 0.0], 2).unwrap();
        assert!(codebook.encode(&[1.0, 2.0, 3.0]).is_err());
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
