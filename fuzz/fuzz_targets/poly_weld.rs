//! Raw bytes through the polygon reader (no format declared, then each format), polygon
//! triangulation, vertex welding and the STL reader's welding, each checked against its
//! documented rule by independent code (see `contractible_fuzz::check_poly_bytes`).
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    contractible_fuzz::check_poly_bytes(data);
});
