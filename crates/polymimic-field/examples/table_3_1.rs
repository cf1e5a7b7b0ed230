//! Print Table 3.1 as the simulated imitator reproduces it: `cargo run --release --example
//! table_3_1 -- [sessions] [noiseless]` (each session: 1000 primitives of each type).

use polymimic_field::{
    FieldConfig, Primitive, THESIS_TABLE_3_1, TrackerConfig, primitive_stats, self_observation, table_3_1_row,
};

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
    for thesis in &THESIS_TABLE_3_1 {
        println!("{}", table_3_1_row(&stats[thesis.primitive.index()], Some(thesis)));
    }
    println!("{}", table_3_1_row(&stats[Primitive::Stop.index()], None));
    Ok(())
}
