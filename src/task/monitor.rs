//! Progress observation and cancellation of a task call.

use std::fmt;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

use crate::progress::Progress;
use crate::simplify::PassReport;

/// The steps of a task call, in order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    /// Validating the faces and splitting them into components.
    Build,
    /// Running the algorithm on one component.
    Run,
    /// Checking one component's output independently.
    Verify,
}

/// What a task call reports to its [`Monitor`].
#[derive(Clone, Copy, Debug)]
pub enum Event {
    /// A step starts: [`Step::Build`] once (with `component == 0`, `components == 0`
    /// and `faces` the input's face count); [`Step::Run`] and [`Step::Verify`] once per
    /// component `component` of `components` (`faces`: that component's).
    Step {
        /// Which step.
        step: Step,
        /// The component (0-based).
        component: usize,
        /// The number of components.
        components: usize,
        /// Faces concerned.
        faces: usize,
    },
    /// Progress inside the algorithm of the current component (see [`crate::progress`]).
    Progress(Progress),
    /// `simplify` only: a pass over the current component ended.
    Pass(PassReport),
}

type Observer = dyn Fn(&Event) + Send + Sync;

/// How a task call reports progress and learns it should stop. The default observes
/// nothing and never cancels. Cheap to clone (shared handles).
///
/// Cancellation is checked before every step and every component (and so between the
/// components of a mesh): a cancelled call returns [`crate::Error::Cancelled`] at the
/// next check and produces nothing. A running algorithm is not interrupted inside one
/// component.
#[derive(Clone, Default)]
pub struct Monitor {
    observer: Option<Arc<Observer>>,
    cancel: Option<Arc<AtomicBool>>,
}

impl fmt::Debug for Monitor {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Monitor")
            .field("observer", &self.observer.is_some())
            .field("cancelled", &self.is_cancelled())
            .finish()
    }
}

impl Monitor {
    /// A monitor that observes nothing and never cancels.
    pub fn new() -> Self {
        Monitor::default()
    }

    /// This monitor calling `observer` with every [`Event`].
    pub fn observe(mut self, observer: impl Fn(&Event) + Send + Sync + 'static) -> Self {
        self.observer = Some(Arc::new(observer));
        self
    }

    /// This monitor cancelling the call once `flag` is set (from any thread).
    pub fn cancel_on(mut self, flag: Arc<AtomicBool>) -> Self {
        self.cancel = Some(flag);
        self
    }

    /// Whether the cancellation flag is set.
    pub fn is_cancelled(&self) -> bool {
        self.cancel
            .as_ref()
            .is_some_and(|c| c.load(Ordering::Relaxed))
    }

    /// Reports `event` to the observer, if any.
    pub fn report(&self, event: &Event) {
        if let Some(o) = &self.observer {
            o(event);
        }
    }

    /// Reports the start of a step, then fails with [`crate::Error::Cancelled`] if the
    /// call was cancelled.
    pub(crate) fn step(
        &self,
        step: Step,
        component: usize,
        components: usize,
        faces: usize,
    ) -> Result<(), crate::Error> {
        if self.is_cancelled() {
            return Err(crate::Error::Cancelled);
        }
        self.report(&Event::Step {
            step,
            component,
            components,
            faces,
        });
        Ok(())
    }

    /// The observer an algorithm takes, forwarding its reports as [`Event::Progress`].
    pub(crate) fn progress(&self) -> impl FnMut(Progress) + '_ {
        move |p| self.report(&Event::Progress(p))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Mutex;

    #[test]
    fn a_monitor_reports_and_cancels() {
        let seen = Arc::new(Mutex::new(Vec::new()));
        let flag = Arc::new(AtomicBool::new(false));
        let s = Arc::clone(&seen);
        let m = Monitor::new()
            .observe(move |e| {
                if let Event::Step { step, .. } = e {
                    s.lock().expect("not poisoned").push(*step);
                }
            })
            .cancel_on(Arc::clone(&flag));
        assert!(m.step(Step::Build, 0, 0, 4).is_ok());
        flag.store(true, Ordering::Relaxed);
        assert!(matches!(
            m.step(Step::Run, 0, 1, 4),
            Err(crate::Error::Cancelled)
        ));
        assert_eq!(*seen.lock().expect("not poisoned"), vec![Step::Build]);
        assert!(format!("{m:?}").contains("cancelled: true"));
    }
}
