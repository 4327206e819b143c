//! The conformance checker (`contractible::check::reduce`) on answers made by contracting
//! a surface grown by vertex splits, some irreducible, some not, some corrupted: never a
//! panic; exact on unedited answers; a passing verdict confirmed by the core (see
//! `contractible_fuzz::check_check`).
#![no_main]
use contractible_fuzz::{check_check, CheckInput};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: CheckInput| {
    check_check(&input);
});
