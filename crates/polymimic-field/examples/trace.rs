//! Print one demonstration every half second: `cargo run --release --example trace -- expert 1 [seed]`.

use polymimic_field::{Command, Configuration, Demonstrator, FieldConfig, LapseRate, demonstrate};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let d = Demonstrator::from_name(args.get(1).map_or("expert", String::as_str))?;
    let c = if args.get(2).is_some_and(|s| s == "2") { Configuration::Two } else { Configuration::One };
    let seed: u64 = args.get(3).map_or(Ok(0), |s| s.parse())?;
    let demo = demonstrate(d, c, seed, LapseRate::NONE, &FieldConfig::default())?;
    for f in demo.frames.iter().step_by(15) {
        println!(
            "{:5.1}s robot ({:7.1}, {:7.1}, {:6.1}°) ball ({:7.1}, {:7.1}) {}",
            f.t_s,
            f.robot_x_mm,
            f.robot_y_mm,
            f.robot_theta_rad.to_degrees(),
            f.ball_x_mm,
            f.ball_y_mm,
            Command::from_id(f.command).map_or("?", Command::name)
        );
    }
    println!("{:?} after {} frames", demo.outcome, demo.frames.len());
    Ok(())
}
