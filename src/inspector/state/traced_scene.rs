//! The scene as the inspector traces it: the scene with what a tracer makes of
//! its objects before the first ray (the hierarchy, the media around the eye)
//! and the objects' entries a trace names them by, made once when the scene
//! is loaded and kept across what-if edits, which change materials and methods
//! but never objects. So a key costs what its pixel costs, whatever the number
//! of objects: a million objects' hierarchy was built again for every key, for
//! each picture of the image pane and for every scan, about a second each time,
//! and their entries made again for every trace (issue 29).

use std::sync::Arc;

use crate::scene::Scene;
use crate::scene::source::SceneSource;
use crate::trace::tracer::{Prepared, Tracer};
use crate::tree::document::{ObjectEntry, TraceDocument, object_entries};
use crate::tree::record::{self, TraceError};

/// A scene and what its tracers share.
#[derive(Clone, Debug)]
pub(in crate::inspector) struct TracedScene {
    scene: Arc<Scene>,
    prepared: Prepared,
    objects: Arc<[ObjectEntry]>,
}

impl TracedScene {
    /// Builds what tracing `scene` needs (its hierarchy, on all cores).
    pub fn new(scene: Scene) -> Self {
        Self {
            prepared: Prepared::new(&scene),
            objects: object_entries(&scene),
            scene: Arc::new(scene),
        }
    }

    /// `scene`, an edit of this one (or this one as loaded, after an edit):
    /// the same objects, so the same hierarchy; and the same materials'
    /// names, so the same entries.
    pub fn edited(&self, scene: Arc<Scene>) -> Self {
        debug_assert_eq!(scene.objects, self.scene.objects);
        debug_assert!(
            (scene.materials.iter().map(|m| &m.name)).eq(self
                .scene
                .materials
                .iter()
                .map(|m| &m.name))
        );
        Self {
            prepared: self.prepared.for_edited(&scene),
            objects: Arc::clone(&self.objects),
            scene,
        }
    }

    /// The scene.
    pub fn scene(&self) -> &Arc<Scene> {
        &self.scene
    }

    /// A new tracer (remembering no shadow ray's blocker yet, as
    /// `raytree trace` starts), building nothing.
    pub fn tracer(&self) -> Tracer<'_> {
        Tracer::prepared(&self.scene, &self.prepared)
    }

    /// Traces pixel `(x, y)` exactly as `raytree trace` does.
    pub fn record(&self, source: SceneSource, x: u32, y: u32) -> Result<TraceDocument, TraceError> {
        let objects = Arc::clone(&self.objects);
        record::pixel_with(&self.tracer(), objects, source, x, y, None)
    }
}
