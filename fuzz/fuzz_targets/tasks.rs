//! The per-task library calls (`describe`, `reduce`, `quadrangulate`, `simplify`) on
//! arbitrary face lists: never a panic, every refusal a typed input error that agrees with
//! `describe` and an independent surface oracle, every output checked from its face lists
//! (see `contractible_fuzz::check_tasks`).
#![no_main]
use contractible_fuzz::{check_tasks, TaskInput};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: TaskInput| {
    check_tasks(&input);
});
