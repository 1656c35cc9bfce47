//! `raytree vectors`: test vectors for a learner's tracer, from a lesson's
//! pixels and rays (lessons 03–11) or a scene's. A lesson without vectors
//! and a `--lessons` that is no lesson folder are usage errors (exit status
//! 2); a scene or a lesson's file that cannot be read or used is bad input
//! (exit status 1), as for every command.

use std::path::{Path, PathBuf};

use anyhow::Result;
use raytree::course::learner::vectors;
use raytree::course::lesson;
use raytree::scene::source;

use crate::args::usage;
use crate::lesson::{held, lessons_in};
use crate::output;

#[derive(clap::Args)]
pub struct Args {
    /// A lesson's number (3 to 11: the cases of the functions it teaches, from its pixels and rays), or a scene file (the cases of every function, from 25 of its pixels).
    #[arg(value_name = "LESSON_OR_SCENE")]
    target: String,
    /// The folder holding the lessons (run from the repository, it is ./lessons).
    #[arg(long, value_name = "DIR", default_value = "lessons")]
    lessons: PathBuf,
    /// Write to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "FILE")]
    output: Option<PathBuf>,
}

pub fn run(args: &Args) -> Result<()> {
    let mut inputs: Vec<PathBuf> = Vec::new();
    let text = match args.target.parse::<u32>() {
        Ok(number) => {
            let functions = vectors::LESSON_FUNCTIONS
                .iter()
                .find(|(n, _)| *n == number)
                .map(|(_, f)| *f)
                .ok_or_else(|| {
                    usage(format_args!(
                        "lesson {number}: vectors exist for lessons 3 to 11"
                    ))
                })?;
            held(
                &args.lessons,
                &lessons_in(&args.lessons, "vectors")?,
                number,
            )?;
            let (name, targets) =
                vectors::lesson_targets(&args.lessons, number).map_err(anyhow::Error::msg)?;
            let folder = args.lessons.join(&name);
            inputs.extend([lesson::SPEC, lesson::TEXT, lesson::STEPS].map(|f| folder.join(f)));
            inputs.extend(scene_files(&targets));
            vectors::document(
                &name,
                &format!("raytree vectors {number}"),
                functions,
                &targets,
            )
        }
        Err(_) => {
            let scene = PathBuf::from(&args.target);
            let all: Vec<&str> = vectors::LESSON_FUNCTIONS
                .iter()
                .flat_map(|(_, f)| f.iter().copied())
                .collect();
            let targets = vectors::scene_targets(&scene).map_err(anyhow::Error::msg)?;
            inputs.extend(scene_files(&targets));
            let made_by = format!("raytree vectors {}", args.target);
            vectors::document(&args.target, &made_by, &all, &targets)
        }
    }
    .map_err(anyhow::Error::msg)?;
    match &args.output {
        Some(path) => {
            let file = output::create(path, &inputs)?;
            file.commit(text.as_bytes())?;
            output::note(&format!("wrote {}", path.display()))?;
        }
        None => output::print(text)?,
    }
    Ok(())
}

/// The files the targets' scenes are read from: each scene and its meshes.
fn scene_files(targets: &[vectors::Target]) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = Vec::new();
    for t in targets {
        if files.contains(&t.scene) {
            continue;
        }
        files.push(t.scene.clone());
        // A scene that does not load fails the command below, with its reason.
        if let Ok((scene, _)) = source::load(Some(Path::new(&t.scene))) {
            files.extend(scene.mesh_files);
        }
    }
    files
}
