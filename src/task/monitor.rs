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
    /// component `component` of `components` (`faces`: that component's), in component
    /// order unless the components run in parallel (then in any order, every run
    /// before every verification).
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
    /// Progress inside the algorithm of component `component` (see
    /// [`crate::progress`]). Components run in parallel (the options' `parallel`) report
    /// interleaved, each under its own index.
    Progress {
        /// The component (0-based) whose algorithm reports.
        component: usize,
        /// The report.
        progress: Progress,
    },
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

    /// The observer an algorithm takes, forwarding its reports as [`Event::Progress`]
    /// of component `component`.
    pub(crate) fn progress(&self, component: usize) -> impl FnMut(Progress) + '_ {
        move |progress| {
            self.report(&Event::Progress {
                component,
                progress,
            })
        }
    }

    /// `run(i, item, observer)` on every item `i` of `items` (pairs of a face count,
    /// reported with the step, and the item), each after [`Monitor::step`] `(step, i,
    /// n)`; the results in the items' order.
    ///
    /// With `parallel` (and the crate's `parallel` feature; without it the flag is
    /// ignored) the items run on the current rayon thread pool, the global one unless
    /// the caller runs the call inside `ThreadPool::install`; events of different items
    /// then interleave. Either way the result is the same: the outputs in item order or,
    /// if any item fails, the error of the first failing item in item order (in
    /// parallel the later items may have run too; their results are dropped).
    pub(crate) fn each_component<I: Send, T: Send>(
        &self,
        step: Step,
        parallel: bool,
        items: Vec<(usize, I)>,
        run: impl Fn(usize, I, &mut dyn FnMut(Progress)) -> Result<T, crate::Error> + Sync,
    ) -> Result<Vec<T>, crate::Error> {
        let n = items.len();
        let one = |i: usize, faces: usize, item: I| {
            self.step(step, i, n, faces)?;
            run(i, item, &mut self.progress(i))
        };
        #[cfg(feature = "parallel")]
        if parallel && n > 1 {
            use rayon::prelude::*;
            let results: Vec<Result<T, crate::Error>> = items
                .into_par_iter()
                .enumerate()
                .map(|(i, (faces, item))| one(i, faces, item))
                .collect();
            // The first error in item order, as the sequential loop would stop at.
            return results.into_iter().collect();
        }
        #[cfg(not(feature = "parallel"))]
        let _ = parallel;
        items
            .into_iter()
            .enumerate()
            .map(|(i, (faces, item))| one(i, faces, item))
            .collect()
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

    /// [`Monitor::each_component`], which every task's component loop uses: results in
    /// item order, the first failing item's error (in parallel too, where later items
    /// may fail first in time), each item's step and progress reported under its own
    /// index, and in sequence no item run after a failure.
    #[test]
    #[cfg(feature = "parallel")]
    fn components_run_in_order_or_in_parallel_with_the_same_result() {
        let events = Arc::new(Mutex::new(Vec::new()));
        let e = Arc::clone(&events);
        let m = Monitor::new().observe(move |ev| {
            let mut e = e.lock().expect("not poisoned");
            match *ev {
                Event::Step {
                    step,
                    component,
                    components,
                    faces,
                } => e.push((step, component, components, faces, None)),
                Event::Progress {
                    component,
                    progress,
                } => e.push((Step::Run, component, 0, 0, Some(progress.done))),
                Event::Pass(_) => {}
            }
        });
        let items = |k: usize| (0..k).map(|i| (10 * i, i)).collect::<Vec<_>>();
        let ran = Arc::new(Mutex::new(Vec::new()));
        let run = |i: usize, item: usize, observer: &mut dyn FnMut(Progress)| {
            ran.lock().expect("not poisoned").push(i);
            observer(Progress {
                stage: "item",
                done: item as u64 + 100,
                total: 200,
            });
            // Items 3 and 5 fail: the call returns item 3's error, whichever fails
            // first in time.
            if item == 3 || item == 5 {
                Err(crate::Error::BadOption {
                    option: "item",
                    value: item.to_string(),
                    expected: String::new(),
                })
            } else {
                Ok(item * item)
            }
        };
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(3)
            .build()
            .expect("a pool");
        for parallel in [false, true] {
            events.lock().expect("not poisoned").clear();
            ran.lock().expect("not poisoned").clear();
            let ok = pool.install(|| m.each_component(Step::Verify, parallel, items(3), run));
            assert_eq!(ok.expect("no failing item"), vec![0, 1, 4]);
            let mut seen = events.lock().expect("not poisoned").clone();
            seen.sort_by_key(|e| (e.1, e.4.is_some()));
            assert_eq!(
                seen,
                vec![
                    (Step::Verify, 0, 3, 0, None),
                    (Step::Run, 0, 0, 0, Some(100)),
                    (Step::Verify, 1, 3, 10, None),
                    (Step::Run, 1, 0, 0, Some(101)),
                    (Step::Verify, 2, 3, 20, None),
                    (Step::Run, 2, 0, 0, Some(102)),
                ],
                "parallel: {parallel}"
            );
            ran.lock().expect("not poisoned").clear();
            let err = pool
                .install(|| m.each_component(Step::Run, parallel, items(8), run))
                .unwrap_err();
            assert!(
                matches!(&err, crate::Error::BadOption { value, .. } if value == "3"),
                "parallel: {parallel}: {err}"
            );
            let mut ran = ran.lock().expect("not poisoned").clone();
            ran.sort_unstable();
            if parallel {
                assert!(ran.starts_with(&[0, 1, 2, 3]), "{ran:?}");
            } else {
                assert_eq!(ran, vec![0, 1, 2, 3]);
            }
        }
    }
}
