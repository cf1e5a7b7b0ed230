//! Writes the valid files each fuzz target's corpus starts from:
//! `cargo +nightly run --manifest-path fuzz/Cargo.toml --example seed_corpus` (from the
//! repository root) fills `fuzz/corpus/<target>/seed-*.json`.

use std::path::Path;

fn main() -> std::io::Result<()> {
    let corpus = Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus");
    for (target, name, text) in polymimic_fuzz::seeds() {
        let dir = corpus.join(target);
        std::fs::create_dir_all(&dir)?;
        std::fs::write(dir.join(name), &text)?;
        println!("{target}/{name}: {} bytes", text.len());
    }
    Ok(())
}
