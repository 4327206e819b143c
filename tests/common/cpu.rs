//! CPU time of the calling thread, shared by the algorithm tests that report it and the
//! profiling tools (`tools/src/lib.rs` includes this file).

/// CPU seconds of the calling thread (from `/proc/thread-self/stat`, 10 ms ticks; 0
/// where that file does not exist).
pub fn cpu() -> f64 {
    let Ok(stat) = std::fs::read_to_string("/proc/thread-self/stat") else {
        return 0.0;
    };
    let rest = stat.rsplit(')').next().unwrap_or("");
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks = |i: usize| f.get(i).and_then(|x| x.parse::<f64>().ok()).unwrap_or(0.0);
    (ticks(11) + ticks(12)) / 100.0
}
