//! Progress reports from long computations, for callers that show them (the command
//! line draws them as bars; the library depends on nothing to do so).
//!
//! An algorithm that takes an observer (`&mut dyn FnMut(Progress)`) calls it when it
//! starts, at most once every [`REPORT_EVERY`] steps of its main loop, and when it ends
//! (with `done == total`), so that the observer's cost is negligible next to the work:
//! one counter comparison per step. The functions without an observer pass
//! [`ignore`].

/// Steps (link tests, contractions, settled vertices, ...) between two reports.
pub const REPORT_EVERY: u64 = 4096;

/// One report: `done` of `total` units of the step named `stage`.
///
/// Guarantees: within one stage of one run, `done` never decreases and never exceeds
/// `total`; the last report of a stage has `done == total` unless the stage is cut short
/// (the brute force's last pass ends as soon as its array is exhausted, which is also
/// `done == total`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Progress {
    /// What is counted, in the words a progress bar can show (e.g. "vertices settled").
    pub stage: &'static str,
    /// Units done so far.
    pub done: u64,
    /// Units in all (an upper bound known when the stage starts).
    pub total: u64,
}

impl Progress {
    /// `done` of `total` in `stage`, with `done` clamped to `total`.
    pub fn new(stage: &'static str, done: u64, total: u64) -> Self {
        Progress {
            stage,
            done: done.min(total),
            total,
        }
    }
}

/// The observer that ignores every report.
pub fn ignore(_: Progress) {}

/// Calls an observer every [`REPORT_EVERY`] steps: `tick` is a counter comparison, the
/// observer runs only when a report is due.
#[derive(Debug, Default, Clone, Copy)]
pub struct Throttle {
    next: u64,
}

impl Throttle {
    /// A throttle whose first report is due after [`REPORT_EVERY`] steps.
    pub fn new() -> Self {
        Throttle { next: REPORT_EVERY }
    }

    /// Whether a report is due at `steps` steps (and if so, schedules the next one).
    #[inline]
    pub fn due(&mut self, steps: u64) -> bool {
        if steps < self.next {
            return false;
        }
        self.next = steps + REPORT_EVERY;
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn throttle_fires_once_per_period_and_progress_clamps() {
        let mut t = Throttle::new();
        let fired: Vec<u64> = (0..3 * REPORT_EVERY + 1).filter(|&s| t.due(s)).collect();
        assert_eq!(
            fired,
            vec![REPORT_EVERY, 2 * REPORT_EVERY, 3 * REPORT_EVERY]
        );
        assert_eq!(Progress::new("x", 7, 5).done, 5);
    }
}
