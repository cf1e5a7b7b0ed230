//! Vector quantisation by the Linde-Buzo-Gray algorithm.
//!
//! A codebook grows from the data's mean by splitting every codeword in two and refining
//! with Lloyd's k-means, until it reaches the size asked for. Nearest codewords are found
//! with a k-d tree, exact and fast in the low dimensions of tracker frames.
//!
//! ```
//! use polymimic_vq::{Codebook, LbgParams};
//!
//! let data: Vec<f64> = (0..400).map(|i| f64::from(i % 20)).collect(); // 200 points in 2-D
//! let codebook = Codebook::fit(&data, 2, LbgParams::new(16))?;
//! assert_eq!(codebook.len(), 16);
//! let symbols = codebook.encode(&[3.0, 3.0, 18.0, 19.0], 2)?;
//! assert_eq!(symbols.len(), 2);
//! # Ok::<(), polymimic_vq::VqParamsError>(())
//! ```

mod bounds;
mod codebook;
mod error;
mod kdtree;
mod lbg;
mod lloyd;
mod points;

pub use codebook::Codebook;
pub use error::{VqError, VqParamsError};
pub use kdtree::KdTree;
pub use lbg::{LbgParams, LbgReport, grow};
pub use lloyd::{Refinement, Stopping};
pub use points::{Points, distance2};
