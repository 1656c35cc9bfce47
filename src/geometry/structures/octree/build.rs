//! Building the octree.
//!
//! A node becomes a leaf when it holds at most [`LEAF_SIZE`]
//! primitives, when it is [`DEPTH_LIMIT`] levels deep (or as deep as asked), when
//! every one of its primitives overlaps every child (splitting again would only
//! copy the list eight times, level after level), or when the split would take
//! the entries of all leaves past [`Octree::entry_cap`]. Nodes are split level
//! by level (breadth first), so when the cap stops the splitting it stops it at
//! about one depth everywhere; built depth first, the first corner of a scene
//! could spend the whole budget and leave the rest in leaves of thousands. (A
//! first version also stopped when all of a node's primitives fell into one
//! child: the sphereflake's 7,382 spheres, all in one corner of the root's
//! child, then stayed in one leaf and its rays tested 2,820 primitives each.)
//! A primitive goes into every child whose closed
//! box its closed box overlaps (touching counts). The nodes live in one `Vec`,
//! the eight children of a node consecutive; the leaves' lists in one `Vec<u32>`.

use glam::{BVec3, DVec3};

use crate::geometry::structures::octree::{DEEPEST, DEPTH_LIMIT, Kind, LEAF_SIZE, Node, Octree};
use crate::math::bounds::Bounds;

impl Octree {
    /// Builds the octree over primitives with these (finite, non-empty) bounds,
    /// at most [`DEPTH_LIMIT`] levels deep.
    pub fn build(bounds: &[Bounds]) -> Octree {
        Octree::build_to_depth(bounds, DEPTH_LIMIT)
    }

    /// [`Octree::build`] with leaves at most `depth_limit` levels below the root
    /// (clamped to [`DEEPEST`]); 0 makes the root a leaf of every primitive.
    pub fn build_to_depth(bounds: &[Bounds], depth_limit: u32) -> Octree {
        let depth_limit = depth_limit.min(DEEPEST);
        let n = bounds.len();
        if n == 0 {
            return Octree {
                nodes: Vec::new(),
                entries: Vec::new(),
                primitives: 0,
                depth: 0,
                depth_limit,
            };
        }
        assert!(
            u32::try_from(Octree::entry_cap(n)).is_ok(),
            "too many primitives for an octree"
        );
        let scene = bounds.iter().fold(Bounds::EMPTY, |a, b| a.union(*b));
        let side = (scene.max - scene.min).max_element();
        // A cube at the scene's lower corner; `max` keeps it around the scene
        // box even where `min + side` rounds down.
        let root = Bounds {
            min: scene.min,
            max: (scene.min + side).max(scene.max),
        };
        let mut builder = Builder {
            boxes: bounds,
            nodes: vec![Node {
                cell: root,
                kind: Kind::Leaf { start: 0, len: 0 },
            }],
            entries: Vec::new(),
            live: n,
            cap: Octree::entry_cap(n),
            depth_limit,
            depth: 0,
        };
        builder.build((0..n as u32).collect());
        Octree {
            nodes: builder.nodes,
            entries: builder.entries,
            primitives: n,
            depth: builder.depth,
            depth_limit,
        }
    }
}

/// The state of a build: the nodes and entries so far, and the entries all
/// current leaves would hold (`live`), kept at most `cap`.
struct Builder<'a> {
    boxes: &'a [Bounds],
    nodes: Vec<Node>,
    entries: Vec<u32>,
    live: usize,
    cap: usize,
    depth_limit: u32,
    depth: u32,
}

impl Builder<'_> {
    /// Makes the root (node 0, its cell set) over `all`, and every node under
    /// it, a level at a time.
    fn build(&mut self, all: Vec<u32>) {
        let mut level = vec![(0usize, all)];
        let mut depth = 0;
        while !level.is_empty() {
            self.depth = depth;
            let mut next = Vec::new();
            for (at, prims) in level {
                match self.split(at, &prims, depth) {
                    Some(children) => next.extend(children),
                    None => self.leaf(at, &prims),
                }
            }
            level = next;
            depth += 1;
        }
    }

    /// Splits node `at` over `prims`, `depth` levels down, into eight children
    /// (returned with their primitives), unless it should stay a leaf.
    fn split(&mut self, at: usize, prims: &[u32], depth: u32) -> Option<Vec<(usize, Vec<u32>)>> {
        if prims.len() <= LEAF_SIZE || depth >= self.depth_limit {
            return None;
        }
        let cells = octants(&self.nodes[at].cell);
        let parts: [Vec<u32>; 8] = cells.map(|cell| {
            prims
                .iter()
                .copied()
                .filter(|&p| overlaps(&self.boxes[p as usize], &cell))
                .collect()
        });
        let everywhere = parts.iter().all(|part| part.len() == prims.len());
        let live = self.live - prims.len() + parts.iter().map(Vec::len).sum::<usize>();
        if everywhere || live > self.cap {
            return None;
        }
        self.live = live;
        let first = self.nodes.len();
        self.nodes.extend(cells.iter().map(|&cell| Node {
            cell,
            kind: Kind::Leaf { start: 0, len: 0 },
        }));
        self.nodes[at].kind = Kind::Inner {
            first: first as u32,
        };
        Some(
            parts
                .into_iter()
                .enumerate()
                .map(|(i, part)| (first + i, part))
                .collect(),
        )
    }

    /// Makes node `at` a leaf listing `prims`.
    fn leaf(&mut self, at: usize, prims: &[u32]) {
        let start = self.entries.len() as u32;
        self.entries.extend_from_slice(prims);
        self.nodes[at].kind = Kind::Leaf {
            start,
            len: prims.len() as u32,
        };
    }
}

/// The eight children of a cell, split at its mid-point; the children share
/// that one mid-point, so together they cover the cell exactly.
fn octants(cell: &Bounds) -> [Bounds; 8] {
    let mid = cell.center();
    std::array::from_fn(|i| {
        let upper = BVec3::new(i & 1 != 0, i & 2 != 0, i & 4 != 0);
        Bounds {
            min: DVec3::select(upper, mid, cell.min),
            max: DVec3::select(upper, cell.max, mid),
        }
    })
}

/// Whether two closed boxes share a point (touching counts).
fn overlaps(a: &Bounds, b: &Bounds) -> bool {
    a.min.cmple(b.max).all() && a.max.cmpge(b.min).all()
}
