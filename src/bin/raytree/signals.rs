//! What a signal ends, and how: on SIGINT, SIGTERM, SIGHUP or SIGQUIT the
//! program gives the terminal back, ends the outside program a command runs
//! (Ghostscript, a [`Helper`]) and removes its folder, removes every pending
//! file, says so in one line and exits as shells expect. The handler's exit
//! skips every destructor, so what it must clean up is registered here.

use std::io;
use std::process::{Child, ExitStatus, Output};
use std::sync::{Mutex, MutexGuard};

use raytree::io::output::remove_pending;

use crate::output;

/// On SIGINT, SIGTERM, SIGHUP or SIGQUIT: give the terminal back, remove every pending
/// file, say so in one line and exit with 128 + the signal's number (130 for
/// Ctrl-C), as shells do.
pub fn clean_up_on_signals() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGQUIT, SIGTERM};
    // SIGQUIT too: its default (a core dump) would leave the inspector's
    // terminal raw, and pending files behind.
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP, SIGQUIT])
    else {
        return;
    };
    std::thread::spawn(move || {
        if let Some(signal) = signals.forever().next() {
            raytree::inspector::restore();
            // Held until the exit: the command's thread, waiting on the
            // helper, must not see it end and report that as its error.
            let _helper = end_helper();
            remove_pending();
            let what = match signal {
                SIGINT => "interrupted",
                SIGTERM => "terminated (SIGTERM)",
                SIGQUIT => "quit (SIGQUIT)",
                _ => "hung up (SIGHUP)",
            };
            output::last_word_below_bar(&format!("{what}: no output written"));
            std::process::exit(128 + signal);
        }
    });
}

/// The outside program running for the command, and the temporary folder it
/// works in. The signal handler's exit skips every destructor, so without this
/// a signal would leave the program running as an orphan (forever, on a
/// program that loops) and its folder behind.
struct Running {
    /// `None` once it has ended and its output is being read.
    child: Option<Child>,
    /// Removed when dropped.
    _folder: tempfile::TempDir,
}

static HELPER: Mutex<Option<Running>> = Mutex::new(None);

fn helper() -> MutexGuard<'static, Option<Running>> {
    HELPER.lock().unwrap_or_else(|e| e.into_inner())
}

/// Kills the helper, if one runs, waits for it and removes its folder;
/// returns the lock, still held.
fn end_helper() -> MutexGuard<'static, Option<Running>> {
    let mut slot = helper();
    // Dropping what was taken removes the folder.
    if let Some(child) = slot.take().as_mut().and_then(|r| r.child.as_mut()) {
        let _ = child.kill();
        let _ = child.wait();
    }
    slot
}

/// An outside program (Ghostscript) that a command runs in a temporary
/// folder: a signal kills it and removes the folder, as does dropping this
/// (an error carried up with `?`). One at a time.
pub struct Helper(());

impl Helper {
    /// Registers `child`, just spawned, working in `folder`.
    pub fn start(child: Child, folder: tempfile::TempDir) -> Helper {
        let mut slot = helper();
        debug_assert!(slot.is_none(), "one helper at a time");
        *slot = Some(Running {
            child: Some(child),
            _folder: folder,
        });
        Helper(())
    }

    /// The program's exit status, if it has ended (without waiting).
    pub fn try_wait(&self) -> io::Result<Option<ExitStatus>> {
        match helper().as_mut().and_then(|r| r.child.as_mut()) {
            Some(child) => child.try_wait(),
            None => Err(io::Error::other("the helper program is gone")),
        }
    }

    /// Everything the program wrote, once it has ended ([`Helper::try_wait`]
    /// said so); its folder stays until this is dropped.
    pub fn output(&self) -> io::Result<Output> {
        let child = helper().as_mut().and_then(|r| r.child.take());
        match child {
            Some(child) => child.wait_with_output(),
            None => Err(io::Error::other("the helper program is gone")),
        }
    }
}

impl Drop for Helper {
    fn drop(&mut self) {
        drop(end_helper());
    }
}
