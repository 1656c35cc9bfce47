//! What keys, clicks and the mouse wheel do to the inspector's state: a key
//! press is looked up in the key table (`keymap.rs`) and its action done here.

use ratatui::crossterm::event::{KeyCode, KeyEvent, MouseButton, MouseEvent, MouseEventKind};

use super::{App, Prompt};
use crate::inspector::keymap::{self, Action};
use crate::inspector::state::selection::{Focus, Item};
use crate::inspector::state::whatif;

impl App {
    /// Handles one key press: the prompt or the help take it while open,
    /// else it is looked up in the key table.
    pub fn on_key(&mut self, key: KeyEvent) {
        // A message answers the key before; the next key clears it.
        self.message.clear();
        let quit_asked = std::mem::take(&mut self.quit_asked);
        if self.prompt.is_some() {
            self.prompt_key(key.code);
            return;
        }
        let action = keymap::action(&key);
        if self.screen.help_open() {
            match action {
                Some(Action::Down) => self.screen.scroll_help(1),
                Some(Action::ScrollDown) => self.screen.scroll_help(10),
                Some(Action::Up) => self.screen.scroll_help(-1),
                Some(Action::ScrollUp) => self.screen.scroll_help(-10),
                // Esc closes the help, as it closes a prompt; the other
                // quit keys (q, Ctrl-C) still quit; any other key closes it.
                Some(Action::Quit) if key.code != KeyCode::Esc => self.ask_quit(quit_asked),
                _ => self.screen.close_help(),
            }
            return;
        }
        if let Some(action) = action {
            self.act(action, quit_asked);
        }
    }

    /// Quits, unless what-if edits no file holds would be lost: then the
    /// first press asks, and a second one right after quits.
    fn ask_quit(&mut self, asked: bool) {
        if asked || !self.what_if.unsaved() {
            self.quit = true;
            return;
        }
        self.quit_asked = true;
        self.message =
            "the what-if edits are not saved: q again quits without them (w writes them)"
                .to_owned();
    }

    /// Does what a key asks for; `quit_asked`: the key before asked to quit.
    fn act(&mut self, action: Action, quit_asked: bool) {
        match action {
            Action::Quit => self.ask_quit(quit_asked),
            Action::Help => self.screen.open_help(),
            Action::SwitchFocus => self.selection.set_focus(match self.focus() {
                Focus::Image => Focus::Tree,
                Focus::Tree => Focus::Image,
            }),
            // Away from the guide's pixel, its stops are of another pixel.
            Action::Next if self.guided_here() => self.stop_by(1),
            Action::Next => self.step_by(1),
            Action::Previous if self.guided_here() => self.stop_by(-1),
            Action::Previous => self.step_by(-1),
            Action::StepForward => self.step_by(1),
            Action::StepBack => self.step_by(-1),
            Action::LeaveStepping => self.stepping.leave(),
            Action::ZoomIn => self.zoom_by(1),
            Action::ZoomOut => self.zoom_by(-1),
            Action::GoTo => self.prompt = Some(Prompt::GoTo(String::new())),
            Action::Edit => self.prompt = Some(Prompt::Edit(String::new())),
            Action::Write if self.what_if.edits().is_empty() => {
                self.message =
                    "no what-if edits to write: m edits the selected hit's material".to_owned();
            }
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
                if let Some(said) = self.finding.next_overlay(self.scene.as_ref()) {
                    self.message = said;
                }
            }
            Action::SwitchPane => self.screen.switch_pane(),
            Action::ScrollDown => self.selection.scroll_by(10),
            Action::ScrollUp => self.selection.scroll_by(-10),
            Action::FocusTree => self.selection.set_focus(Focus::Tree),
            Action::FocusImage => self.selection.set_focus(Focus::Image),
            Action::Left | Action::Right | Action::Up | Action::Down | Action::Enter => {
                match self.focus() {
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
                Some(Prompt::Write(t)) => match self.what_if.write(&self.source, &t) {
                    Ok(said) => self.message = said,
                    Err(e) => {
                        self.message = e;
                        self.prompt = Some(Prompt::Write(t));
                    }
                },
                None => {}
            },
            _ => {}
        }
    }

    /// The arrows and Enter in the image pane.
    fn image_key(&mut self, action: Action) {
        let step = self.cursor_step();
        let (x, y) = self.cursor();
        let (x, y) = (i64::from(x), i64::from(y));
        let to = match action {
            Action::Left => (x - step, y),
            Action::Right => (x + step, y),
            Action::Up => (x, y - step),
            Action::Down => (x, y + step),
            Action::Enter => {
                self.selection.set_focus(Focus::Tree);
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
        let Some(&(item, _)) = items.get(self.selection.line()) else {
            return;
        };
        match action {
            Action::Up => self.selection.move_line(-1, items.len()),
            Action::Down => self.selection.move_line(1, items.len()),
            Action::Enter | Action::Right => {
                if let Item::Ray(n) = item {
                    self.selection.expand(n);
                }
            }
            Action::Left => match item {
                Item::Ray(n) if self.selection.is_expanded(n) => self.selection.collapse(n),
                // Go to the parent line.
                Item::Shadow(n, _) => self.select_node(n),
                Item::Ray(n) => {
                    if let Some(p) = self.selection.parent(n) {
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
            let areas = self.screen.areas();
            if self.screen.help_open() {
                self.screen.scroll_help(wheel);
            } else if areas.details.contains(at) {
                self.selection.scroll_by(wheel);
            } else if areas.tree.contains(at) {
                let count = self.items().len();
                self.selection.move_line(i64::from(wheel), count);
            }
            return;
        }
        if m.kind != MouseEventKind::Down(MouseButton::Left) {
            return;
        }
        let (img, tree) = (self.screen.areas().image, self.screen.areas().tree);
        if img.contains((m.column, m.row).into()) {
            let (i, j) = (m.column - img.x, (m.row - img.y) * 2);
            let (w, h) = self.image_size();
            if let Some(p) = self.window().pixel_at(i, j, w, h) {
                self.selection.set_focus(Focus::Image);
                self.select(p);
            }
        } else if tree.contains((m.column, m.row).into()) {
            self.selection.set_focus(Focus::Tree);
            let line = usize::from(m.row - tree.y) + self.selection.tree_scroll(tree.height);
            if line < self.items().len() {
                self.selection.set_line(line);
            }
        }
    }

    /// Goes to the next pixel with what `f` seeks.
    fn find(&mut self) {
        if self.scene.is_none() {
            // The search traces every pixel: without the scene it would find
            // nothing and wrongly say so.
            self.message = format!(
                "f searches the whole image, which needs the scene: {}",
                self.no_scene_here()
            );
            return;
        }
        let (found, said) = self.finding.find(self.scene.as_ref(), self.cursor());
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
