use super::*;
use crate::config::LearningConfig;
use crate::model::ForwardModel;

fn record() -> TrialRecord {
    let config = LearningConfig::default();
    let mut expert = ForwardModel::new("expert", 0.5, false, &config);
    expert.lp = 0.8369656826815547;
    expert.lp_history = vec![0.5, 0.50008, 1e-5];
    let imitator = ForwardModel::new("imitator", 0.9, true, &config);
    TrialRecord::of(&TrialResult { models: vec![expert], imitator }, 3)
}

#[test]
fn a_record_reads_back_equal_and_writes_the_same_text() {
    let record = record();
    let text = record.to_json();
    assert!(text.starts_with(r#"{"models": {"expert": {"name": "expert", "lp": 0.8369656826815547, "lp_history": [0.5, 0.50008, 1e-05], "match_rate": 0.0, "created": 0,"#), "{text}");
    assert!(
        text.contains(r#""behaviours": [{"primitives": "F", "permanency": 1.0, "permanent": true, "age": 0,"#),
        "{text}"
    );
    let again = TrialRecord::from_json(&text).unwrap();
    assert_eq!(again, record);
    assert_eq!(again.to_json(), text);
    assert_eq!(again.imitator_model.as_deref(), record.imitator_model.as_deref());
}

fn error_of(text: &str) -> RecordError {
    TrialRecord::from_json(text).unwrap_err()
}

#[test]
fn a_damaged_value_is_named_by_its_key() {
    let text = record().to_json();
    let high = text.replacen(r#""lp": 0.8369656826815547"#, r#""lp": "high""#, 1);
    assert_eq!(error_of(&high).to_string(), r#"models.expert.lp: "high" is not a number"#);
    let above = text.replacen(r#""lp": 0.8369656826815547"#, r#""lp": 1.5"#, 1);
    assert_eq!(error_of(&above).to_string(), "models.expert.lp: 1.5 is not a number in [0, 1]");
    let negative = text.replacen(r#""seed": 3"#, r#""seed": -3"#, 1);
    assert_eq!(error_of(&negative).to_string(), "seed: -3 is not a whole number ≥ 0");
    let letters = text.replacen(r#""primitives": "F""#, r#""primitives": "FX""#, 1);
    assert!(error_of(&letters).to_string().starts_with("models.expert.behaviours[0].primitives: \"FX\""));
    let foreign = text.replacen(r#""seed": 3"#, r#""seed": 3, "colour": "red""#, 1);
    assert!(error_of(&foreign).to_string().starts_with("colour: unknown key"));
    let missing = text.replacen(r#""match_rate": 0.0, "#, "", 1);
    assert_eq!(error_of(&missing).to_string(), "models.expert.match_rate: missing");
    let model = text.replacen(r#"{\"format\""#, r#"{\"formats\""#, 1);
    assert!(error_of(&model).to_string().starts_with("imitator_model: "), "{}", error_of(&model));
}

#[test]
fn a_truncated_record_names_where_it_ends() {
    let text = record().to_json();
    let cut = &text[..text.find("0.50008").unwrap()];
    assert_eq!(
        error_of(cut),
        RecordError::Syntax {
            at: "models.expert.lp_history[1]".to_owned(),
            why: "the text ends early (EOF while parsing a value at line 1 column 87)".to_owned()
        }
    );
    assert!(matches!(error_of("[1, 2]"), RecordError::Value { .. }));
}
