//! Any bytes through the reader, parser and checker, and the diagnostics rendered: none may panic.
//! Run with `cargo fuzz run parse` from the repository root.

#![no_main]

use behavior_bddl::activity::{Activity, CheckContext};
use behavior_bddl::data::source_from_bytes;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    match source_from_bytes("fuzz.bddl".into(), data.to_vec()) {
        Ok(source) => match Activity::load(&source, CheckContext::default()) {
            Ok((_, warnings)) => drop(warnings.render(&source)),
            Err(errors) => drop(errors.to_string()),
        },
        Err(errors) => drop(errors.to_string()),
    }
});
