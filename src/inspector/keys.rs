//! What keys, clicks and the mouse wheel do to the inspector's state.

use ratatui::crossterm::event::{
    KeyCode, KeyEvent, KeyModifiers, MouseButton, MouseEvent, MouseEventKind,
};

use super::app::{App, Focus, Item, Pane, Prompt};
use super::find::Seek;

impl App {
    /// Handles one key press.
    pub fn on_key(&mut self, key: KeyEvent) {
        // A message answers the key before; the next key clears it.
        self.message.clear();
        if self.prompt.is_some() {
            self.prompt_key(key.code);
            return;
        }
        if self.help {
            match key.code {
                KeyCode::Down | KeyCode::Char('j') => self.help_scroll += 1,
                KeyCode::PageDown => self.help_scroll += 10,
                KeyCode::Up | KeyCode::Char('k') => {
                    self.help_scroll = self.help_scroll.saturating_sub(1)
                }
                KeyCode::PageUp => self.help_scroll = self.help_scroll.saturating_sub(10),
                KeyCode::Char('q') => self.quit = true,
                _ => self.help = false,
            }
            return;
        }
        let ctrl = key.modifiers.contains(KeyModifiers::CONTROL);
        match key.code {
            KeyCode::Char('q') | KeyCode::Esc => self.quit = true,
            KeyCode::Char('c') if ctrl => self.quit = true,
            KeyCode::Char('?') => {
                self.help = true;
                self.help_scroll = 0;
            }
            KeyCode::Tab | KeyCode::BackTab => {
                self.focus = if self.focus == Focus::Image {
                    Focus::Tree
                } else {
                    Focus::Image
                }
            }
            KeyCode::Char('n') | KeyCode::Char(' ') => match self.guide {
                Some(_) => self.stop_by(1),
                None => self.step_by(1),
            },
            KeyCode::Char('p') | KeyCode::Backspace => match self.guide {
                Some(_) => self.stop_by(-1),
                None => self.step_by(-1),
            },
            KeyCode::Char(']') => self.step_by(1),
            KeyCode::Char('[') => self.step_by(-1),
            KeyCode::Char('x') => self.step = None,
            KeyCode::Char('+') | KeyCode::Char('=') => self.zoom_by(1),
            KeyCode::Char('-') | KeyCode::Char('_') => self.zoom_by(-1),
            KeyCode::Char('g') => self.prompt = Some(Prompt::GoTo(String::new())),
            KeyCode::Char('m') => self.prompt = Some(Prompt::Edit(String::new())),
            KeyCode::Char('w') => self.prompt = Some(Prompt::Write(self.default_edit_name())),
            KeyCode::Char('u') => self.restore_scene(),
            KeyCode::Char('e') => self.expand_all(),
            KeyCode::Char('s') => self.next_sample(),
            KeyCode::Char('f') => self.find(),
            KeyCode::Char('F') => {
                let k = Seek::ALL.iter().position(|&s| s == self.seek).unwrap_or(0);
                self.seek = Seek::ALL[(k + 1) % Seek::ALL.len()];
                self.find();
            }
            KeyCode::Char('o') => self.cycle_overlay(),
            KeyCode::Char('v') => {
                self.pane = match self.pane {
                    Pane::Details => Pane::Diagram,
                    Pane::Diagram => Pane::Details,
                }
            }
            KeyCode::PageDown => self.scroll_details(10),
            KeyCode::PageUp => self.scroll_details(-10),
            KeyCode::Char('t') => self.focus = Focus::Tree,
            KeyCode::Char('i') => self.focus = Focus::Image,
            code => match self.focus {
                Focus::Image => self.image_key(code),
                Focus::Tree => self.tree_key(code),
            },
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
                Some(Prompt::Write(t)) => self.write_scene(&t),
                None => {}
            },
            _ => {}
        }
    }

    fn image_key(&mut self, code: KeyCode) {
        let step = self.cursor_step();
        let (x, y) = (i64::from(self.cursor.0), i64::from(self.cursor.1));
        let to = match code {
            KeyCode::Left | KeyCode::Char('h') => (x - step, y),
            KeyCode::Right | KeyCode::Char('l') => (x + step, y),
            KeyCode::Up | KeyCode::Char('k') => (x, y - step),
            KeyCode::Down | KeyCode::Char('j') => (x, y + step),
            KeyCode::Enter => {
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

    fn tree_key(&mut self, code: KeyCode) {
        let items = self.items();
        let Some(&(item, _)) = items.get(self.selected) else {
            return;
        };
        match code {
            KeyCode::Up | KeyCode::Char('k') => {
                self.selected = self.selected.saturating_sub(1);
                self.detail_scroll = 0;
            }
            KeyCode::Down | KeyCode::Char('j') => {
                self.selected = (self.selected + 1).min(items.len().saturating_sub(1));
                self.detail_scroll = 0;
            }
            KeyCode::Enter | KeyCode::Right | KeyCode::Char('l') => {
                if let Item::Ray(n) = item {
                    self.expanded.insert(n);
                }
            }
            KeyCode::Left | KeyCode::Char('h') => match item {
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

    fn zoom_by(&mut self, by: i32) {
        let max = self.max_zoom();
        self.zoom = self.zoom.saturating_add_signed(by).min(max);
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
