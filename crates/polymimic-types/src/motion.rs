//! Table 3.1: how far a primitive moves and turns in one second, mean and spread.

use serde::{Deserialize, Serialize};

use crate::primitive::Primitive;

/// Mean and sample standard deviation of one primitive's signed displacement along its
/// starting heading and its heading change over its sequences (Table 3.1). Rotations are in
/// degrees, as the thesis and the saved recognisers give them. A body that side-steps also
/// has its displacement across the starting heading measured ([`Sideways`]): the thesis's
/// two columns would read a side-step as standing still.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MotionStats {
    /// The primitive measured.
    pub primitive: Primitive,
    /// Sequences measured.
    pub count: usize,
    /// Mean signed distance along the starting heading, mm.
    pub distance_mean_mm: f64,
    /// Sample sd of the distance, mm.
    pub distance_sd_mm: f64,
    /// Mean heading change, deg.
    pub rotation_mean_deg: f64,
    /// Sample sd of the heading change, deg.
    pub rotation_sd_deg: f64,
    /// Displacement to the left of the starting heading, for bodies that side-step; absent
    /// (and left out of files) for the wheeled bodies, which move only along their heading.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sideways: Option<Sideways>,
}

/// Mean and sample sd of a primitive's signed displacement to the left of its starting
/// heading, mm.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Sideways {
    pub mean_mm: f64,
    pub sd_mm: f64,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn serialises_with_units_in_the_field_names() {
        let s = MotionStats {
            primitive: Primitive::Left,
            count: 3,
            distance_mean_mm: 4.0,
            distance_sd_mm: 5.0,
            rotation_mean_deg: 30.0,
            rotation_sd_deg: 18.0,
            sideways: None,
        };
        let text = serde_json::to_string(&s).expect("numbers");
        assert_eq!(
            text,
            r#"{"primitive":"left","count":3,"distance_mean_mm":4.0,"distance_sd_mm":5.0,"rotation_mean_deg":30.0,"rotation_sd_deg":18.0}"#
        );
        assert_eq!(serde_json::from_str::<MotionStats>(&text).expect("valid"), s);
        let stepping = MotionStats { sideways: Some(Sideways { mean_mm: 28.5, sd_mm: 1.5 }), ..s };
        let text = serde_json::to_string(&stepping).expect("numbers");
        assert!(text.ends_with(r#""rotation_sd_deg":18.0,"sideways":{"mean_mm":28.5,"sd_mm":1.5}}"#), "{text}");
        assert_eq!(serde_json::from_str::<MotionStats>(&text).expect("valid"), stepping);
    }
}
