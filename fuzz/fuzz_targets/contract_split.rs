//! Contractions under the naive link condition, then exact undo of all of them.
#![no_main]
use contractible_fuzz::{check_contract_undo, ContractInput};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: ContractInput| {
    check_contract_undo(&input);
});
