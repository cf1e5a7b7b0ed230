//! Saved files written by earlier builds must load and write back byte for byte: a recogniser
//! (its codebooks, HMMs and Table 3.1), a forward model and a field config, each saved by the
//! code as it stood when the fixture was made.

use polymimic_field::FieldConfig;
use polymimic_learn::ForwardModel;
use polymimic_perceive::Recognizer;

fn fixture(name: &str) -> String {
    let path = format!("{}/tests/fixtures/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

#[test]
fn a_saved_recogniser_loads_and_saves_identically() {
    let text = fixture("recognizer.json");
    let recognizer = Recognizer::from_json(&text).expect("a recogniser saved earlier loads");
    assert_eq!(recognizer.to_json().expect("saves"), text);
}

#[test]
fn a_saved_forward_model_loads_and_saves_identically() {
    let text = fixture("forward_model.json");
    let model = ForwardModel::from_json(&text).expect("a forward model saved earlier loads");
    assert_eq!(model.to_json(), text);
}

#[test]
fn a_saved_field_config_loads_and_saves_identically() {
    let text = fixture("field_config.json");
    let config = FieldConfig::from_json(&text).expect("a field config saved earlier loads");
    assert_eq!(config.to_json(), text);
}
