//! "Try the recent hit first", the lecture's trick for shadow rays: the object
//! that blocked the last shadow ray toward a light is likely to block the next
//! one too (neighbouring pixels lie in the same shadows), so it is tested first,
//! and when it blocks again the shadow ray is done after one test.
//!
//! Each thread remembers, per light, the last opaque blocker of each tracer
//! (a thread-local memory keyed by the tracer, so threads never wait on each
//! other; up to [`LIGHTS`] lights). Remembering changes only which object is tested first, never whether
//! the light is reached: a remembered object is opaque, and one that still
//! blocks would have blocked anyway. So images do not depend on it, whatever
//! the number of threads; the ray tree shows it in a shadow ray's `recent` and
//! its test counts.

use std::cell::Cell;
use std::sync::atomic::{AtomicU64, Ordering};

/// Lights remembered per thread; a scene's further lights go without.
pub const LIGHTS: usize = 16;

/// No object remembered.
const NOTHING: u32 = u32::MAX;

/// Tells tracers apart, so one tracer never sees another's memory.
static NEXT_TRACER: AtomicU64 = AtomicU64::new(1);

thread_local! {
    /// The tracer the memory on this thread belongs to (0: none yet).
    static OWNER: Cell<u64> = const { Cell::new(0) };
    /// Its last blocker per light. Plain cells: reading one costs a load.
    static LAST_BLOCKER: [Cell<u32>; LIGHTS] = const { [const { Cell::new(NOTHING) }; LIGHTS] };
}

/// One tracer's memory of the last blocker per light, on each thread.
#[derive(Debug)]
pub struct RecentBlockers {
    tracer: u64,
}

impl RecentBlockers {
    /// A memory of nothing yet.
    pub fn new() -> Self {
        RecentBlockers {
            tracer: NEXT_TRACER.fetch_add(1, Ordering::Relaxed),
        }
    }

    /// The object that last blocked a shadow ray toward `light` on this thread.
    #[inline]
    pub fn get(&self, light: usize) -> Option<usize> {
        if light >= LIGHTS || OWNER.get() != self.tracer {
            return None;
        }
        let object = LAST_BLOCKER.with(|last| last[light].get());
        (object != NOTHING).then_some(object as usize)
    }

    /// Forgets this thread's memory, so what is traced next does not depend
    /// on what this thread traced before (per-pixel counts that match
    /// `raytree trace`, which starts every pixel with nothing remembered).
    pub fn forget(&self) {
        if OWNER.get() == self.tracer {
            LAST_BLOCKER.with(|last| last.iter().for_each(|c| c.set(NOTHING)));
        }
    }

    /// Remembers that `object` (opaque) blocked a shadow ray toward `light`.
    #[inline]
    pub fn set(&self, light: usize, object: usize) {
        if light >= LIGHTS {
            return;
        }
        LAST_BLOCKER.with(|last| {
            if OWNER.get() != self.tracer {
                OWNER.set(self.tracer);
                last.iter().for_each(|c| c.set(NOTHING));
            }
            last[light].set(object as u32);
        });
    }
}

impl Default for RecentBlockers {
    fn default() -> Self {
        Self::new()
    }
}

/// A clone starts with a memory of its own: two tracers never share one, so
/// what one records cannot depend on what the other traced.
impl Clone for RecentBlockers {
    fn clone(&self) -> Self {
        Self::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn remembers_per_light_and_per_tracer() {
        let (a, b) = (RecentBlockers::new(), RecentBlockers::new());
        assert_eq!(a.get(0), None);
        a.set(1, 7);
        assert_eq!((a.get(0), a.get(1), a.get(5)), (None, Some(7), None));
        // Lights past the memory's size are never remembered.
        a.set(LIGHTS, 2);
        assert_eq!(a.get(LIGHTS), None);
        // Another tracer on the same thread starts from nothing, and takes over.
        assert_eq!(b.get(1), None);
        b.set(0, 3);
        assert_eq!((b.get(0), a.get(1)), (Some(3), None));
        // Another thread has a memory of its own.
        std::thread::scope(|s| {
            s.spawn(|| assert_eq!(b.get(0), None));
        });
        assert_eq!(b.get(0), Some(3));
    }
}
