//! Lines fitted to a pane: cut with a marker (…) where a line does not fit,
//! or wrapped with the continuation aligned under the text it continues (the
//! wrapping itself is [`crate::views::wrap`], shared with the book), so
//! nothing is lost silently at any terminal size.

use ratatui::style::Style;
use ratatui::text::{Line, Span};

use crate::views::wrap;

/// The marker at the end of a cut line.
pub const CUT: &str = "…";

/// `line` cut to `width` columns, ending in [`CUT`] if anything was cut.
pub fn cut(line: Line<'static>, width: usize) -> Line<'static> {
    let cells = cells(&line);
    if cells.len() <= width {
        return line;
    }
    let mut kept: Vec<(char, Style)> = cells.into_iter().take(width.saturating_sub(1)).collect();
    kept.extend(CUT.chars().map(|c| (c, Style::default())));
    join(kept, line.style)
}

/// `lines` wrapped to `width` columns by [`crate::views::wrap`]: breaks at
/// spaces where it can; each continuation starts under the first text after
/// the line's indentation and label (a bold label padded with spaces counts
/// as the label).
pub fn wrap(lines: Vec<Line<'static>>, width: usize) -> Vec<Line<'static>> {
    let mut out = Vec::new();
    for line in lines {
        let cells = cells(&line);
        let indent = hang(&line, &cells);
        for row in wrap::rows(&cells, width, indent, Style::default()) {
            out.push(join(row, line.style));
        }
    }
    out
}

/// Where a line's continuation starts: after a padded label, or where
/// [`wrap::hang`] puts it in the line's text.
fn hang(line: &Line<'static>, cells: &[(char, Style)]) -> usize {
    if line.spans.len() > 1 && line.spans[0].content.ends_with("  ") {
        return line.spans[0].content.chars().count();
    }
    let text: String = cells.iter().map(|c| c.0).collect();
    wrap::hang(&text)
}

fn cells(line: &Line<'static>) -> Vec<(char, Style)> {
    line.spans
        .iter()
        .flat_map(|s| s.content.chars().map(move |c| (c, s.style)))
        .collect()
}

fn join(cells: Vec<(char, Style)>, style: Style) -> Line<'static> {
    let mut spans: Vec<Span<'static>> = Vec::new();
    for (c, st) in cells {
        match spans.last_mut() {
            Some(last) if last.style == st => last.content.to_mut().push(c),
            _ => spans.push(Span::styled(c.to_string(), st)),
        }
    }
    Line::from(spans).style(style)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text(l: &Line) -> String {
        l.spans.iter().map(|s| s.content.as_ref()).collect()
    }

    #[test]
    fn a_cut_line_says_so() {
        let l = cut(Line::from("abcdefghij"), 6);
        assert_eq!(text(&l), "abcde…");
        assert_eq!(text(&cut(Line::from("abc"), 6)), "abc");
    }

    #[test]
    fn wrapped_lines_keep_every_character_and_align_under_the_value() {
        let line = Line::from("color = local (0.1, 0.2, 0.3) + 0.1 × reflected (0.4, 0.5, 0.6)");
        let rows = wrap(vec![line.clone()], 30);
        assert!(rows.len() > 1);
        for r in &rows {
            assert!(text(r).chars().count() <= 30, "{:?}", text(r));
        }
        for r in &rows[1..] {
            assert!(text(r).starts_with(&" ".repeat(8)), "{:?}", text(r));
        }
        let joined: String = rows
            .iter()
            .map(|r| text(r).trim().to_owned())
            .collect::<Vec<_>>()
            .join(" ");
        assert_eq!(joined, text(&line));
    }
}
