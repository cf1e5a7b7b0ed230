//! One LBG fit of the thesis's codebook (125 000 × 3 points to 512 codewords), timed, for
//! profilers (`valgrind --tool=callgrind`) and for checking that an optimisation leaves the
//! codebook unchanged: `cargo bench -p polymimic-vq --bench lbg_once -- --dump FILE` writes
//! the bits of every codeword of a few fits, one per line.

mod common;

use std::fmt::Write as _;
use std::time::Instant;

use polymimic_vq::{Codebook, LbgParams};

fn fit(data: &[f64], dim: usize, size: usize, seed: u64) -> Codebook {
    let mut params = LbgParams::new(size);
    params.seed = seed;
    Codebook::fit(data, dim, params).expect("grows")
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let dump = args.iter().position(|a| a == "--dump").and_then(|i| args.get(i + 1));
    let points: usize = args
        .iter()
        .position(|a| a == "--points")
        .and_then(|i| args.get(i + 1))
        .map_or(125_000, |n| n.parse().expect("a number of points"));

    let data = common::tracker_like_points(points, 2);
    let start = Instant::now();
    let codebook = fit(&data, 3, 512, 0);
    let report = codebook.report();
    println!(
        "{points} × 3 → 512: {:.3} s, {} Lloyd iterations, {} re-seeded, distortion {:.6}",
        start.elapsed().as_secs_f64(),
        report.lloyd_iterations,
        report.reseeded_cells,
        report.distortion
    );

    if let Some(path) = dump {
        let mut text = String::new();
        let mut record = |name: &str, codebook: &Codebook| {
            let r = codebook.report();
            writeln!(
                text,
                "# {name}: {} iterations, {} re-seeded, distortion {:016x}",
                r.lloyd_iterations,
                r.reseeded_cells,
                r.distortion.to_bits()
            )
            .expect("writes");
            for codeword in codebook.codewords().chunks_exact(codebook.dim()) {
                let bits: Vec<String> = codeword.iter().map(|x| format!("{:016x}", x.to_bits())).collect();
                writeln!(text, "{}", bits.join(" ")).expect("writes");
            }
        };
        record("125000x3 to 512, seed 0", &codebook);
        record("125000x3 to 300, seed 7", &fit(&data, 3, 300, 7));
        let flat: Vec<f64> = data.chunks_exact(3).flat_map(|p| [p[0], p[1]]).collect();
        record("125000x2 to 100, seed 1", &fit(&flat, 2, 100, 1));
        let wide: Vec<f64> =
            data[..60_000].chunks_exact(3).flat_map(|p| [p[0], p[1], p[2], p[0] - p[1], p[2] * 0.5]).collect();
        record("20000x5 to 128, seed 3", &fit(&wide, 5, 128, 3));
        let line: Vec<f64> = data.iter().step_by(3).copied().collect();
        record("125000x1 to 64, seed 0", &fit(&line, 1, 64, 0));
        // Few distinct points (a coarse grid): cells empty out and are re-seeded.
        let coarse: Vec<f64> = data.iter().map(|x| (x / 12.0).round()).collect();
        record("125000x3 coarse to 512, seed 0", &fit(&coarse, 3, 512, 0));
        let grid: Vec<f64> = data.iter().map(|x| (x / 4.0).round()).collect();
        record("125000x3 grid to 512, seed 0", &fit(&grid, 3, 512, 0));
        std::fs::write(path, text).expect("writes the dump");
        println!("codewords written to {path}");
    }
}
