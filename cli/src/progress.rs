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

/// The bars of one library task call, driven by its [`contractible::Monitor`]: a spinner
/// while the input is checked, a [`StageBar`] following the algorithm inside each
/// component (`VERB (NAME), component i/n`; with components in parallel, the one that
/// started last), and a bar over the components while their outputs are verified.
pub struct TaskBars {
    ui: Ui,
    verb: &'static str,
    name: String,
    verify_message: &'static str,
    check: Option<ProgressBar>,
    run: Option<StageBar>,
    verify: Option<ProgressBar>,
    /// Simplification: edges contracted so far in the current component.
    contracted: usize,
    /// The number of components (known from the first run step).
    components: usize,
    /// The component the run bar follows: the one whose run started last (components
    /// processed in parallel report interleaved; the others' reports are not drawn).
    current: usize,
    /// Components whose verification started (in parallel, in any order).
    verifying: u64,
}

impl TaskBars {
    /// The monitor to pass in the task's options, and the bars it drives (call
    /// [`TaskBars::finish`] on them when the call returns).
    pub fn monitor(
        ui: Ui,
        verb: &'static str,
        name: String,
        verify_message: &'static str,
    ) -> (
        contractible::Monitor,
        std::sync::Arc<std::sync::Mutex<TaskBars>>,
    ) {
        let bars = std::sync::Arc::new(std::sync::Mutex::new(TaskBars {
            ui,
            verb,
            name,
            verify_message,
            check: None,
            run: None,
            verify: None,
            contracted: 0,
            components: 1,
            current: 0,
            verifying: 0,
        }));
        let shared = std::sync::Arc::clone(&bars);
        let monitor = contractible::Monitor::new().observe(move |e| {
            // A poisoned lock means a bar panicked: drawing is not worth a second panic.
            if let Ok(mut b) = shared.lock() {
                b.on(e);
            }
        });
        (monitor, bars)
    }

    fn on(&mut self, e: &contractible::task::Event) {
        use contractible::task::{Event, Step};
        match *e {
            Event::Step {
                step: Step::Build,
                faces,
                ..
            } => {
                self.check = Some(spinner(self.ui, format!("checking {faces} faces")));
            }
            Event::Step {
                step: Step::Run,
                component,
                components,
                ..
            } => {
                if let Some(pb) = self.check.take() {
                    pb.finish_and_clear();
                }
                self.contracted = 0;
                self.components = components;
                self.current = component;
                let prefix = component_prefix(self.verb, &self.name, component, components);
                match &mut self.run {
                    Some(bar) => bar.set_prefix(prefix),
                    None => self.run = Some(StageBar::new(self.ui, prefix)),
                }
            }
            Event::Step {
                step: Step::Verify,
                components,
                ..
            } => {
                if let Some(bar) = self.run.take() {
                    bar.finish();
                }
                let pb = self
                    .verify
                    .get_or_insert_with(|| bar(self.ui, components as u64, self.verify_message));
                // The verifications started before this one: in sequence, the components
                // done; in parallel, also the few still running on other threads.
                pb.set_position(self.verifying);
                self.verifying += 1;
            }
            Event::Progress {
                component,
                progress,
            } => {
                if let (Some(bar), true) = (&mut self.run, component == self.current) {
                    bar.observe(progress);
                }
            }
            Event::Pass(r) => {
                self.contracted += r.contracted;
                if let Some(bar) = &mut self.run {
                    // Short enough for one terminal line.
                    bar.set_prefix(format!(
                        "{}, pass {} ({} contracted so far, {} faces)",
                        component_prefix(self.verb, &self.name, r.component, self.components),
                        r.pass + 1,
                        self.contracted,
                        r.faces
                    ));
                }
            }
        }
    }

    /// Clears every bar.
    pub fn finish(&mut self) {
        if let Some(pb) = self.check.take() {
            pb.finish_and_clear();
        }
        if let Some(bar) = self.run.take() {
            bar.finish();
        }
        if let Some(pb) = self.verify.take() {
            pb.finish_and_clear();
        }
    }
}

/// Clears the bars of a finished call.
pub fn finish(bars: &std::sync::Mutex<TaskBars>) {
    if let Ok(mut b) = bars.lock() {
        b.finish();
    }
}

/// `VERB (NAME)`, plus `, component i/n` when there are several.
pub fn component_prefix(verb: &str, name: &str, i: usize, n: usize) -> String {
    if n > 1 {
        format!("{verb} ({name}), component {}/{n}", i + 1)
    } else {
        format!("{verb} ({name})")
    }
}
