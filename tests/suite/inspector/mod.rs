//! The inspector: its state and keys without a terminal, what stepping
//! reveals, and the real binary driven in tmux.

mod keys;
mod state;
mod teaching;
pub mod tmux;
