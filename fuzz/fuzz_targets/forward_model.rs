#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| polymimic_fuzz::forward_model(&String::from_utf8_lossy(data)));
