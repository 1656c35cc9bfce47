//! `raytree lesson`: the lessons, and one lesson's guided step-through.

use std::path::PathBuf;

use anyhow::{Result, anyhow};
use raytree::views::lesson;

use crate::output;

#[derive(clap::Args)]
pub struct Args {
    /// The lesson to step through (its number); without one, list the lessons.
    #[arg(value_name = "N")]
    number: Option<u32>,
    /// The folder holding the lessons (run from the repository, it is ./lessons).
    #[arg(long, value_name = "DIR", default_value = "lessons")]
    lessons: PathBuf,
}

pub fn run(args: &Args) -> Result<()> {
    if !args.lessons.is_dir() {
        return Err(anyhow!(
            "{}: no such folder; run raytree lesson from the repository, or give --lessons DIR",
            args.lessons.display()
        ));
    }
    let text = match args.number {
        None => {
            let entries = lesson::list(&args.lessons).map_err(anyhow::Error::msg)?;
            format!(
                "{}\n`raytree lesson N` steps through lesson N; the book (book/) has their text.\n",
                lesson::list_text(&entries).trim_end()
            )
        }
        Some(n) => {
            let loaded = lesson::load(&args.lessons, n).map_err(anyhow::Error::msg)?;
            let walk = lesson::step_through(&loaded).map_err(anyhow::Error::msg)?;
            lesson::step_through_text(&loaded, &walk)
        }
    };
    output::write_stdout(text.as_bytes())
}
