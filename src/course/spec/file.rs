//! A spec file's TOML as serde reads it, before [`crate::course::spec`]
//! checks it: every table and field with its span, so an error can name the
//! line.

use std::collections::BTreeMap;

use serde::Deserialize;
use toml::Spanned;

use crate::course::spec::frame::Minutes;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct SpecFile {
    pub(crate) title: Option<String>,
    pub(crate) summary: Option<String>,
    pub(crate) objectives: Option<Spanned<Vec<String>>>,
    pub(crate) minutes: Option<Spanned<Minutes>>,
    pub(crate) beyond_lecture: Option<bool>,
    #[serde(default)]
    pub(crate) run: BTreeMap<String, Spanned<RunFile>>,
    #[serde(default)]
    pub(crate) figure: BTreeMap<String, Spanned<FigureFile>>,
    #[serde(default)]
    pub(crate) image: BTreeMap<String, Spanned<RunFile>>,
    #[serde(default)]
    pub(crate) excerpt: BTreeMap<String, Spanned<ExcerptFile>>,
    #[serde(default)]
    pub(crate) number: BTreeMap<String, Spanned<NumberFile>>,
    #[serde(default)]
    pub(crate) exercise: Vec<Spanned<ExerciseFile>>,
    #[serde(default)]
    pub(crate) question: Vec<Spanned<crate::course::spec::question::QuestionFile>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RunFile {
    pub(crate) command: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct FigureFile {
    pub(crate) command: String,
    pub(crate) caption: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct ExcerptFile {
    pub(crate) run: String,
    pub(crate) steps: Option<[usize; 2]>,
    pub(crate) lines: Option<[usize; 2]>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct NumberFile {
    pub(crate) run: String,
    pub(crate) step: Option<usize>,
    pub(crate) value: Option<String>,
    pub(crate) json: Option<String>,
    pub(crate) after: Option<String>,
    pub(crate) before: Option<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct ExerciseFile {
    pub(crate) task: String,
    pub(crate) answer: String,
}
