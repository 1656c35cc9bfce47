//! The inspector: its state and keys without a terminal, what stepping
//! reveals, the real binary driven in tmux, and its work per key.

mod drive;
mod keys;
mod review;
mod state;
mod teaching;
pub mod tmux;
mod work;
