//! `raytree convert`: an NFF scene (the Standard Procedural Databases' format)
//! written as raytree's scene JSON, the very text `render` reads the NFF file
//! through, so a learner can open it, read it and change it.

use std::path::PathBuf;

use anyhow::Result;
use raytree::scene::{loader, nff};

use crate::args::usage;
use crate::output;

#[derive(clap::Args)]
pub struct Args {
    /// The NFF scene file to read (.nff).
    pub input: PathBuf,
    /// The scene JSON to write [default: the input's name with .json, in the current folder].
    #[arg(short, long, value_name = "OUT.json")]
    pub output: Option<PathBuf>,
}

pub fn run(args: &Args) -> Result<()> {
    let name = args.input.display().to_string();
    if !nff::is_nff(&name) {
        return Err(usage(format_args!(
            "cannot convert {name}: raytree converts NFF files (.nff) to scene JSON; a .json scene is already one"
        )));
    }
    let path = output::name_or(&args.output, || {
        output::stem_and(args.input.file_stem().unwrap_or("scene".as_ref()), ".json")
    });
    if !output::has_extension(&path, "json") {
        return Err(usage(format_args!(
            "cannot write {}: a scene is written as a .json file",
            path.display()
        )));
    }
    let json = nff::to_json(&loader::read(&args.input)?, &name)?;
    // Read back as any scene file is: what is written must load.
    let scene = loader::parse(&json, &path.display().to_string())?;
    let pending = output::create(&path, std::slice::from_ref(&args.input))?;
    pending.commit(json.as_bytes())?;
    output::note(&format!(
        "wrote {} ({} objects, {} materials, {} lights)",
        path.display(),
        scene.objects.len(),
        scene.materials.len(),
        scene.lights.len()
    ))?;
    Ok(())
}
