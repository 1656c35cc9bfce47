//! The inspector without a terminal: its state and keys, and its panes drawn
//! into ratatui's test backend.

use crate::inspector::drive::{key, keys};
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyModifiers, MouseButton, MouseEvent, MouseEventKind};
use ratatui::layout::Rect;
use raytree::inspector::{App, Areas, Focus, Item, draw};
use raytree::scene::source::SceneSource;

/// An inspector on the Whitted scene with an 80 × 30-cell image pane, as if drawn.
fn app_at(pixel: Option<(u32, u32)>) -> App {
    let mut app = App::new(
        raytree::scene::loader::whitted(),
        SceneSource::new("scenes/whitted.json", ""),
        pixel,
        false,
    );
    app.set_areas(Areas {
        image: Rect::new(1, 1, 80, 30),
        tree: Rect::new(83, 1, 76, 20),
        details: Rect::new(82, 22, 78, 24),
    });
    app
}

fn screen(app: &mut App) -> String {
    let mut terminal = Terminal::new(TestBackend::new(160, 48)).unwrap();
    app.render_picture_now();
    raytree::inspector::tick(app, Rect::new(0, 0, 160, 48));
    terminal.draw(|f| draw(f, app)).unwrap();
    let buffer = terminal.backend().buffer().clone();
    (0..buffer.area.height)
        .map(|y| {
            (0..buffer.area.width)
                .map(|x| buffer[(x, y)].symbol().to_owned())
                .collect::<String>()
                + "\n"
        })
        .collect()
}

#[test]
fn starts_on_the_deepest_tree_nearest_the_center() {
    let app = app_at(None);
    let scene = raytree::scene::loader::whitted();
    let map = raytree::inspector::scan_features(&scene, 8);
    let deepest = map.cells.iter().map(|f| f.depth).max().unwrap();
    let start = map.at(app.cursor().0, app.cursor().1);
    assert_eq!(start.depth, deepest, "the start pixel has the deepest tree");
    assert!(start.depth > 2, "and it is deeper than a floor pixel's");
    // The image's center is a plain floor pixel: not where the inspector starts.
    assert_ne!(app.cursor(), (320, 240));
}

#[test]
fn arrows_move_the_cursor() {
    let mut app = app_at(Some((320, 240)));
    // Fitting 640×480 into 80 × 60 dots: 8 image pixels per dot, so one press moves 8 pixels.
    key(&mut app, KeyCode::Right);
    key(&mut app, KeyCode::Char('j'));
    assert_eq!(app.cursor(), (328, 248));
    // Never past the edge.
    for _ in 0..100 {
        key(&mut app, KeyCode::Left);
    }
    assert_eq!(app.cursor().0, 0);
    assert_eq!(
        app.trace().unwrap().pixel.unwrap().x,
        0,
        "moving traces the new pixel"
    );
}

#[test]
fn zoom_reaches_every_pixel() {
    let mut app = app_at(Some((416, 209)));
    assert_eq!(app.window().scale, 8.0);
    keys(&mut app, "++");
    assert_eq!((app.zoom(), app.window().scale), (2, 2.0));
    // Deepest zoom: four dots per pixel, so a press moves exactly one pixel.
    for _ in 0..10 {
        key(&mut app, KeyCode::Char('+'));
    }
    assert_eq!((app.zoom(), app.window().scale), (5, 0.25));
    key(&mut app, KeyCode::Right);
    assert_eq!(app.cursor(), (417, 209));
    // The window follows the cursor and keeps it in view.
    let w = app.window();
    assert!(w.dot_of(417, 209).is_some());
    keys(&mut app, "------");
    assert_eq!(app.zoom(), 0);
}

#[test]
fn tree_expands_collapses_and_goes_to_the_parent() {
    let mut app = app_at(Some((416, 209)));
    key(&mut app, KeyCode::Tab);
    assert_eq!(app.focus(), Focus::Tree);
    // The root is open: its two shadow rays, then its reflected and refracted rays.
    let items: Vec<Item> = app.items().into_iter().map(|(i, _)| i).collect();
    assert_eq!(
        items,
        vec![
            Item::Ray(0),
            Item::Shadow(0, 0),
            Item::Shadow(0, 1),
            Item::Ray(1),
            Item::Ray(2)
        ]
    );
    for _ in 0..4 {
        key(&mut app, KeyCode::Down);
    }
    assert_eq!(app.selected_item(), Some(Item::Ray(2)));
    key(&mut app, KeyCode::Enter);
    let opened = app.items().len();
    assert!(opened > 5, "the refracted ray opens");
    key(&mut app, KeyCode::Left);
    assert_eq!(app.items().len(), 5, "and closes");
    key(&mut app, KeyCode::Left);
    assert_eq!(
        app.selected_item(),
        Some(Item::Ray(0)),
        "← on a closed ray goes to its parent"
    );
    key(&mut app, KeyCode::Char('e'));
    assert!(app.items().len() > opened, "e opens everything");
}

#[test]
fn steps_go_forward_and_back_and_select_their_ray() {
    let mut app = app_at(Some((416, 209)));
    let steps = app.steps().to_vec();
    assert!(steps.len() > 20);
    key(&mut app, KeyCode::Char('n'));
    assert_eq!(app.step(), Some(0));
    // Forward to the first step of another ray: the tree selects that ray.
    let first_child = steps.iter().position(|s| s.node != 0).unwrap();
    for _ in 0..first_child {
        key(&mut app, KeyCode::Char(' '));
    }
    assert_eq!(app.step(), Some(first_child));
    assert_eq!(app.selected_item().unwrap().node(), steps[first_child].node);
    key(&mut app, KeyCode::Char('p'));
    key(&mut app, KeyCode::Backspace);
    assert_eq!(app.step(), Some(first_child - 2));
    // Back past the start stays at the first step.
    for _ in 0..100 {
        key(&mut app, KeyCode::Char('p'));
    }
    assert_eq!(app.step(), Some(0));
}

#[test]
fn go_to_prompt_help_and_quit() {
    let mut app = app_at(None);
    key(&mut app, KeyCode::Char('g'));
    keys(&mut app, "416,209");
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.cursor(), (416, 209));
    key(&mut app, KeyCode::Char('g'));
    keys(&mut app, "999,1");
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.cursor(), (416, 209), "an outside pixel is refused");
    assert!(app.message().contains("outside"), "{}", app.message());
    key(&mut app, KeyCode::Char('?'));
    assert!(app.help_shown());
    key(&mut app, KeyCode::Char('x'));
    assert!(
        !app.help_shown() && !app.quitting(),
        "any key closes the help"
    );
    key(&mut app, KeyCode::Char('q'));
    assert!(app.quitting());
}

#[test]
fn a_click_selects_the_pixel_under_it() {
    let mut app = app_at(None);
    // Cell (11, 6) of the screen is dot (10, 10) of the pane (its top half): pixel (84, 84).
    app.on_mouse(MouseEvent {
        kind: MouseEventKind::Down(MouseButton::Left),
        column: 11,
        row: 6,
        modifiers: KeyModifiers::NONE,
    });
    assert_eq!(app.cursor(), (84, 84));
}

#[test]
fn panes_show_the_tree_the_numbers_and_the_steps() {
    let mut app = app_at(Some((416, 209)));
    app.set_areas(Areas::default());
    let text = screen(&mut app);
    for expected in [
        "ray tree",
        "primary d1 'glass'",
        "refracted d2 'cavity'",
        "total internal reflection",
        "selected ray",
        "= local",
        "× refracted",
        "diagram",
        "pixel 416,209 of 640×480",
    ] {
        assert!(text.contains(expected), "missing {expected:?}:\n{text}");
    }
    // The step line follows the steps: the camera stage, then the primary ray.
    key(&mut app, KeyCode::Char('n'));
    let text = screen(&mut app);
    assert!(
        text.contains("step 1/") && text.contains("camera: pixel 416,209"),
        "{text}"
    );
    key(&mut app, KeyCode::Char('n'));
    let text = screen(&mut app);
    assert!(
        text.contains("step 2/") && text.contains("spawn primary ray"),
        "{text}"
    );
    // The help lists every key.
    key(&mut app, KeyCode::Char('?'));
    let text = screen(&mut app);
    for b in raytree::inspector::KEYS {
        assert!(text.contains(b.keys), "help lacks {}", b.keys);
    }
}

#[test]
fn image_pane_shows_the_render_in_half_blocks_with_the_cursor() {
    let mut app = app_at(Some((416, 209)));
    let mut terminal = Terminal::new(TestBackend::new(160, 48)).unwrap();
    raytree::inspector::tick(&mut app, Rect::new(0, 0, 160, 48));
    terminal.draw(|f| draw(f, &app)).unwrap();
    app.render_picture_now();
    raytree::inspector::tick(&mut app, Rect::new(0, 0, 160, 48));
    terminal.draw(|f| draw(f, &app)).unwrap();
    let buffer = terminal.backend().buffer().clone();
    let image = app.areas().image;
    let window = app.window();
    // Every dot shows the 8-bit color the renderer gives its pixel.
    let scene = raytree::scene::loader::whitted();
    let rendered =
        raytree::trace::render::render(&scene, &raytree::trace::progress::Progress::QUIET).unwrap();
    let (ci, cj) = window.dot_of(416, 209).unwrap();
    for (i, j) in [(5u16, 5u16), (40, 33), (ci, cj + 2)] {
        let (x, y) = window.pixel_at(i, j, 640, 480).unwrap();
        let [r, g, b] = raytree::io::image::rgb8(rendered.get(x, y));
        let cell = &buffer[(image.x + i, image.y + j / 2)];
        let shown = if j % 2 == 0 { cell.fg } else { cell.bg };
        assert_eq!(shown, ratatui::style::Color::Rgb(r, g, b), "dot ({i}, {j})");
    }
    let cursor_cell = &buffer[(image.x + ci, image.y + cj / 2)];
    let cursor = if cj % 2 == 0 {
        cursor_cell.fg
    } else {
        cursor_cell.bg
    };
    assert_eq!(
        cursor,
        ratatui::style::Color::Rgb(255, 0, 255),
        "the cursor is marked"
    );
}

/// Issue 29: idle, the inspector drew a frame every 30 ms. It draws one when
/// something changed: an input event, the terminal's size, a picture from
/// the worker.
#[test]
fn idle_the_inspector_draws_no_frame() {
    use raytree::inspector::Frames;
    let mut app = app_at(Some((320, 240)));
    app.render_picture_now();
    let mut terminal = Terminal::new(TestBackend::new(160, 48)).unwrap();
    let mut frames = Frames::default();
    assert!(
        frames.frame(&mut terminal, &mut app).unwrap(),
        "the first frame"
    );
    for _ in 0..100 {
        frames.frame(&mut terminal, &mut app).unwrap();
    }
    assert_eq!(frames.drawn(), 1, "idle frames drawn");
    frames.input();
    assert!(
        frames.frame(&mut terminal, &mut app).unwrap(),
        "after a key"
    );
    assert!(!frames.frame(&mut terminal, &mut app).unwrap());
    terminal.backend_mut().resize(120, 40);
    assert!(
        frames.frame(&mut terminal, &mut app).unwrap(),
        "after a resize"
    );
    assert!(!frames.frame(&mut terminal, &mut app).unwrap());
    assert_eq!(frames.drawn(), 3);
}

/// The worker's pictures are drawn as they come (coarse, then complete), and
/// once the complete one is shown nothing more is.
#[test]
fn a_picture_from_the_worker_is_drawn_and_then_nothing() {
    use raytree::inspector::Frames;
    let mut app = App::new(
        raytree::scene::loader::whitted(),
        SceneSource::new("scenes/whitted.json", ""),
        None,
        true,
    );
    let mut terminal = Terminal::new(TestBackend::new(160, 48)).unwrap();
    let mut frames = Frames::default();
    let started = std::time::Instant::now();
    while !app.picture().is_some_and(|p| p.complete)
        && started.elapsed() < std::time::Duration::from_secs(60)
    {
        frames.frame(&mut terminal, &mut app).unwrap();
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    frames.frame(&mut terminal, &mut app).unwrap();
    assert!(
        app.picture().is_some_and(|p| p.complete),
        "no complete picture"
    );
    let drawn = frames.drawn();
    // The first frame, and at least the complete picture's.
    assert!(drawn >= 2, "{drawn} frames");
    for _ in 0..50 {
        frames.frame(&mut terminal, &mut app).unwrap();
        std::thread::sleep(std::time::Duration::from_millis(2));
    }
    assert_eq!(frames.drawn(), drawn, "frames drawn idle");
}
