//! An NFF file as the reader walks it: lines of words (a `#` starts a
//! comment), each word with its column, and every number read strictly,
//! finite and within [`crate::scene::limits`], an error naming the file, the
//! line and the column.

use glam::DVec3;

use crate::io::image::srgb_to_linear;
use crate::scene::limits;
use crate::scene::quote::{printable, quote};
use crate::scene::scene_error::SceneError;

/// The words that begin a line of an NFF file: the entities' keywords and
/// the view's lines.
const KEYWORDS: [&str; 14] = [
    "v",
    "b",
    "l",
    "f",
    "s",
    "c",
    "p",
    "pp",
    "from",
    "at",
    "up",
    "angle",
    "hither",
    "resolution",
];

/// A line of the file: its number and its words with their columns.
pub(super) struct Line<'t> {
    pub(super) number: usize,
    pub(super) words: Vec<(usize, &'t str)>,
}

/// The reader of one NFF file: the lines still to read, and the file's name
/// for errors.
pub(super) struct Reader<'t> {
    file: &'t str,
    lines: Box<dyn Iterator<Item = Line<'t>> + 't>,
    /// The line the file ended after, for "ends early" errors.
    last: usize,
}

impl<'t> Reader<'t> {
    /// The reader of `text`, the NFF file named `file`; its lines without a
    /// word are skipped.
    pub(super) fn new(text: &'t str, file: &'t str) -> Self {
        let lines = text.lines().enumerate().filter_map(|(i, line)| {
            let line = line.split('#').next().unwrap_or("");
            let mut words = Vec::new();
            let mut column = 1;
            for piece in line.split_inclusive(char::is_whitespace) {
                let word = piece.trim_end();
                if !word.is_empty() {
                    words.push((column, word));
                }
                column += piece.chars().count();
            }
            (!words.is_empty()).then_some(Line {
                number: i + 1,
                words,
            })
        });
        let last = text.lines().count();
        Reader {
            file,
            lines: Box::new(lines),
            last,
        }
    }

    pub(super) fn error(
        &self,
        line: usize,
        column: usize,
        message: impl Into<String>,
    ) -> SceneError {
        SceneError::Syntax {
            file: self.file.to_owned(),
            line,
            column,
            message: printable(&message.into()),
        }
    }

    /// An error at the end of the file: what the whole file lacks.
    pub(super) fn at_end(&self, message: impl Into<String>) -> SceneError {
        self.error(self.last.max(1), 1, message)
    }

    /// The next line that holds a word, if any.
    pub(super) fn next_line(&mut self) -> Option<Line<'t>> {
        self.lines.next()
    }

    /// The next line, which entity `what` (begun on line `from`) needs.
    pub(super) fn next_for(&mut self, what: &str, from: usize) -> Result<Line<'t>, SceneError> {
        self.lines.next().ok_or_else(|| {
            self.at_end(format!(
                "the file ends inside the {what} begun on line {from}"
            ))
        })
    }

    /// Checks that `line` holds its keyword and `n` more words.
    pub(super) fn count(&self, line: &Line, n: usize) -> Result<(), SceneError> {
        let (column, keyword) = line.words[0];
        let got = line.words.len() - 1;
        if got != n {
            let what = match n {
                0 => "nothing".to_owned(),
                1 => "1 number".to_owned(),
                n => format!("{n} numbers"),
            };
            return Err(self.error(
                line.number,
                column,
                format!("'{keyword}' takes {what} after it, got {got}"),
            ));
        }
        Ok(())
    }

    /// The `N` numbers after `line`'s keyword: finite, and exactly `N`.
    pub(super) fn numbers<const N: usize>(&self, line: &Line) -> Result<[f64; N], SceneError> {
        self.count(line, N)?;
        self.numbers_from(line, 1)
    }

    /// `N` finite numbers of `line` from word `first` on (the words must be there).
    pub(super) fn numbers_from<const N: usize>(
        &self,
        line: &Line,
        first: usize,
    ) -> Result<[f64; N], SceneError> {
        let mut out = [0.0; N];
        for (k, value) in out.iter_mut().enumerate() {
            let (column, word) = line.words[first + k];
            *value = match word.parse::<f64>() {
                Ok(x) if x.is_finite() => x,
                Ok(_) => {
                    return Err(self.error(
                        line.number,
                        column,
                        format!("{} is not a finite number", quote(word, "'")),
                    ));
                }
                Err(_) => {
                    return Err(self.error(
                        line.number,
                        column,
                        format!("{} is not a number", quote(word, "'")),
                    ));
                }
            };
        }
        Ok(out)
    }

    /// The three numbers of words `first..first + 3` of `line`, within the
    /// limits of a point; `what` they are (a vertex, a normal) names them.
    pub(super) fn point(&self, line: &Line, first: usize, what: &str) -> Result<DVec3, SceneError> {
        let [x, y, z] = self.numbers_from(line, first)?;
        limits::point(DVec3::new(x, y, z))
            .map_err(|e| self.error(line.number, line.words[first].0, format!("{what}: {e}")))
    }

    /// Checks that `line`, which must hold `what` (an end of a cone, a
    /// vertex), holds `n` numbers: a keyword there means the entity before
    /// it was cut short, and says so.
    pub(super) fn expect_numbers(
        &self,
        line: &Line,
        n: usize,
        what: &str,
    ) -> Result<(), SceneError> {
        let (column, first) = line.words[0];
        if KEYWORDS.contains(&first) {
            return Err(self.error(
                line.number,
                column,
                format!("expected {what}, found the keyword '{first}'"),
            ));
        }
        if line.words.len() != n {
            return Err(self.error(
                line.number,
                column,
                format!(
                    "{what} takes {n} numbers, got {} (a wrong count?)",
                    line.words.len()
                ),
            ));
        }
        Ok(())
    }

    /// A color as NFF gives it, for a display (sRGB), checked and made linear;
    /// an error names word `first`, its R, where the color begins on the line
    /// (a light's `l X Y Z R G B` puts it after the position).
    pub(super) fn color(&self, line: &Line, first: usize, c: DVec3) -> Result<DVec3, SceneError> {
        let c = limits::color(c)
            .map_err(|e| self.error(line.number, line.words[first].0, format!("a color: {e}")))?;
        Ok(DVec3::new(
            srgb_to_linear(c.x),
            srgb_to_linear(c.y),
            srgb_to_linear(c.z),
        ))
    }
}
