//! Building the bounding volume hierarchy of [`crate::geometry::structures::bvh`], top-down
//! with the binned surface area heuristic (Wald, "On fast Construction of
//! SAH-based Bounding Volume Hierarchies", 2007; pbrt-v4 §7.3.2): each split is
//! the one of [`BINS`] candidate planes along the widest axis of the centroids
//! that minimizes the expected cost of a random ray, and a group stays a leaf
//! when no split is expected to pay for its extra box test. A node's up to four
//! children come from splitting its largest group again until there are four.
//! Subtrees over many primitives are built on all cores (rayon), and so are the
//! first splits' passes over all the primitives.

use glam::DVec3;

use crate::geometry::structures::bvh::node::{
    Child, MAX_LEAF, MAX_PRIMITIVES, Node, WIDTH, set_lane,
};
use crate::math::bounds::Bounds;

/// Candidate split planes per split.
pub const BINS: usize = 16;
/// Cost of a box test relative to a primitive test, for the heuristic.
const TRAVERSAL_COST: f64 = 0.5;
/// Subtrees over at least this many primitives are built on other threads.
const PARALLEL_MIN: usize = 8192;
/// Passes over at least this many primitives (binning them) run on all cores.
const PARALLEL_PASS: usize = 8 * PARALLEL_MIN;
/// Below this depth the heuristic's splits are taken; deeper, the median's, so a
/// pathological scene cannot make the tree (and a traversal's stack) deep.
pub(crate) const SAH_DEPTH_LIMIT: u32 = 32;

/// A primitive while building: its box and its box's center.
#[derive(Clone, Copy)]
struct Item {
    bounds: Bounds,
    centroid: DVec3,
    index: u32,
}

/// Where a group splits (relative to its start) and the boxes of its two halves.
#[derive(Clone, Copy)]
struct Split {
    mid: usize,
    halves: [Bounds; 2],
}

/// A run of items that will become one child.
#[derive(Clone, Copy)]
struct Group {
    start: usize,
    end: usize,
    bounds: Bounds,
    /// How the group splits, or `None`: it is a leaf.
    split: Option<Split>,
}

/// The tree's nodes (the root first), the primitives leaf by leaf, and the box
/// around everything.
pub(crate) fn build(bounds: &[Bounds]) -> (Vec<Node>, Vec<u32>, Bounds) {
    assert!(
        bounds.len() < MAX_PRIMITIVES,
        "a hierarchy holds fewer than 2²⁸ primitives"
    );
    let mut items: Vec<Item> = bounds
        .iter()
        .enumerate()
        .map(|(i, b)| Item {
            bounds: *b,
            centroid: b.center(),
            index: i as u32,
        })
        .collect();
    let mut nodes = Vec::with_capacity(bounds.len() / 2 + 1);
    let all = union(&items);
    if !items.is_empty() {
        let root = Group {
            start: 0,
            end: items.len(),
            bounds: all,
            split: split(&mut items, &all, 0),
        };
        build_node(&mut items, 0, root, 0, &mut nodes);
    }
    (nodes, items.iter().map(|it| it.index).collect(), all)
}

/// The box around the items.
fn union(items: &[Item]) -> Bounds {
    items.iter().fold(Bounds::EMPTY, |b, it| b.union(it.bounds))
}

/// Builds the node over `items` (which start at `first` in the whole list, and
/// are the group `whole`, already split) and its subtree into `nodes`; returns
/// its index there.
fn build_node(
    items: &mut [Item],
    first: usize,
    whole: Group,
    depth: u32,
    nodes: &mut Vec<Node>,
) -> usize {
    let at = nodes.len();
    nodes.push(Node::empty());
    let groups = widest_groups(items, whole, depth);
    let mut children = [Child(0); WIDTH];
    // Inner children: built here one after the other, or on other threads when large.
    let mut inner: Vec<(usize, &mut [Item], usize, Group)> = Vec::new();
    let mut rest = &mut items[..];
    let mut consumed = 0;
    for (lane, g) in groups.iter().enumerate() {
        let (slice, tail) = std::mem::take(&mut rest).split_at_mut(g.end - consumed);
        let slice = &mut slice[g.start - consumed..];
        rest = tail;
        consumed = g.end;
        match g.split {
            None => children[lane] = Child::leaf(first + g.start, g.end - g.start),
            Some(_) => inner.push((
                lane,
                slice,
                first + g.start,
                Group {
                    start: 0,
                    end: g.end - g.start,
                    ..*g
                },
            )),
        }
    }
    let parallel = inner.iter().filter(|c| c.1.len() >= PARALLEL_MIN).count() > 1;
    if parallel {
        use rayon::prelude::*;
        let subtrees: Vec<(usize, Vec<Node>)> = inner
            .into_par_iter()
            .map(|(lane, slice, start, g)| {
                let mut sub = Vec::with_capacity(slice.len() / 2);
                build_node(slice, start, g, depth + 1, &mut sub);
                (lane, sub)
            })
            .collect();
        for (lane, sub) in subtrees {
            let base = nodes.len();
            nodes.extend(sub.into_iter().map(|mut node| {
                for c in &mut node.children[..usize::from(node.len)] {
                    if !c.is_leaf() {
                        c.0 += base as u32;
                    }
                }
                node
            }));
            children[lane] = Child::inner(base);
        }
    } else {
        for (lane, slice, start, g) in inner {
            children[lane] = Child::inner(build_node(slice, start, g, depth + 1, nodes));
        }
    }
    let node = &mut nodes[at];
    node.children = children;
    node.len = groups.len() as u8;
    for (lane, g) in groups.iter().enumerate() {
        set_lane(node, lane, &g.bounds);
    }
    at
}

/// Splits `items` into up to four groups: the whole (already split), then again
/// and again the group of largest surface area that the heuristic splits. The
/// groups come out in the order of `items`, which they partition; each knows
/// its own split, so its node need not look for it again.
fn widest_groups(items: &mut [Item], whole: Group, depth: u32) -> Vec<Group> {
    let mut groups = vec![whole];
    while groups.len() < WIDTH {
        let Some(k) = (0..groups.len())
            .filter(|&k| groups[k].split.is_some())
            .max_by(|&a, &b| groups[a].bounds.area().total_cmp(&groups[b].bounds.area()))
        else {
            break;
        };
        let g = groups[k];
        let Split { mid, halves } = g.split.expect("filtered");
        let mid = g.start + mid;
        let halves =
            [(g.start, mid, halves[0]), (mid, g.end, halves[1])].map(|(start, end, b)| Group {
                start,
                end,
                bounds: b,
                split: split(&mut items[start..end], &b, depth + 1),
            });
        groups.splice(k..=k, halves);
    }
    groups
}

/// How `items` (partitioned in place) split in two, or `None` when they should
/// stay one leaf.
fn split(items: &mut [Item], bounds: &Bounds, depth: u32) -> Option<Split> {
    let centroids = centroid_bounds(items);
    let extent = centroids.max - centroids.min;
    let axis = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    let split = if items.len() == 1 || extent[axis] <= 0.0 {
        // One primitive, or all centered on one point: no plane separates them.
        None
    } else if depth < SAH_DEPTH_LIMIT {
        sah_split(items, bounds, &centroids, axis)
    } else {
        Some(median_split(items, axis))
    };
    match split {
        Some(split) => Some(split),
        None if items.len() <= MAX_LEAF => None,
        // Too many to keep together: halve by centroid so leaves stay small.
        None => Some(median_split(items, axis)),
    }
}

/// The box around the items' centroids, on all cores for many items.
fn centroid_bounds(items: &[Item]) -> Bounds {
    let one = |items: &[Item]| Bounds::around(items.iter().map(|it| it.centroid));
    if items.len() < PARALLEL_PASS {
        return one(items);
    }
    use rayon::prelude::*;
    items
        .par_chunks(PARALLEL_MIN)
        .map(one)
        .reduce(|| Bounds::EMPTY, Bounds::union)
}

/// How many items fall in each bin, and the box around each bin's items, on
/// all cores for many items.
fn binned(
    items: &[Item],
    bin_of: impl Fn(DVec3) -> usize + Sync,
) -> ([usize; BINS], [Bounds; BINS]) {
    let one = |items: &[Item]| {
        let mut count = [0usize; BINS];
        let mut boxes = [Bounds::EMPTY; BINS];
        for it in items {
            let b = bin_of(it.centroid);
            count[b] += 1;
            boxes[b] = boxes[b].union(it.bounds);
        }
        (count, boxes)
    };
    if items.len() < PARALLEL_PASS {
        return one(items);
    }
    use rayon::prelude::*;
    items.par_chunks(PARALLEL_MIN).map(one).reduce(
        || ([0; BINS], [Bounds::EMPTY; BINS]),
        |(mut count, mut boxes), (c, b)| {
            for i in 0..BINS {
                count[i] += c[i];
                boxes[i] = boxes[i].union(b[i]);
            }
            (count, boxes)
        },
    )
}

/// Halves `items` by centroid along `axis`.
fn median_split(items: &mut [Item], axis: usize) -> Split {
    let mid = items.len() / 2;
    items.select_nth_unstable_by(mid, |a, b| a.centroid[axis].total_cmp(&b.centroid[axis]));
    Split {
        mid,
        halves: [union(&items[..mid]), union(&items[mid..])],
    }
}

/// How `items` (partitioned in place) split at the binned SAH's best plane
/// along `axis`, or `None` when a leaf is expected to be cheaper. The halves'
/// boxes come from the bins' boxes, with no second pass over the items.
fn sah_split(
    items: &mut [Item],
    bounds: &Bounds,
    centroids: &Bounds,
    axis: usize,
) -> Option<Split> {
    let lo = centroids.min[axis];
    let scale = BINS as f64 / (centroids.max[axis] - lo);
    let bin_of = |c: DVec3| (((c[axis] - lo) * scale) as usize).min(BINS - 1);
    let (count, boxes) = binned(items, bin_of);
    // Cost of splitting after bin i: sweep from the right, then from the left.
    let mut right = [(0.0, Bounds::EMPTY); BINS];
    let (mut acc, mut n) = (Bounds::EMPTY, 0);
    for i in (1..BINS).rev() {
        acc = acc.union(boxes[i]);
        n += count[i];
        right[i - 1] = (n as f64 * acc.area(), acc);
    }
    let (mut acc, mut n) = (Bounds::EMPTY, 0);
    let mut best = (f64::INFINITY, 0, Bounds::EMPTY);
    for i in 0..BINS - 1 {
        acc = acc.union(boxes[i]);
        n += count[i];
        let cost = n as f64 * acc.area() + right[i].0;
        if n > 0 && n < items.len() && cost < best.0 {
            best = (cost, i, acc);
        }
    }
    let area = bounds.area();
    let split_cost = TRAVERSAL_COST + best.0 / area;
    let leaf_cost = items.len() as f64;
    if best.0.is_infinite() || (items.len() <= MAX_LEAF && split_cost >= leaf_cost) {
        return None;
    }
    let mut mid = 0;
    for i in 0..items.len() {
        if bin_of(items[i].centroid) <= best.1 {
            items.swap(i, mid);
            mid += 1;
        }
    }
    Some(Split {
        mid,
        halves: [best.2, right[best.1].1],
    })
}
