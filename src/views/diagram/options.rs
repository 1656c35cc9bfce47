//! What the reader asks of a ray diagram: what it frames, which labels it
//! writes, its size, the sample and the steps it shows, the hierarchy's boxes.
//! Apart from the drawing, so the command line, the lessons and the inspector
//! name the same options.

use glam::DVec2;

use crate::views::diagram::projection::View;

/// Which labels to write.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Labels {
    /// None: only the legend and caption.
    None,
    /// Objects, lights and the eye.
    Objects,
    /// Also hit points (P1, P2, … in the order they were found), normals and angles.
    All,
}

/// What the figure frames.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum Fit {
    /// The hits and the objects they are on, large: where the optics happen.
    #[default]
    Hits,
    /// The whole tree: the eye, the image plane, every ray near them.
    Tree,
    /// Every bounded object, the eye and the lights.
    Scene,
}

/// What to draw, and how big.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// Figure width in pixels.
    pub width: u32,
    /// Figure height in pixels.
    pub height: u32,
    /// The projection.
    pub view: View,
    /// Draw only rays up to this depth (1: the primary ray).
    pub depth: Option<u32>,
    /// Draw shadow rays.
    pub shadows: bool,
    /// Which labels.
    pub labels: Labels,
    /// Which of the trace's samples to draw.
    pub sample: usize,
    /// What to frame.
    pub fit: Fit,
    /// An explicit window in drawing-plane coordinates (`lo`, `hi`), over `fit`.
    pub window: Option<(DVec2, DVec2)>,
    /// Tick marks along the rays at whole steps of `t`.
    pub ticks: bool,
    /// The hit object's other roots on each ray's line, with their fates.
    pub roots: bool,
    /// Step numbers, as `raytree trace --steps` numbers them.
    pub steps: bool,
    /// Show the algorithm only up to this step (0-based), as a step-through does.
    pub until_step: Option<usize>,
    /// Draw the hierarchy's boxes the drawn rays were tested against.
    pub boxes: bool,
    /// Also record the figure as SVG ([`crate::figure::canvas::Figure::svg`]),
    /// shape for shape with its PNG.
    pub svg: bool,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            width: 1200,
            height: 800,
            view: View::Auto,
            depth: None,
            shadows: true,
            labels: Labels::All,
            sample: 0,
            fit: Fit::default(),
            window: None,
            ticks: false,
            roots: false,
            steps: false,
            until_step: None,
            boxes: false,
            svg: false,
        }
    }
}
