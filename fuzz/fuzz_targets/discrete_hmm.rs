#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| polymimic_fuzz::discrete_hmm(&String::from_utf8_lossy(data)));
