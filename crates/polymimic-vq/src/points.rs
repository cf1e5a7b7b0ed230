//! A checked view of `n` points of dimension `d`, stored row-major.

use crate::error::VqParamsError;

/// Row-major points, all finite.
#[derive(Debug, Clone, Copy)]
pub struct Points<'a> {
    data: &'a [f64],
    dim: usize,
}

impl<'a> Points<'a> {
    /// # Errors
    /// No points, zero dimensions, a ragged buffer, or a NaN or infinite coordinate.
    pub fn new(data: &'a [f64], dim: usize) -> Result<Self, VqParamsError> {
        if dim == 0 {
            return Err(VqParamsError::NoDimensions);
        }
        if data.is_empty() {
            return Err(VqParamsError::NoPoints);
        }
        if !data.len().is_multiple_of(dim) {
            return Err(VqParamsError::RaggedPoints { len: data.len(), dim });
        }
        if let Some(flat) = data.iter().position(|x| !x.is_finite()) {
            return Err(VqParamsError::NotFinite { index: flat / dim, dimension: flat % dim, value: data[flat] });
        }
        Ok(Self { data, dim })
    }

    #[must_use]
    pub fn len(&self) -> usize {
        self.data.len() / self.dim
    }

    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.data.is_empty()
    }

    #[must_use]
    pub fn dim(&self) -> usize {
        self.dim
    }

    #[must_use]
    pub fn raw(&self) -> &'a [f64] {
        self.data
    }

    #[must_use]
    pub fn get(&self, index: usize) -> &'a [f64] {
        &self.data[index * self.dim..(index + 1) * self.dim]
    }
}

/// Squared Euclidean distance.
#[inline]
#[must_use]
pub fn distance2(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y) * (x - y)).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_the_point_and_dimension_of_a_nan() {
        let data = [0.0, 1.0, 2.0, f64::NAN];
        assert_eq!(
            Points::new(&data, 2).unwrap_err().to_string(),
            "point 1 has a non-finite coordinate (NaN) in dimension 1"
        );
    }

    #[test]
    fn rejects_ragged_and_empty_data() {
        assert_eq!(Points::new(&[1.0, 2.0, 3.0], 2).unwrap_err(), VqParamsError::RaggedPoints { len: 3, dim: 2 });
        assert_eq!(Points::new(&[], 2).unwrap_err(), VqParamsError::NoPoints);
    }
}
