//! Print Table 3.1 as the simulated imitator reproduces it: `cargo run --release --example
//! table_3_1 -- [sessions] [noiseless]` (each session: 1000 primitives of each type).

use polymimic_field::{FieldConfig, Primitive, THESIS_TABLE_3_1, TrackerConfig, primitive_stats, self_observation};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let sessions: u64 = args.get(1).map_or(Ok(1), |s| s.parse())?;
    let mut config = FieldConfig::default();
    if args.iter().any(|a| a == "noiseless") {
        config.tracker = TrackerConfig::noiseless();
    }
    let mut pooled = Vec::new();
    for seed in 0..sessions {
        pooled.extend(self_observation(1000, seed, &config)?);
    }
    let stats = primitive_stats(&pooled);
    println!("primitive  n       distance mm (sd)   thesis          rotation deg (sd)  thesis");
    for t in THESIS_TABLE_3_1.iter().copied().chain([stats[Primitive::Stop.index()]]) {
        let p = t.primitive;
        let s = stats[p.index()];
        println!(
            "{:9} {:6}  {:7.2} ({:5.2})   {:7.2} ({:5.2})   {:7.2} ({:5.2})   {:7.2} ({:5.2})",
            p.name(),
            s.count,
            s.distance_mean_mm,
            s.distance_sd_mm,
            t.distance_mean_mm,
            t.distance_sd_mm,
            s.rotation_mean_deg,
            s.rotation_sd_deg,
            t.rotation_mean_deg,
            t.rotation_sd_deg,
        );
    }
    Ok(())
}
