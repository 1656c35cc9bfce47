//! The scene as the inspector traces it: the scene with what a tracer makes of
//! its objects before the first ray (the hierarchy, the media around the eye),
//! made once when the scene is loaded and kept across what-if edits, which
//! change materials and methods but never objects. So a key costs what its
//! pixel costs, whatever the number of objects: a million objects' hierarchy
//! was built again for every key, for each picture of the image pane and for
//! every scan, about a second each time (issue 29).

use std::sync::Arc;

use crate::scene::Scene;
use crate::trace::tracer::{Prepared, Tracer};

/// A scene and what its tracers share.
#[derive(Clone, Debug)]
pub(super) struct TracedScene {
    scene: Arc<Scene>,
    prepared: Prepared,
}

impl TracedScene {
    /// Builds what tracing `scene` needs (its hierarchy, on all cores).
    pub fn new(scene: Scene) -> Self {
        let prepared = Prepared::new(&scene);
        Self {
            scene: Arc::new(scene),
            prepared,
        }
    }

    /// `scene`, an edit of this one (or this one as loaded, after an edit):
    /// the same objects, so the same hierarchy.
    pub fn edited(&self, scene: Arc<Scene>) -> Self {
        debug_assert_eq!(scene.objects, self.scene.objects);
        Self {
            prepared: self.prepared.for_edited(&scene),
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
}
