//! Long lines wrapped to a width with a hanging indent: each continuation
//! starts under the text it continues, past the indentation, a step number
//! and a short `name = ` or `name: ` opening, so a reader sees at once that it
//! continues a line. One wrapper for every place a learner reads a trace: the
//! inspector's panes (with their styles) and the book's code blocks.

/// `cells` (a character and whatever rides with it, such as a style) broken
/// into rows of at most `width`, at spaces where it can; every row after the
/// first starts with `indent` copies of `blank`. A space a row breaks at is
/// dropped, and `indent` is held to half the width so every row has room.
pub fn rows<T: Clone>(
    cells: &[(char, T)],
    width: usize,
    indent: usize,
    blank: T,
) -> Vec<Vec<(char, T)>> {
    let width = width.max(8);
    if cells.len() <= width {
        return vec![cells.to_vec()];
    }
    let indent = indent.min(width / 2);
    let mut out = Vec::new();
    let mut rest = cells;
    let mut first = true;
    while !rest.is_empty() {
        let room = if first { width } else { width - indent };
        let mut take = rest.len().min(room);
        if take < rest.len()
            && let Some(space) = rest[..take].iter().rposition(|c| c.0 == ' ')
            && space > room / 3
        {
            take = space + 1;
        }
        let mut row: Vec<(char, T)> = Vec::new();
        if !first {
            row.extend(std::iter::repeat_n((' ', blank.clone()), indent));
        }
        row.extend_from_slice(&rest[..take]);
        out.push(row);
        rest = &rest[take..];
        while rest.first().is_some_and(|c| c.0 == ' ') {
            rest = &rest[1..];
        }
        first = false;
    }
    out
}

/// Where a continuation of `text` starts: past its indentation and a step
/// number (`  12. `, as `raytree trace --steps` numbers steps), then past the
/// first `name = ` or `name: ` opening with a short name, or else two columns
/// in.
pub fn hang(text: &str) -> usize {
    let chars: Vec<char> = text.chars().collect();
    let mut lead = chars.iter().take_while(|c| **c == ' ').count();
    let digits = chars[lead..]
        .iter()
        .take_while(|c| c.is_ascii_digit())
        .count();
    if digits > 0
        && chars.get(lead + digits) == Some(&'.')
        && chars.get(lead + digits + 1) == Some(&' ')
    {
        lead += digits + 1;
        lead += chars[lead..].iter().take_while(|c| **c == ' ').count();
    }
    let body: String = chars[lead..].iter().collect();
    // The first opening, so `Snell: n₁ sin θ₁ = …` continues under `n₁`.
    [" = ", ": "]
        .iter()
        .filter_map(|sep| Some((body.find(sep)?, sep.len())))
        .filter(|(i, _)| body[..*i].chars().count() < 24)
        .min()
        .map_or(lead + 2, |(i, sep)| lead + body[..i].chars().count() + sep)
}

/// `line` wrapped to `width` columns (characters) with its [`hang`]; rows
/// lose the spaces they break at, so none ends in a space.
pub fn line(line: &str, width: usize) -> Vec<String> {
    let cells: Vec<(char, ())> = line.chars().map(|c| (c, ())).collect();
    rows(&cells, width, hang(line), ())
        .into_iter()
        .map(|r| {
            r.into_iter()
                .map(|(c, _)| c)
                .collect::<String>()
                .trim_end()
                .to_owned()
        })
        .collect()
}

/// Every line of `text` wrapped to `width`, the line ends kept.
pub fn text(text: &str, width: usize) -> String {
    let mut out = String::new();
    for l in text.split_inclusive('\n') {
        let (body, end) = match l.strip_suffix('\n') {
            Some(b) => (b, "\n"),
            None => (l, ""),
        };
        out.push_str(&line(body, width).join("\n"));
        out.push_str(end);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_step_line_continues_under_its_text_and_keeps_every_character() {
        let step = "  17.   color = local (0, 0, 0) + 1 × reflected (0.3333, 0.3333, 0.3333) + 0 × refracted (0, 0, 0) = (0.3333, 0.3333, 0.3333)";
        let rows = line(step, 60);
        assert!(rows.len() > 1, "{rows:?}");
        for r in &rows {
            assert!(r.chars().count() <= 60, "{r:?}");
        }
        // Under `local`, past "  17.   color = ": deeper than the step's text.
        for r in &rows[1..] {
            assert!(
                r.starts_with(&" ".repeat(16)) && !r.starts_with(&" ".repeat(17)),
                "{r:?}"
            );
        }
        let joined: Vec<&str> = rows.iter().map(|r| r.trim()).collect();
        assert_eq!(joined.join(" "), step.trim());
    }

    #[test]
    fn the_hang_skips_indentation_and_step_numbers() {
        assert_eq!(hang("            ambient = k_a·color"), 22);
        assert_eq!(hang(" 105.   closest hit: 'floor' at t = 4.599"), 21);
        assert_eq!(hang("    plain words without an opening"), 6);
        assert_eq!(hang("  Snell: n₁ sin θ₁ = n₂ sin θ₂"), 9);
        // A number that is no step number (no ". " after it) is text.
        assert_eq!(hang("3.5 is a number, not a step"), 2);
    }

    #[test]
    fn short_lines_and_line_ends_are_kept() {
        assert_eq!(text("a\n\nb c\n", 90), "a\n\nb c\n");
        assert_eq!(text("x", 90), "x");
        let long = format!("{}\n", "word ".repeat(30).trim_end());
        let wrapped = text(&long, 40);
        assert!(wrapped.ends_with('\n') && wrapped.lines().all(|l| l.chars().count() <= 40));
    }
}
