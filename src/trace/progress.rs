//! How long work tells how far it got, and learns that it should stop: two
//! closures, so the library draws no progress bar and owns no terminal (the
//! binary turns the reports into a bar; the inspector cancels a picture it no
//! longer needs).

/// Reports `(done, total)` and answers whether to stop.
#[derive(Clone, Copy)]
pub struct Progress<'a> {
    report: &'a (dyn Fn(u64, u64) + Sync),
    cancelled: &'a (dyn Fn() -> bool + Sync),
}

impl<'a> Progress<'a> {
    /// Reports nowhere and never stops.
    pub const QUIET: Progress<'static> = Progress {
        report: &|_, _| {},
        cancelled: &|| false,
    };

    /// Reports to `report` as `(done, total)`; never stops.
    pub fn reporting(report: &'a (dyn Fn(u64, u64) + Sync)) -> Self {
        Progress {
            report,
            cancelled: Progress::QUIET.cancelled,
        }
    }

    /// Stops when `cancelled` says so; reports nowhere.
    pub fn cancellable(cancelled: &'a (dyn Fn() -> bool + Sync)) -> Self {
        Progress {
            report: Progress::QUIET.report,
            cancelled,
        }
    }

    /// Tells that `done` of `total` units are finished.
    pub fn report(&self, done: u64, total: u64) {
        (self.report)(done, total);
    }

    /// Whether the work is no longer wanted.
    pub fn cancelled(&self) -> bool {
        (self.cancelled)()
    }
}
