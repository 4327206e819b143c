//! The conformance checker for `simplify` (`contractible::check::simplify`) on the
//! library's own answers and edited ones, on surfaces with holes: never a panic; the
//! library's answer passes; a passing verdict confirmed by the core (see
//! `contractible_fuzz::check_simplify_check`).
#![no_main]
use contractible_fuzz::{check_simplify_check, CheckSimplifyInput};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: CheckSimplifyInput| {
    check_simplify_check(&input);
});
