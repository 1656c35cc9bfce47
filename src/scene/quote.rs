//! The user's own words quoted in an error: printable, so a message stays one
//! line and never instructs the terminal, and short, so a key, a name or a
//! word of ten million characters gives a line a person can read, not ten
//! megabytes on stderr. Every reader quotes through here: the NFF and OBJ
//! readers, the scene and trace documents' messages (serde's among them),
//! the learner trace's.

/// Most characters of one token an error quotes: enough to recognise a key
/// or a name, a line's worth at most.
pub const MAX_QUOTED: usize = 60;

/// `text` with its control characters escaped (`\u{1b}`, `\n`): a message
/// quoting a key or a name stays one line and never instructs the terminal.
pub fn printable(text: &str) -> String {
    text.chars().map(shown).collect()
}

/// One character as a message shows it.
fn shown(c: char) -> String {
    match c.is_control() {
        true => c.escape_default().to_string(),
        false => c.to_string(),
    }
}

/// `token` between two `mark`s (`'`, `` ` ``, or none), printable; one
/// longer than [`MAX_QUOTED`] characters is cut there with `…`, and its
/// length follows the closing mark: `'xxx…' (10000000 characters)`.
pub fn quote(token: &str, mark: &str) -> String {
    let mut shown_chars = token.chars().map(shown);
    let head: String = shown_chars.by_ref().take(MAX_QUOTED).collect();
    if shown_chars.next().is_none() {
        return format!("{mark}{head}{mark}");
    }
    let n = token.chars().count();
    format!("{mark}{head}…{mark} ({n} characters)")
}

/// serde's `message` with the token from the input it quotes cut as
/// [`quote`] cuts it: the key of `unknown field`, the name of `unknown
/// variant`, and a `string "…"` (which serde writes escaped, as Rust
/// would). The rest of the message is serde's own, and short.
pub fn shorten_serde(message: &str) -> String {
    for (open, ends) in [
        (
            "unknown field `",
            ["`, expected ", "`, there are no fields"],
        ),
        (
            "unknown variant `",
            ["`, expected ", "`, there are no variants"],
        ),
    ] {
        let Some(start) = message.find(open).map(|i| i + open.len()) else {
            continue;
        };
        // The token may hold anything, a backtick too: serde's own words are
        // the last of their kind in the message.
        let Some(end) = ends
            .iter()
            .filter_map(|e| message[start..].rfind(e))
            .max()
            .map(|i| start + i)
        else {
            continue;
        };
        let token = quote(&message[start..end], "`");
        return format!("{}{token}{}", &message[..start - 1], &message[end + 1..]);
    }
    const STRING: &str = "string \"";
    if let Some(start) = message.find(STRING).map(|i| i + STRING.len()) {
        let (n, cut, end) = escaped(&message[start..]);
        if let Some(cut) = cut {
            let after = message.get(start + end + 1..).unwrap_or("");
            return format!("{}…\" ({n} characters){after}", &message[..start + cut]);
        }
    }
    message.to_owned()
}

/// A Rust-escaped string (`\"`, `\\`, `\u{1b}`) up to its closing quote: how
/// many characters it holds, where the one past [`MAX_QUOTED`] starts if it
/// holds more, and where the closing quote is.
fn escaped(text: &str) -> (usize, Option<usize>, usize) {
    let (mut n, mut cut) = (0, None);
    let mut chars = text.char_indices();
    while let Some((i, c)) = chars.next() {
        if c == '"' {
            return (n, cut, i);
        }
        if n == MAX_QUOTED {
            cut = Some(i);
        }
        if c == '\\' && chars.next().is_some_and(|(_, e)| e == 'u') {
            chars.by_ref().find(|&(_, c)| c == '}');
        }
        n += 1;
    }
    (n, cut, text.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_token_is_cut_with_its_length() {
        assert_eq!(quote("radius", "'"), "'radius'");
        assert_eq!(quote("a\u{1b}[2J", "`"), "`a\\u{1b}[2J`");
        let long = "k".repeat(10_000_000);
        let cut = format!("'{}…' (10000000 characters)", "k".repeat(MAX_QUOTED));
        assert_eq!(quote(&long, "'"), cut);
        // Exactly the limit is not cut.
        let full = "é".repeat(MAX_QUOTED);
        assert_eq!(quote(&full, ""), full);
    }

    #[test]
    fn serdes_quoted_tokens_are_cut() {
        let key = format!("a`, expected b{}", "k".repeat(100));
        let m = format!("unknown field `{key}`, expected `center` or `radius`");
        assert_eq!(
            shorten_serde(&m),
            format!(
                "unknown field `{}…` (114 characters), expected `center` or `radius`",
                &key[..MAX_QUOTED]
            )
        );
        let m = format!(
            "unknown variant `{}`, there are no variants",
            "v".repeat(61)
        );
        assert_eq!(
            shorten_serde(&m),
            format!(
                "unknown variant `{}…` (61 characters), there are no variants",
                "v".repeat(60)
            )
        );
        // serde escapes a string as Rust does: an escape is one character.
        let s = format!("{:?}", format!("\"\u{1b}{}", "s".repeat(70)));
        let m = format!("invalid type: string {s}, expected a number");
        assert_eq!(
            shorten_serde(&m),
            format!(
                "invalid type: string \"\\\"\\u{{1b}}{}…\" (72 characters), expected a number",
                "s".repeat(58)
            )
        );
        let short = "unknown field `radus`, expected `center` or `radius`";
        assert_eq!(shorten_serde(short), short);
        assert_eq!(
            shorten_serde("invalid type: string \"x\", expected a number"),
            "invalid type: string \"x\", expected a number"
        );
    }
}
