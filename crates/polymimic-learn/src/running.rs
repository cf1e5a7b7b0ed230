//! Running mean and standard deviation (Welford), for statistics gathered one sample at a time.

use serde::{Deserialize, Serialize};

#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Running {
    pub count: usize,
    pub mean: f64,
    m2: f64,
}

impl Running {
    pub fn push(&mut self, value: f64) {
        self.count += 1;
        let delta = value - self.mean;
        self.mean += delta / self.count as f64;
        self.m2 += delta * (value - self.mean);
    }

    /// Sample standard deviation (0 with fewer than two samples).
    #[must_use]
    pub fn sd(&self) -> f64 {
        if self.count < 2 { 0.0 } else { (self.m2 / (self.count - 1) as f64).sqrt() }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matches_the_two_pass_formula() {
        let values = [2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0];
        let mut r = Running::default();
        for &v in &values {
            r.push(v);
        }
        assert!((r.mean - 5.0).abs() < 1e-12);
        assert!((r.sd() - (32.0_f64 / 7.0).sqrt()).abs() < 1e-12);
    }
}
