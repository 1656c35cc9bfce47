//! The update step before each frame, apart from both the state and the
//! drawing: it measures what the frame will show (the panes depend on the
//! guide's and the step's text), keeps the pane areas for clicks, asks for the
//! picture of the image pane's window and keeps the numbers' scroll in range,
//! so that drawing then only reads.

use ratatui::layout::Rect;

use super::app::App;
use super::panes::details::details_top;
use super::ui::panes;

/// Brings `app` up to date for a frame on a terminal of `area`.
pub fn tick(app: &mut App, area: Rect) {
    app.receive();
    let panes = panes(app, area);
    app.set_areas(panes.areas());
    app.request_picture();
    if let Some(details) = panes.details {
        let top = details_top(app, details) as u16;
        app.scroll_details_to(top);
    }
}
