//! Terminal colors: whether the terminal takes 24-bit color, and the nearest
//! color of the 256-color palette when it does not.

use glam::DVec3;
use ratatui::style::{Color, Style};
use ratatui::text::Span;

use crate::figure::pen::Rgb;
use crate::io::image::rgb8;

/// Whether to draw in 24-bit color, and if not, a note saying why and how to
/// change it. Asks the environment as terminals announce themselves
/// (`COLORTERM`, `TERM`, known terminal programs) and, inside tmux, tmux
/// itself (its client's `RGB` feature).
pub fn detect() -> (bool, Option<String>) {
    let var = |k: &str| std::env::var(k).unwrap_or_default();
    let colorterm = var("COLORTERM");
    let term = var("TERM");
    let says_so = colorterm.contains("truecolor")
        || colorterm.contains("24bit")
        || ["direct", "truecolor", "24bit"]
            .iter()
            .any(|w| term.contains(w))
        || ["iTerm.app", "WezTerm", "vscode", "ghostty", "Hyper"]
            .contains(&var("TERM_PROGRAM").as_str())
        || [
            "KITTY_WINDOW_ID",
            "WT_SESSION",
            "KONSOLE_VERSION",
            "ALACRITTY_WINDOW_ID",
        ]
        .iter()
        .any(|k| std::env::var_os(k).is_some());
    if says_so || (std::env::var_os("TMUX").is_some() && tmux_has_rgb()) {
        return (true, None);
    }
    (
        false,
        Some(
            "256 colors: no sign of 24-bit color (COLORTERM=truecolor or --color truecolor if the terminal has it)"
                .to_owned(),
        ),
    )
}

/// Whether the tmux client this runs in draws 24-bit color.
fn tmux_has_rgb() -> bool {
    std::process::Command::new("tmux")
        .args(["display-message", "-p", "#{client_termfeatures}"])
        .output()
        .is_ok_and(|o| String::from_utf8_lossy(&o.stdout).contains("RGB"))
}

/// `c` as the terminal draws it: itself in 24-bit color, else the nearest of
/// the 256-color palette's 6×6×6 cube (levels 0, 95, 135, 175, 215, 255) and
/// its 24 grays (8, 18, …, 238).
pub fn term_color(c: Rgb, truecolor: bool) -> Color {
    if truecolor {
        return Color::Rgb(c[0], c[1], c[2]);
    }
    const LEVELS: [i32; 6] = [0, 95, 135, 175, 215, 255];
    let nearest_level = |v: u8| {
        (0..6)
            .min_by_key(|&i| (LEVELS[i] - i32::from(v)).abs())
            .expect("six levels")
    };
    let [r, g, b] = c.map(nearest_level);
    let cube = [LEVELS[r], LEVELS[g], LEVELS[b]];
    let mean = (i32::from(c[0]) + i32::from(c[1]) + i32::from(c[2])) / 3;
    let k = ((mean - 8) / 10).clamp(0, 23);
    let gray = 8 + 10 * k;
    let dist = |p: [i32; 3]| (0..3).map(|i| (p[i] - i32::from(c[i])).pow(2)).sum::<i32>();
    if dist([gray; 3]) < dist(cube) {
        Color::Indexed(232 + k as u8)
    } else {
        Color::Indexed((16 + 36 * r + 6 * g + b) as u8)
    }
}

/// Two cells of a color: a swatch.
pub fn swatch(c: DVec3, tc: bool) -> Span<'static> {
    Span::styled("██", Style::default().fg(term_color(rgb8(c), tc)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_256_color_fallback_picks_the_nearest_entry() {
        // Pure colors and grays map exactly.
        assert_eq!(term_color([255, 0, 0], false), Color::Indexed(196));
        assert_eq!(
            term_color([95, 135, 175], false),
            Color::Indexed(16 + 36 + 12 + 3)
        );
        assert_eq!(term_color([128, 128, 128], false), Color::Indexed(244));
        // The Whitted sky stays blue, not lavender: its nearest is a cube blue.
        assert_eq!(term_color([46, 92, 191], false), Color::Indexed(16 + 6 + 3));
    }
}
