//! Contractions, flips and undos interleaved through a `Journal`, with edge numbers in
//! lockstep and changes behind the journal's back refused by the state guard.
#![no_main]
use contractible_fuzz::{check_journal, JournalInput};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: JournalInput| {
    check_journal(&input);
});
