//! The lecture's last slide is a ray tracer in a page of PostScript (Takashi
//! Hayakawa's, from the 1993 Obfuscated PostScript Contest). The lecture's
//! copy of it was transcribed from the slide, and nine characters came out
//! wrong, so it does not run as printed. This module finds the program in a
//! Markdown file (or takes a PostScript file as it is) and repairs those
//! slips, each named with the reason it must be one, so that Ghostscript can
//! draw it beside raytree's twin of its scene (lesson 14).
//!
//! The program is never copied into raytree: it is read from the lecture at
//! run time. The slips below hold a few characters each, around the mistake.

/// A transcription slip: what the lecture's copy has, what the program needs
/// there, and why it cannot be anything else.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Slip {
    /// The characters as the copy has them (unique in the program).
    pub found: &'static str,
    /// The characters the program needs.
    pub meant: &'static str,
    /// The reason, from what the program does there.
    pub why: &'static str,
}

/// The slips of the lecture's copy, worked out by decoding the program (its
/// one-letter names stand for PostScript operators and for procedures kept in
/// strings, one character per word): each is the one reading under which the
/// program runs and every procedure leaves the stack as its callers expect.
pub const SLIPS: &[Slip] = &[
    Slip {
        found: "iffelse",
        meant: "ifelse",
        why: "J is bound to an operator by its name, and PostScript's two-way branch is ifelse",
    },
    Slip {
        found: "(T(9)q{cvn}{s}J)",
        meant: "{T(9)q{cvn}{s}J}",
        why: "the decoder's branch for letters and digits is run by ifelse, so it is a procedure in braces, not a string",
    },
    Slip {
        found: "{[{}]}",
        meant: "{[}{]}",
        why: "the decoder's other branch turns & into [ and ! into ], two procedures for one ifelse",
    },
    Slip {
        found: "/z(blx",
        meant: "/Z(blx",
        why: "z is defined twice, so the highlight procedure that the shading calls as Z would not exist",
    },
    Slip {
        found: "jlid",
        meant: "j1id",
        why: "c scales a vector and fetches the factor with 1 index; the letter l would run the light direction instead",
    },
    Slip {
        found: "4Iwxca",
        meant: "4Ixwca",
        why: "on the floor the distance along the ray is one dot product divided by another (x, then w)",
    },
    Slip {
        found: "&v1x",
        meant: "&vlx",
        why: "the sky's brightness is the ray's dot product with the light direction l, not with the number 1",
    },
    Slip {
        found: "Z4ws!",
        meant: "Z4wS!",
        why: "a quarter of the sun's glow is added to the sky (S is add); s (cvi) would drop the sky's own brightness",
    },
    Slip {
        found: "EYEO!",
        meant: "EYEY0!",
        why: "a ray that misses a sphere drops the eight numbers of the test and answers 0: the copy lost a pop (Y) and read 0 as O",
    },
];

/// The PostScript program in `text`: all of it when it starts with `%!`,
/// else the first fenced code block of a Markdown file whose first line does.
pub fn program(text: &str) -> Option<&str> {
    if text.starts_with("%!") {
        return Some(text);
    }
    let mut fenced = false;
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        let start = offset;
        offset += line.len();
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced && line.starts_with("%!") {
            let rest = &text[start..];
            let end = rest
                .split_inclusive('\n')
                .scan(0, |at, l| {
                    let here = *at;
                    *at += l.len();
                    Some((here, l))
                })
                .find(|(_, l)| l.trim_start().starts_with("```"))
                .map_or(rest.len(), |(at, _)| at);
            return Some(&rest[..end]);
        }
    }
    None
}

/// `program` with every slip it holds repaired, and the slips repaired. A
/// slip is repaired where its characters occur exactly once; a program
/// without them (another copy, or one already right) is left as it is.
pub fn repair(program: &str) -> (String, Vec<Slip>) {
    let mut out = program.to_owned();
    let mut repaired = Vec::new();
    for slip in SLIPS {
        if out.matches(slip.found).count() == 1 {
            out = out.replacen(slip.found, slip.meant, 1);
            repaired.push(*slip);
        }
    }
    (out, repaired)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_program_is_the_fenced_block_that_starts_with_the_postscript_mark() {
        let md =
            "# Slides\n\n```\nraytrace(ray)\n```\n\ntext\n\n```\n%! tiny\n1 2 add\n```\nafter\n";
        assert_eq!(program(md), Some("%! tiny\n1 2 add\n"));
        // A file that is PostScript is the program; a file without one has none.
        assert_eq!(program("%!PS\nshowpage\n"), Some("%!PS\nshowpage\n"));
        assert_eq!(program("# no program\n```\ncode\n```\n"), None);
        // Unclosed: to the end of the file.
        assert_eq!(program("```\n%! a\nb"), Some("%! a\nb"));
    }

    #[test]
    fn each_slip_is_repaired_once_where_it_is_found() {
        let (fixed, done) = repair("%! /J/iffelse x(jlidj) /z(blxC)/z(&9)");
        assert_eq!(fixed, "%! /J/ifelse x(j1idj) /Z(blxC)/z(&9)");
        let names: Vec<&str> = done.iter().map(|s| s.found).collect();
        assert_eq!(names, ["iffelse", "/z(blx", "jlid"]);
        // Already right, or ambiguous: left alone.
        let (same, none) = repair("%! /J/ifelse jlid jlid");
        assert_eq!((same.as_str(), none.len()), ("%! /J/ifelse jlid jlid", 0));
    }

    #[test]
    fn every_slip_changes_a_few_characters_and_says_why() {
        for s in SLIPS {
            assert!(s.found != s.meant && s.found.len() <= 16 && !s.why.is_empty());
            // Repairing twice changes nothing more: no meant text holds a found one.
            assert!(SLIPS.iter().all(|t| !s.meant.contains(t.found)), "{s:?}");
        }
    }
}
