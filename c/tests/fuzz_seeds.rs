//! The fuzz target `c_abi`'s seed corpus (`fuzz/corpus/c_abi/`) and its minimized crash
//! inputs (`fuzz/regressions/c_abi/`, once a campaign finds one) replayed through the
//! target's own check, so they run in every `cargo test`.

use std::path::PathBuf;

#[test]
fn the_c_abi_seeds_and_regressions_pass_the_targets_check() {
    let fuzz = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../fuzz");
    let mut decoded = 0;
    for dir in ["corpus", "regressions"] {
        let Ok(entries) = std::fs::read_dir(fuzz.join(dir).join("c_abi")) else {
            assert_eq!(
                dir, "regressions",
                "the seed corpus is part of the repository"
            );
            continue;
        };
        let mut paths: Vec<PathBuf> = entries.map(|e| e.expect("an entry").path()).collect();
        paths.sort();
        for path in paths {
            let bytes = std::fs::read(&path).expect("reads");
            if let Some(input) = crate::harness::decode::<crate::c_abi::CAbiInput>(&bytes) {
                eprintln!("c_abi: {}", path.display());
                crate::c_abi::check_c_abi(&input);
                decoded += 1;
            }
        }
    }
    assert!(decoded >= 8, "c_abi: {decoded} inputs decoded");
}
