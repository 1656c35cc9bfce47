//! What keys, clicks and the mouse wheel do to the inspector's state: a key
//! press is looked up in the key table (`keymap.rs`) and its action done here.

use ratatui::crossterm::event::{KeyCode, KeyEvent, MouseButton, MouseEvent, MouseEventKind};

use super::{App, Focus, Item, Prompt};
use crate::inspector::keymap::{self, Action};
use crate::inspector::layout::Pane;
use crate::inspector::whatif;

impl App {
    /// Handles one key press: the prompt or the help take it while open,
    /// else it is looked up in the key table.
    pub fn on_key(&mut self, key: KeyEvent) {
        // A message answers the key before; the next key clears it.
        self.message.clear();
        if self.prompt.is_some() {
            self.prompt_key(key.code);
            return;
        }
        let action = keymap::action(&key);
        if self.help {
            match action {
                Some(Action::Down) => self.help_scroll += 1,
                Some(Action::ScrollDown) => self.help_scroll += 10,
                Some(Action::Up) => self.help_scroll = self.help_scroll.saturating_sub(1),
                Some(Action::ScrollUp) => self.help_scroll = self.help_scroll.saturating_sub(10),
                // q still quits; any other key (Esc too) closes the help.
                _ if key.code == KeyCode::Char('q') => self.quit = true,
                _ => self.help = false,
            }
            return;
        }
        if let Some(action) = action {
            self.act(action);
        }
    }

    /// Does what a key asks for.
    fn act(&mut self, action: Action) {
        match action {
            Action::Quit => self.quit = true,
            Action::Help => {
                self.help = true;
                self.help_scroll = 0;
            }
            Action::SwitchFocus => {
                self.focus = if self.focus == Focus::Image {
                    Focus::Tree
                } else {
                    Focus::Image
                }
            }
            Action::Next => match self.guide {
                Some(_) => self.stop_by(1),
                None => self.step_by(1),
            },
            Action::Previous => match self.guide {
                Some(_) => self.stop_by(-1),
                None => self.step_by(-1),
            },
            Action::StepForward => self.step_by(1),
            Action::StepBack => self.step_by(-1),
            Action::LeaveStepping => self.stepping.leave(),
            Action::ZoomIn => self.zoom_by(1),
            Action::ZoomOut => self.zoom_by(-1),
            Action::GoTo => self.prompt = Some(Prompt::GoTo(String::new())),
            Action::Edit => self.prompt = Some(Prompt::Edit(String::new())),
            Action::Write => self.prompt = Some(Prompt::Write(whatif::default_name(&self.source))),
            Action::Undo => self.undo_edits(),
            Action::ExpandAll => self.expand_all(),
            Action::NextSample => self.next_sample(),
            Action::Find => self.find(),
            Action::FindOther => {
                self.finding.seek_next();
                self.find();
            }
            Action::Overlay => {
                if let Some(said) = self.finding.next_overlay(self.scene.as_deref()) {
                    self.message = said;
                }
            }
            Action::SwitchPane => {
                self.pane = match self.pane {
                    Pane::Details => Pane::Diagram,
                    Pane::Diagram => Pane::Details,
                }
            }
            Action::ScrollDown => self.scroll_details(10),
            Action::ScrollUp => self.scroll_details(-10),
            Action::FocusTree => self.focus = Focus::Tree,
            Action::FocusImage => self.focus = Focus::Image,
            Action::Left | Action::Right | Action::Up | Action::Down | Action::Enter => {
                match self.focus {
                    Focus::Image => self.image_key(action),
                    Focus::Tree => self.tree_key(action),
                }
            }
        }
    }

    fn prompt_key(&mut self, code: KeyCode) {
        let Some(prompt) = &mut self.prompt else {
            return;
        };
        let text = match prompt {
            Prompt::GoTo(t) | Prompt::Edit(t) | Prompt::Write(t) => t,
        };
        match code {
            KeyCode::Char(c) if !c.is_control() && text.len() < 200 => text.push(c),
            KeyCode::Backspace => {
                text.pop();
            }
            KeyCode::Esc => self.prompt = None,
            KeyCode::Enter => match self.prompt.take() {
                Some(Prompt::GoTo(t)) => self.go_to(&t),
                Some(Prompt::Edit(t)) => self.edit(&t),
                Some(Prompt::Write(t)) => self.message = self.what_if.write(&t),
                None => {}
            },
            _ => {}
        }
    }

    /// The arrows and Enter in the image pane.
    fn image_key(&mut self, action: Action) {
        let step = self.cursor_step();
        let (x, y) = (i64::from(self.cursor.0), i64::from(self.cursor.1));
        let to = match action {
            Action::Left => (x - step, y),
            Action::Right => (x + step, y),
            Action::Up => (x, y - step),
            Action::Down => (x, y + step),
            Action::Enter => {
                self.focus = Focus::Tree;
                return;
            }
            _ => return,
        };
        let (w, h) = self.image_size();
        self.select((
            to.0.clamp(0, i64::from(w) - 1) as u32,
            to.1.clamp(0, i64::from(h) - 1) as u32,
        ));
    }

    /// The arrows and Enter in the tree pane.
    fn tree_key(&mut self, action: Action) {
        let items = self.items();
        let Some(&(item, _)) = items.get(self.selected) else {
            return;
        };
        match action {
            Action::Up => {
                self.selected = self.selected.saturating_sub(1);
                self.detail_scroll = 0;
            }
            Action::Down => {
                self.selected = (self.selected + 1).min(items.len().saturating_sub(1));
                self.detail_scroll = 0;
            }
            Action::Enter | Action::Right => {
                if let Item::Ray(n) = item {
                    self.expanded.insert(n);
                }
            }
            Action::Left => match item {
                Item::Ray(n) if self.expanded.contains(&n) => {
                    self.expanded.remove(&n);
                }
                _ => {
                    // Go to the parent line.
                    let parent = match item {
                        Item::Shadow(n, _) => Some(n),
                        Item::Ray(n) => self
                            .trace
                            .as_ref()
                            .and_then(|t| t.samples[self.sample].tree.nodes[n].parent),
                    };
                    if let Some(p) = parent {
                        self.select_node(p);
                    }
                }
            },
            _ => {}
        }
    }

    /// How far one arrow press moves the cursor: one dot, but at least one pixel.
    fn cursor_step(&self) -> i64 {
        (self.window().scale.round() as i64).max(1)
    }

    /// Handles a mouse event: a left click on the image selects that pixel; on the
    /// tree, that line.
    pub fn on_mouse(&mut self, m: MouseEvent) {
        let at = (m.column, m.row).into();
        let wheel = match m.kind {
            MouseEventKind::ScrollDown => 3,
            MouseEventKind::ScrollUp => -3,
            _ => 0,
        };
        if wheel != 0 {
            if self.help {
                self.help_scroll = self.help_scroll.saturating_add_signed(wheel as i16);
            } else if self.areas.details.contains(at) {
                self.scroll_details(wheel);
            } else if self.areas.tree.contains(at) {
                let last = self.items().len().saturating_sub(1) as i64;
                self.selected = (self.selected as i64 + i64::from(wheel)).clamp(0, last) as usize;
                self.detail_scroll = 0;
            }
            return;
        }
        if m.kind != MouseEventKind::Down(MouseButton::Left) {
            return;
        }
        let (img, tree) = (self.areas.image, self.areas.tree);
        if img.contains((m.column, m.row).into()) {
            let (i, j) = (m.column - img.x, (m.row - img.y) * 2);
            let (w, h) = self.image_size();
            if let Some(p) = self.window().pixel_at(i, j, w, h) {
                self.focus = Focus::Image;
                self.select(p);
            }
        } else if tree.contains((m.column, m.row).into()) {
            self.focus = Focus::Tree;
            let line = usize::from(m.row - tree.y) + self.tree_scroll(tree.height);
            if line < self.items().len() {
                self.selected = line;
            }
        }
    }

    /// The first tree line shown, so the selection stays in view.
    pub fn tree_scroll(&self, height: u16) -> usize {
        self.selected.saturating_sub(usize::from(height.max(1)) - 1)
    }

    /// Goes to the next pixel with what `f` seeks.
    fn find(&mut self) {
        let (found, said) = self.finding.find(self.scene.as_deref(), self.cursor);
        self.message = said;
        if let Some(p) = found {
            self.select(p);
        }
    }

    fn go_to(&mut self, typed: &str) {
        let parsed = typed.split_once(',').and_then(|(x, y)| {
            Some((x.trim().parse::<u32>().ok()?, y.trim().parse::<u32>().ok()?))
        });
        let (w, h) = self.image_size();
        match parsed {
            Some((x, y)) if x < w && y < h => {
                self.message.clear();
                self.select((x, y));
            }
            Some((x, y)) => self.message = format!("pixel {x},{y} is outside the {w}×{h} image"),
            None => self.message = format!("'{typed}' is not a pixel: type x,y (e.g. 320,240)"),
        }
    }
}
