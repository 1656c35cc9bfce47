//! Where the panes go on a terminal of a given size, worked out one way for
//! the update step (which keeps the areas for clicks and the picture's size)
//! and for drawing (which only reads); and the screen's own state: the areas
//! kept, the right-hand pane of a small terminal, the help. A terminal of 120×36 or more shows all
//! four panes; a smaller one (down to 80×24) shows the image and the tree on
//! the left and, on the right, the numbers or the diagram (`v`).

use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::widgets::{Block, Borders};

/// Which pane a small terminal shows on the right.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Pane {
    /// The selected ray's numbers.
    #[default]
    Details,
    /// The diagram.
    Diagram,
}

/// Where the panes were last laid out, for mouse clicks and the picture's size.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Areas {
    /// The image pane's inside.
    pub image: Rect,
    /// The tree pane's inside.
    pub tree: Rect,
    /// The selected ray's pane, border included.
    pub details: Rect,
}

/// Where the panes were last laid out, which pane a small terminal shows on
/// the right, and the help over them: whether it is open, how far scrolled.
#[derive(Debug, Default)]
pub(super) struct Screen {
    areas: Areas,
    pane: Pane,
    help: bool,
    help_scroll: u16,
}

impl Screen {
    /// Where the panes were last laid out.
    pub fn areas(&self) -> Areas {
        self.areas
    }

    /// Keeps where the panes are.
    pub fn set_areas(&mut self, areas: Areas) {
        self.areas = areas;
    }

    /// What a small terminal shows on the right.
    pub fn pane(&self) -> Pane {
        self.pane
    }

    /// The numbers or the diagram on the right, whichever is not shown.
    pub fn switch_pane(&mut self) {
        self.pane = match self.pane {
            Pane::Details => Pane::Diagram,
            Pane::Diagram => Pane::Details,
        }
    }

    /// Whether the help is open.
    pub fn help_open(&self) -> bool {
        self.help
    }

    /// Lines of the help scrolled past.
    pub fn help_scroll(&self) -> u16 {
        self.help_scroll
    }

    /// Opens the help at its top.
    pub fn open_help(&mut self) {
        self.help = true;
        self.help_scroll = 0;
    }

    /// Closes the help.
    pub fn close_help(&mut self) {
        self.help = false;
    }

    /// Scrolls the help by `by` lines.
    pub fn scroll_help(&mut self, by: i32) {
        self.help_scroll = self.help_scroll.saturating_add_signed(by as i16);
    }
}

/// The whole screen's parts, borders included.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Panes {
    /// The image pane.
    pub image: Rect,
    /// The tree pane.
    pub tree: Rect,
    /// The selected ray's numbers, when shown.
    pub details: Option<Rect>,
    /// The diagram, when shown.
    pub diagram: Option<Rect>,
    /// The guided step-through's lines.
    pub guide: Rect,
    /// The step (or prompt) lines.
    pub step: Rect,
    /// The status line.
    pub status: Rect,
    /// All four panes fit.
    pub wide: bool,
}

impl Panes {
    /// The panes on `area`, with `guide` and `step` lines below them; `pane`
    /// says what a small terminal shows on the right.
    pub fn new(area: Rect, guide: u16, step: u16, pane: Pane) -> Self {
        let [main, guide_area, step_area, status_area] = Layout::vertical([
            Constraint::Min(6),
            Constraint::Length(guide),
            Constraint::Length(step),
            Constraint::Length(1),
        ])
        .areas(area);
        let wide = area.width >= 120 && area.height >= 36;
        let (image, tree, details, diagram) = if wide {
            let [left, right] =
                Layout::horizontal([Constraint::Percentage(50), Constraint::Percentage(50)])
                    .areas(main);
            let [image, diagram] =
                Layout::vertical([Constraint::Percentage(60), Constraint::Percentage(40)])
                    .areas(left);
            let [tree, details] =
                Layout::vertical([Constraint::Percentage(45), Constraint::Percentage(55)])
                    .areas(right);
            (image, tree, Some(details), Some(diagram))
        } else {
            let [left, right] =
                Layout::horizontal([Constraint::Percentage(45), Constraint::Percentage(55)])
                    .areas(main);
            let [image, tree] =
                Layout::vertical([Constraint::Percentage(45), Constraint::Percentage(55)])
                    .areas(left);
            match pane {
                Pane::Details => (image, tree, Some(right), None),
                Pane::Diagram => (image, tree, None, Some(right)),
            }
        };
        Self {
            image,
            tree,
            details,
            diagram,
            guide: guide_area,
            step: step_area,
            status: status_area,
            wide,
        }
    }

    /// The insides of the bordered panes, as clicks and the picture see them.
    pub fn areas(&self) -> Areas {
        let inside = |r: Rect| Block::default().borders(Borders::ALL).inner(r);
        Areas {
            image: inside(self.image),
            tree: inside(self.tree),
            details: self.details.unwrap_or_default(),
        }
    }
}
