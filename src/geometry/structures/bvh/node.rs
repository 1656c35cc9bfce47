//! The hierarchy's node layout: up to [`WIDTH`] children a node, each child's
//! box in single precision rounded outward (so no hit is lost), a child packed
//! in 32 bits as an inner node or a run of primitives. Apart from building and
//! traversal, which both read it.

use glam::DVec3;
use wide::f32x4;

use crate::math::bounds::Bounds;

/// Leaves hold at most this many primitives.
pub const MAX_LEAF: usize = 4;
/// Children per node: one SSE register of boxes. Eight (two registers) made
/// random rays 7–9 % faster and coherent ones 3 % slower, a loss for renders,
/// whose rays are mostly coherent (docs/performance.md, "Third pass").
pub const WIDTH: usize = 4;

/// A child of a node: an inner node (its index) or a leaf (a run of primitives
/// in `order`), packed in 32 bits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Child(pub(crate) u32);

const LEAF_BIT: u32 = 1 << 31;
const COUNT_SHIFT: u32 = 28;
/// Leaves can start anywhere below this index.
pub(crate) const MAX_PRIMITIVES: usize = 1 << COUNT_SHIFT;

impl Child {
    pub(crate) fn inner(node: usize) -> Child {
        Child(node as u32)
    }

    pub(crate) fn leaf(first: usize, count: usize) -> Child {
        debug_assert!((1..=MAX_LEAF).contains(&count) && first < MAX_PRIMITIVES);
        Child(LEAF_BIT | ((count as u32 - 1) << COUNT_SHIFT) | first as u32)
    }

    pub(crate) fn is_leaf(self) -> bool {
        self.0 & LEAF_BIT != 0
    }

    /// A leaf's primitives as a range of `order`.
    pub(crate) fn primitives(self) -> std::ops::Range<usize> {
        let first = (self.0 & (MAX_PRIMITIVES as u32 - 1)) as usize;
        let count = ((self.0 & !LEAF_BIT) >> COUNT_SHIFT) as usize + 1;
        first..first + count
    }
}

/// One node: the boxes of up to four children, lane by lane (`bounds[0]` the
/// lower corners, `bounds[1]` the upper, each as x, y, z rows of four lanes),
/// rounded outward to `f32`. Unused lanes hold an empty box, which no ray meets.
/// Two cache lines.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub(crate) struct Node {
    pub(crate) bounds: [[f32x4; 3]; 2],
    pub(crate) children: [Child; WIDTH],
    /// Children in use (the first `len` lanes).
    pub(crate) len: u8,
}

impl Node {
    /// The box of lane `lane`, as stored (rounded outward). Always inlined: a
    /// traversal that does not record asks for every lane it tests and drops
    /// it, which only compiles away once this is inlined (out of line, it was
    /// 13 % of a render's instructions).
    #[inline(always)]
    pub(crate) fn lane(&self, lane: usize) -> Bounds {
        let corner = |c: usize| {
            DVec3::new(
                f64::from(self.bounds[c][0].to_array()[lane]),
                f64::from(self.bounds[c][1].to_array()[lane]),
                f64::from(self.bounds[c][2].to_array()[lane]),
            )
        };
        Bounds {
            min: corner(0),
            max: corner(1),
        }
    }

    /// A node with no children yet: every lane an empty box.
    pub(crate) fn empty() -> Node {
        Node {
            bounds: [
                [f32x4::splat(f32::INFINITY); 3],
                [f32x4::splat(f32::NEG_INFINITY); 3],
            ],
            children: [Child(0); WIDTH],
            len: 0,
        }
    }
}

/// Stores `b` in lane `lane` of the node, rounded outward to `f32`.
pub(crate) fn set_lane(node: &mut Node, lane: usize, b: &Bounds) {
    for axis in 0..3 {
        let mut lo = node.bounds[0][axis].to_array();
        let mut hi = node.bounds[1][axis].to_array();
        lo[lane] = round_down(b.min[axis]);
        hi[lane] = round_up(b.max[axis]);
        node.bounds[0][axis] = f32x4::from(lo);
        node.bounds[1][axis] = f32x4::from(hi);
    }
}

/// The largest `f32` at most `x` (−∞ below the `f32` range).
pub(crate) fn round_down(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) > x { f.next_down() } else { f }
}

/// The smallest `f32` at least `x` (+∞ above the `f32` range).
pub(crate) fn round_up(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) < x { f.next_up() } else { f }
}
