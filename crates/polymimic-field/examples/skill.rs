//! Goals and own goals of each demonstrator over 25 demonstrations per configuration (Table
//! 4.6): `cargo run --release --example skill -- [seed] [n_per_configuration]`.

use std::time::Instant;

use polymimic_field::{Command, Configuration, Demonstrator, FieldConfig, LapseRate, Outcome, record};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let seed: u64 = args.get(1).map_or(Ok(0), |s| s.parse())?;
    let n: usize = args.get(2).map_or(Ok(25), |s| s.parse())?;
    let config = FieldConfig::default();
    println!("demonstrator config  goal own  ball_out robot_out time_up  mean_s   wall_ms");
    for d in Demonstrator::ALL {
        for c in Configuration::ALL {
            let start = Instant::now();
            let demos = record(d, c, n, seed, LapseRate::NONE, &config)?;
            let ms = start.elapsed().as_secs_f64() * 1e3;
            let count = |o: Outcome| demos.iter().filter(|x| x.outcome == o).count();
            let mean_s = demos.iter().map(|x| x.frames.last().map_or(0.0, |f| f.t_s)).sum::<f64>() / demos.len() as f64;
            println!(
                "{:12} {:6}  {:4} {:3}  {:8} {:9} {:7}  {:6.1}  {:8.1}",
                d.name(),
                c.number(),
                count(Outcome::Goal),
                count(Outcome::OwnGoal),
                count(Outcome::BallOut),
                count(Outcome::RobotOut),
                count(Outcome::TimeUp),
                mean_s,
                ms
            );
        }
    }
    println!("\ncommands used (count of frames) per demonstrator, configurations pooled:");
    for d in Demonstrator::ALL {
        let mut counts = std::collections::BTreeMap::new();
        for c in Configuration::ALL {
            for demo in record(d, c, n, seed, LapseRate::NONE, &config)? {
                for f in &demo.frames {
                    *counts.entry(f.command).or_insert(0usize) += 1;
                }
            }
        }
        let names: Vec<String> = counts
            .iter()
            .map(|(id, n)| {
                let c = Command::from_id(*id).map_or("?", Command::name);
                format!("{c}:{n}")
            })
            .collect();
        println!("{:9} {} distinct: {}", d.name(), counts.len(), names.join(" "));
    }
    Ok(())
}
