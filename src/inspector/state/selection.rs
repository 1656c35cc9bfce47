//! What is selected: the pixel and its trace (which of its samples the panes
//! show, how long it took to trace), which pane the arrows drive, and in the
//! tree pane the rays opened, the selected line and how far its numbers are
//! scrolled. What the tree pane lists depends on how far stepping has come,
//! so the methods that list lines take what is revealed.

use std::collections::BTreeSet;
use std::time::Duration;

use super::reveal::Revealed;
use crate::trace::recorder::Branch;
use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::{RayNode, RayTree};
use crate::tree::steps::Step;

/// Which pane the arrow keys drive.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Focus {
    /// Arrows move the pixel cursor.
    #[default]
    Image,
    /// Arrows move through the ray tree.
    Tree,
}

/// A line of the tree pane.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Item {
    /// A ray: node index.
    Ray(usize),
    /// A shadow ray: node index and light index.
    Shadow(usize, usize),
}

impl Item {
    /// The node the line belongs to.
    pub fn node(self) -> usize {
        match self {
            Item::Ray(n) | Item::Shadow(n, _) => n,
        }
    }
}

/// The tree pane's view to give back after the pixel is traced again: the
/// sample, the open rays, the selected line.
pub(in crate::inspector) struct View {
    sample: usize,
    expanded: BTreeSet<usize>,
    line: usize,
}

/// The pixel, its trace, the focus and the tree pane's cursor.
#[derive(Debug, Default)]
pub(in crate::inspector) struct Selection {
    /// In the full image's coordinates (as `raytree trace --pixel`).
    pixel: (u32, u32),
    /// The pixel's trace.
    trace: Option<TraceDocument>,
    /// Which of the pixel's samples the panes show (0 is the first).
    sample: usize,
    /// How long the pixel took to trace.
    traced_in: Duration,
    /// Which pane the arrows drive.
    focus: Focus,
    /// Nodes whose children are shown.
    expanded: BTreeSet<usize>,
    /// The tree pane's selected line.
    line: usize,
    /// Lines of the selected ray's numbers scrolled past.
    scroll: u16,
}

impl Selection {
    /// The selected pixel.
    pub fn pixel(&self) -> (u32, u32) {
        self.pixel
    }

    /// Selects `pixel` (its trace follows with [`Selection::show`]).
    pub fn set_pixel(&mut self, pixel: (u32, u32)) {
        self.pixel = pixel;
    }

    /// The pixel's trace.
    pub fn trace(&self) -> Option<&TraceDocument> {
        self.trace.as_ref()
    }

    /// Which sample the panes show.
    pub fn sample(&self) -> usize {
        self.sample
    }

    /// Shows sample `sample` of the next trace.
    pub fn set_sample(&mut self, sample: usize) {
        self.sample = sample;
    }

    /// The shown sample's ray tree.
    pub fn tree(&self) -> Option<&RayTree> {
        self.trace.as_ref().map(|t| &t.samples[self.sample].tree)
    }

    /// The shown sample's rays (none without a trace).
    fn nodes(&self) -> &[RayNode] {
        self.tree().map_or(&[], |t| &t.nodes)
    }

    /// How long the pixel took to trace.
    pub fn traced_in(&self) -> Duration {
        self.traced_in
    }

    /// Records how long the pixel took to trace.
    pub fn set_traced_in(&mut self, took: Duration) {
        self.traced_in = took;
    }

    /// Shows `trace` (its sample kept if it has it, else its last), the root
    /// open and selected, the numbers at the top; returns its steps.
    pub fn show(&mut self, trace: TraceDocument) -> Vec<Step> {
        self.sample = self.sample.min(trace.samples.len().saturating_sub(1));
        let steps = trace.steps(self.sample);
        self.trace = Some(trace);
        self.expanded = BTreeSet::from([0]);
        self.line = 0;
        self.scroll = 0;
        steps
    }

    /// Shows the pixel's next sample (after the last, the first again);
    /// returns its steps, or nothing without a trace.
    pub fn next_sample(&mut self) -> Option<Vec<Step>> {
        let trace = self.trace.take()?;
        self.sample = (self.sample + 1) % trace.samples.len().max(1);
        Some(self.show(trace))
    }

    /// The tree pane's view, to give back after tracing the pixel again.
    pub fn view(&self) -> View {
        View {
            sample: self.sample,
            expanded: self.expanded.clone(),
            line: self.line,
        }
    }

    /// Gives back `view`'s sample (if the trace has it) and open rays; returns
    /// its line, for [`Selection::set_line`] once the lines are known.
    pub fn set_view(&mut self, view: View) -> usize {
        self.sample = view
            .sample
            .min(self.trace.as_ref().map_or(1, |t| t.samples.len()) - 1);
        self.expanded = view.expanded;
        view.line
    }

    /// Which pane the arrows drive.
    pub fn focus(&self) -> Focus {
        self.focus
    }

    /// Makes the arrows drive `focus`.
    pub fn set_focus(&mut self, focus: Focus) {
        self.focus = focus;
    }

    /// The tree pane's lines: the item and its indentation; of what `shown`
    /// reveals, only the rays spawned and the shadow rays cast.
    pub fn items(&self, shown: &Revealed) -> Vec<(Item, usize)> {
        let mut out = Vec::new();
        let nodes = self.nodes();
        if !nodes.is_empty() && shown.node(0).spawned {
            self.push_items(nodes, shown, 0, 0, &mut out);
        }
        out
    }

    fn push_items(
        &self,
        nodes: &[RayNode],
        shown: &Revealed,
        i: usize,
        indent: usize,
        out: &mut Vec<(Item, usize)>,
    ) {
        out.push((Item::Ray(i), indent));
        if !self.expanded.contains(&i) || out.len() > nodes.len() * 64 {
            return;
        }
        for k in 0..shown.node(i).shadows.min(nodes[i].shadow_rays.len()) {
            out.push((Item::Shadow(i, k), indent + 1));
        }
        for c in nodes[i].children() {
            if shown.node(c).spawned {
                self.push_items(nodes, shown, c, indent + 1, out);
            }
        }
    }

    /// The selected line.
    pub fn line(&self) -> usize {
        self.line
    }

    /// Selects line `line`.
    pub fn set_line(&mut self, line: usize) {
        self.line = line;
    }

    /// Moves the selected line `by` lines, kept within `count` lines; the
    /// numbers start at the top.
    pub fn move_line(&mut self, by: i64, count: usize) {
        let last = count.saturating_sub(1) as i64;
        self.line = (self.line as i64 + by).clamp(0, last) as usize;
        self.scroll = 0;
    }

    /// The selected line's item.
    pub fn selected_item(&self, shown: &Revealed) -> Option<Item> {
        self.items(shown).get(self.line).map(|&(item, _)| item)
    }

    /// Selects `item`'s line, if it is listed.
    pub fn select_item(&mut self, item: Item, shown: &Revealed) {
        if let Some(pos) = self.items(shown).iter().position(|&(i, _)| i == item) {
            self.line = pos;
        }
    }

    /// Selects node `n`'s line, opening its ancestors.
    pub fn select_node(&mut self, n: usize, shown: &Revealed) {
        if self.trace.is_none() {
            return;
        }
        let mut p = self.nodes()[n].parent;
        while let Some(i) = p {
            self.expanded.insert(i);
            p = self.nodes()[i].parent;
        }
        self.select_item(Item::Ray(n), shown);
    }

    /// Node `n`'s parent, if it has one.
    pub fn parent(&self, n: usize) -> Option<usize> {
        self.nodes().get(n).and_then(|node| node.parent)
    }

    /// Whether node `n`'s children are shown.
    pub fn is_expanded(&self, n: usize) -> bool {
        self.expanded.contains(&n)
    }

    /// Shows node `n`'s children.
    pub fn expand(&mut self, n: usize) {
        self.expanded.insert(n);
    }

    /// Folds node `n`'s children.
    pub fn collapse(&mut self, n: usize) {
        self.expanded.remove(&n);
    }

    /// Shows every node's children.
    pub fn expand_all(&mut self) {
        if self.trace.is_some() {
            self.expanded = (0..self.nodes().len()).collect();
        }
    }

    /// Whether node `n` has anything to expand.
    pub fn expandable(&self, n: usize) -> bool {
        self.trace.is_some() && {
            let node = &self.nodes()[n];
            !node.shadow_rays.is_empty() || node.children().next().is_some()
        }
    }

    /// The first tree line shown in `height` lines, so the selection stays in view.
    pub fn tree_scroll(&self, height: u16) -> usize {
        self.line.saturating_sub(usize::from(height.max(1)) - 1)
    }

    /// Lines of the selected ray's numbers scrolled past.
    pub fn scroll(&self) -> u16 {
        self.scroll
    }

    /// Scrolls the numbers to line `top` (`u16::MAX`: the end).
    pub fn set_scroll(&mut self, top: u16) {
        self.scroll = top;
    }

    /// Scrolls the numbers by `by` lines.
    pub fn scroll_by(&mut self, by: i32) {
        self.scroll = self.scroll.saturating_add_signed(by as i16);
    }

    /// Why node `n`'s branches stopped, in words ("" when both were traced or it continues).
    pub fn stop_reason(&self, n: usize) -> String {
        let Some(node) = self.trace.as_ref().map(|_| &self.nodes()[n]) else {
            return String::new();
        };
        if node.hit.is_none() {
            return "miss → background".to_owned();
        }
        let mut why: Vec<&str> = Vec::new();
        for (branch, none) in [
            (&node.reflected, "not reflective"),
            (&node.refracted, "opaque"),
        ] {
            match branch.as_ref().map(|b| b.outcome) {
                Some(Branch::NoCoefficient) => why.push(none),
                Some(Branch::MaxDepth) => why.push("max depth"),
                Some(Branch::WeightCutoff) => why.push("weight cutoff"),
                Some(Branch::TotalInternalReflection) => why.push("total internal reflection"),
                _ => {}
            }
        }
        why.dedup();
        why.join(", ")
    }
}
