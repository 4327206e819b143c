//! Progress indication on stderr (hidden with `--quiet`; indicatif itself hides it when
//! stderr is not a terminal).

use std::time::Duration;

use contractible::progress::Progress;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use super::Ui;

/// A spinner with a message, ticking in the background until dropped or finished.
pub fn spinner(ui: Ui, msg: impl Into<String>) -> ProgressBar {
    if ui.quiet {
        return ProgressBar::hidden();
    }
    let pb = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
    pb.set_style(
        ProgressStyle::with_template("{spinner} {msg} [{elapsed}]")
            .unwrap_or_else(|_| ProgressStyle::default_spinner()),
    );
    pb.set_message(msg.into());
    pb.enable_steady_tick(Duration::from_millis(100));
    pb
}

/// A bar over `len` steps with a message.
pub fn bar(ui: Ui, len: u64, msg: impl Into<String>) -> ProgressBar {
    if ui.quiet {
        return ProgressBar::hidden();
    }
    let pb = ProgressBar::with_draw_target(Some(len), ProgressDrawTarget::stderr());
    pb.set_style(
        ProgressStyle::with_template("{msg} [{bar:30}] {pos}/{len} [{elapsed}]")
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> "),
    );
    pb.set_message(msg.into());
    pb.enable_steady_tick(Duration::from_millis(200));
    pb
}

/// A bar over `len` bytes showing the bytes done, the total and the percentage.
pub fn bytes_bar(ui: Ui, len: u64, msg: impl Into<String>) -> ProgressBar {
    if ui.quiet {
        return ProgressBar::hidden();
    }
    let pb = ProgressBar::with_draw_target(Some(len), ProgressDrawTarget::stderr());
    pb.set_style(
        ProgressStyle::with_template(
            "{msg} [{bar:30}] {bytes}/{total_bytes} ({percent}%) [{elapsed}]",
        )
        .unwrap_or_else(|_| ProgressStyle::default_bar())
        .progress_chars("=> "),
    );
    pb.set_message(msg.into());
    pb.enable_steady_tick(Duration::from_millis(200));
    pb
}

/// A bar for the work inside one component: `prefix` (what runs, and which component of
/// how many) followed by the stage the algorithm reports, its count and percentage.
/// Until the first report it is a spinner (the algorithm may prepare for a while);
/// feed it with [`StageBar::observe`].
pub struct StageBar {
    pb: ProgressBar,
    prefix: String,
    stage: &'static str,
    counting: bool,
}

fn stage_spinner_style() -> ProgressStyle {
    ProgressStyle::with_template("{spinner} {msg} [{elapsed}]")
        .unwrap_or_else(|_| ProgressStyle::default_spinner())
}

fn stage_bar_style() -> ProgressStyle {
    ProgressStyle::with_template(
        "{msg} [{bar:30}] {human_pos}/{human_len} ({percent}%) [{elapsed}]",
    )
    .unwrap_or_else(|_| ProgressStyle::default_bar())
    .progress_chars("=> ")
}

impl StageBar {
    pub fn new(ui: Ui, prefix: impl Into<String>) -> Self {
        let pb = if ui.quiet {
            ProgressBar::hidden()
        } else {
            let pb = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
            pb.set_style(stage_spinner_style());
            pb.enable_steady_tick(Duration::from_millis(200));
            pb
        };
        let prefix = prefix.into();
        pb.set_message(prefix.clone());
        StageBar {
            pb,
            prefix,
            stage: "",
            counting: false,
        }
    }

    /// Names the component (or other unit) the next reports belong to; back to a
    /// spinner until its first report.
    pub fn set_prefix(&mut self, prefix: impl Into<String>) {
        self.prefix = prefix.into();
        self.stage = "";
        if self.counting {
            self.counting = false;
            self.pb.set_style(stage_spinner_style());
        }
        self.pb.set_message(self.prefix.clone());
    }

    /// Shows one report of the library.
    pub fn observe(&mut self, p: Progress) {
        // Count first, so that no redraw shows the new stage with the old count.
        self.pb.set_length(p.total);
        self.pb.set_position(p.done);
        if p.stage != self.stage {
            self.stage = p.stage;
            self.pb.set_message(format!("{}: {}", self.prefix, p.stage));
        }
        if !self.counting {
            self.counting = true;
            self.pb.set_style(stage_bar_style());
        }
    }

    pub fn finish(&self) {
        self.pb.finish_and_clear();
    }
}

/// A spinner that counts bytes (for writes, whose size is known only at the end).
pub fn byte_spinner(ui: Ui, msg: impl Into<String>) -> ProgressBar {
    if ui.quiet {
        return ProgressBar::hidden();
    }
    let pb = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
    pb.set_style(
        ProgressStyle::with_template(
            "{spinner} {msg}: {bytes} ({binary_bytes_per_sec}) [{elapsed}]",
        )
        .unwrap_or_else(|_| ProgressStyle::default_spinner()),
    );
    pb.set_message(msg.into());
    pb.enable_steady_tick(Duration::from_millis(100));
    pb
}
