//! Occlusion culling on the CPU: big upright boxes (walls, doors, the sides of furniture) hide
//! what lies wholly behind them, and what they hide is not sent to the GPU.
//!
//! From a robot's eye in one room of a home, most of the home is in the 120° frustum but behind
//! walls; drawing it costs a CPU rasterizer (lavapipe) most of a frame. The test is conservative,
//! so culling never changes a pixel: a coarse grid over the image holds, per cell, a depth
//! beyond which the cell is certainly hidden, set only where one box covers the whole cell. Its
//! corners' rays all entering the box mean every ray of the cell does (the rays that meet a
//! convex body form a convex set), and the depth at which a ray enters a box is a convex
//! function over the image, so the corners' deepest entry bounds the whole cell's. A shape is
//! culled when the ball that holds it lies, in every cell its projection may touch, beyond that
//! depth by a margin.
//!
//! Depths are along the camera's forward axis (its x).

use crate::camera::{Camera, NEAR};
use rapier3d::math::{Pose, Vector};

/// Cells across and down the image.
const GRID: usize = 24;
/// A box nearer to the camera than this is not an occluder (the GPU clips what lies closer
/// than [`NEAR`], and a camera inside a box does not draw it), m.
const CLEARANCE: f32 = 0.1;
/// A box occludes only when it is an upright panel whose two largest half extents are at least
/// this, m: small boxes hide little, and floors and table tops hide only what is under them,
/// while covering much of the image (each covered grid corner costs a ray).
const MIN_HALF_EXTENT: f32 = 0.2;
/// How far behind an occluder a shape must be to be culled: this plus [`MARGIN_PER_METRE`] of
/// its depth (the GPU's depth buffer rounds), m.
const MARGIN: f32 = 0.01;
const MARGIN_PER_METRE: f32 = 0.002;

/// A corner whose ray has not been cast yet.
const UNCAST: f32 = -1.0;

/// The hidden-beyond depth of each cell of one frame.
pub(crate) struct Occlusion {
    /// The camera's pose, and the world-to-camera transform.
    pose: Pose,
    view: Pose,
    /// Half the image's height and width at 1 m ahead, m.
    half: [f32; 2],
    /// The ray through grid corner (0, 0) in the camera's frame, 1 m forward, and its change
    /// from one corner to the next across and down: corner (i, j)'s is `ray + i·across +
    /// j·down`.
    ray: Vector,
    across: Vector,
    down: Vector,
    /// Per cell, row by row: the depth beyond which it is hidden (infinite where open).
    beyond: Vec<f32>,
    /// Scratch: entry depths at grid corners of one box.
    corners: Vec<f32>,
}

/// A rectangle of grid corners, inclusive.
#[derive(Clone, Copy)]
struct Span {
    x: (usize, usize),
    y: (usize, usize),
}

impl Occlusion {
    /// An empty grid (nothing hidden) for `camera`.
    pub(crate) fn new(camera: &Camera) -> Occlusion {
        let height = (0.5 * camera.vertical_fov).tan();
        let half = [height, height * camera.aspect()];
        let step = 2.0 / GRID as f32;
        Occlusion {
            pose: camera.pose,
            view: camera.pose.inverse(),
            half,
            ray: Vector::new(1.0, half[1], half[0]),
            across: Vector::new(0.0, -step * half[1], 0.0),
            down: Vector::new(0.0, 0.0, -step * half[0]),
            beyond: vec![f32::INFINITY; GRID * GRID],
            corners: Vec::new(),
        }
    }

    /// Whether a box of these half extents at `pose` is worth adding: an upright panel (a
    /// wall, a door, a cabinet's side), big enough.
    pub(crate) fn worth(pose: &Pose, half_extents: Vector) -> bool {
        let [a, b, c] = half_extents.to_array();
        let (smallest, largest) = (a.min(b).min(c), a.max(b).max(c));
        let thin = if smallest == a {
            Vector::X
        } else if smallest == b {
            Vector::Y
        } else {
            Vector::Z
        };
        let upright = (pose.rotation * thin).z.abs() < 0.5;
        upright && a + b + c - smallest - largest >= MIN_HALF_EXTENT
    }

    /// Adds an opaque box that is drawn: centred at `pose`, of `half_extents`.
    pub(crate) fn add_box(&mut self, pose: &Pose, half_extents: Vector) {
        // The box's frame seen from the camera's: rays start at `origin` in the box's frame.
        let to_box = pose.inverse() * self.pose;
        let origin = to_box.translation;
        let outside = (origin.abs() - half_extents).max(Vector::ZERO);
        if outside.length() < CLEARANCE {
            return;
        }
        let Some((span, nearest)) = self.span_of_box(pose, half_extents) else {
            return;
        };
        let columns = span.x.1 - span.x.0 + 1;
        let [ray, across, down] = [self.ray, self.across, self.down].map(|v| to_box.rotation * v);
        // Corner entries are cast when a cell needs them: one already hidden nearer than any
        // point of this box does not.
        self.corners.clear();
        self.corners
            .resize(columns * (span.y.1 - span.y.0 + 1), UNCAST);
        for j in span.y.0..span.y.1 {
            for i in span.x.0..span.x.1 {
                if self.beyond[j * GRID + i] <= nearest {
                    continue;
                }
                let mut entries = [0.0; 4];
                for (k, (di, dj)) in [(0, 0), (1, 0), (0, 1), (1, 1)].into_iter().enumerate() {
                    let (ci, cj) = (i + di, j + dj);
                    let slot = &mut self.corners[(cj - span.y.0) * columns + (ci - span.x.0)];
                    if *slot == UNCAST {
                        let direction = ray + across * ci as f32 + down * cj as f32;
                        *slot = enter(origin, direction, half_extents).unwrap_or(f32::NAN);
                    }
                    entries[k] = *slot;
                }
                // A corner whose ray misses the box (NaN) leaves the cell as it was.
                if entries.iter().any(|d| d.is_nan()) {
                    continue;
                }
                let deepest = entries.into_iter().fold(0.0, f32::max);
                let cell = &mut self.beyond[j * GRID + i];
                *cell = cell.min(deepest);
            }
        }
    }

    /// Whether the ball at `centre` of `radius` is certainly hidden.
    pub(crate) fn hides(&self, centre: Vector, radius: f32) -> bool {
        let c = self.view.transform_point(centre);
        let nearest = c.x - radius;
        if nearest <= NEAR {
            return false;
        }
        let corners = cube_corners(c, Vector::splat(radius));
        let Some(span) = self.span_of(&corners) else {
            // Out of the image: the frustum test's business, not ours.
            return false;
        };
        let margin = MARGIN + MARGIN_PER_METRE * nearest;
        (span.y.0..span.y.1.max(span.y.0 + 1)).all(|j| {
            (span.x.0..span.x.1.max(span.x.0 + 1))
                .all(|i| self.beyond[j.min(GRID - 1) * GRID + i.min(GRID - 1)] + margin < nearest)
        })
    }

    /// The grid corners around a box's image (of its part in front of the near plane, when it
    /// reaches behind it), and the least depth of any of its points.
    fn span_of_box(&self, pose: &Pose, half_extents: Vector) -> Option<(Span, f32)> {
        let corners = cube_corners(Vector::ZERO, half_extents)
            .map(|p| self.view.transform_point(pose.transform_point(p)));
        let nearest = corners.iter().map(|p| p.x).fold(f32::INFINITY, f32::min);
        if nearest > NEAR {
            return Some((self.span_of(&corners)?, nearest));
        }
        // Clip: the corners in front, and where the edges cross the plane just in front of the
        // near one (corner indices differ in one bit along an edge).
        let plane = 2.0 * NEAR;
        let mut kept = Vec::with_capacity(12);
        kept.extend(corners.iter().copied().filter(|p| p.x >= plane));
        for a in 0..8 {
            for bit in [1, 2, 4] {
                let b = a | bit;
                let (p, q) = (corners[a], corners[b]);
                if b != a && (p.x < plane) != (q.x < plane) {
                    kept.push(p + (q - p) * ((plane - p.x) / (q.x - p.x)));
                }
            }
        }
        if kept.is_empty() {
            return None;
        }
        Some((self.span_of(&kept)?, nearest))
    }

    /// The grid corners around the image of points in the camera's frame; `None` when it misses
    /// the image.
    fn span_of(&self, points: &[Vector]) -> Option<Span> {
        if points.iter().any(|p| p.x <= NEAR) {
            return Some(Span {
                x: (0, GRID),
                y: (0, GRID),
            });
        }
        let (mut lo, mut hi) = ([f32::MAX; 2], [f32::MIN; 2]);
        for p in points {
            // Grid units: u to the right, v down.
            let u = (-p.y / (p.x * self.half[1]) + 1.0) * 0.5 * GRID as f32;
            let v = (1.0 - p.z / (p.x * self.half[0])) * 0.5 * GRID as f32;
            lo = [lo[0].min(u), lo[1].min(v)];
            hi = [hi[0].max(u), hi[1].max(v)];
        }
        let n = GRID as f32;
        if hi[0] < 0.0 || hi[1] < 0.0 || lo[0] > n || lo[1] > n {
            return None;
        }
        let clamp = |x: f32| x.clamp(0.0, n) as usize;
        Some(Span {
            x: (clamp(lo[0].floor()), clamp(hi[0].ceil())),
            y: (clamp(lo[1].floor()), clamp(hi[1].ceil())),
        })
    }
}

/// The eight corners of a box around `centre`.
fn cube_corners(centre: Vector, half: Vector) -> [Vector; 8] {
    std::array::from_fn(|k| {
        let sign = |bit: usize| if k >> bit & 1 == 1 { 1.0 } else { -1.0 };
        centre + Vector::new(sign(0) * half.x, sign(1) * half.y, sign(2) * half.z)
    })
}

/// Where a ray from `origin` along `direction` enters the box of `half` extents at the origin
/// (slab test), as a multiple of `direction`; `None` if it misses or starts inside.
fn enter(origin: Vector, direction: Vector, half: Vector) -> Option<f32> {
    let (mut near, mut far) = (f32::NEG_INFINITY, f32::INFINITY);
    for k in 0..3 {
        let (o, d, h) = (origin[k], direction[k], half[k]);
        if d.abs() < 1e-12 {
            if o.abs() > h {
                return None;
            }
            continue;
        }
        let (a, b) = ((-h - o) / d, (h - o) / d);
        near = near.max(a.min(b));
        far = far.min(a.max(b));
    }
    (near <= far && near > 0.0).then_some(near)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera() -> Camera {
        Camera::eye(Pose::IDENTITY)
    }

    /// A wall 3 m ahead, 4 m wide and tall.
    fn wall() -> (Pose, Vector) {
        (
            Pose::from_translation(Vector::new(3.0, 0.0, 0.0)),
            Vector::new(0.05, 2.0, 2.0),
        )
    }

    #[test]
    fn a_wall_hides_what_is_behind_it_and_not_what_is_before_or_beside_it() {
        let mut occlusion = Occlusion::new(&camera());
        let (pose, half) = wall();
        occlusion.add_box(&pose, half);
        assert!(occlusion.hides(Vector::new(4.0, 0.0, 0.0), 0.2));
        assert!(!occlusion.hides(Vector::new(2.0, 0.0, 0.0), 0.2));
        // Behind the wall but peeking past its edge.
        assert!(!occlusion.hides(Vector::new(4.0, 2.6, 0.0), 0.4));
        // Behind its front face by less than the margin (the GPU's depth buffer may round).
        assert!(!occlusion.hides(Vector::new(2.955, 0.0, 0.0), 0.0));
        assert!(occlusion.hides(Vector::new(3.06, 0.0, 0.0), 0.0));
    }

    #[test]
    fn boxes_that_are_small_near_or_around_the_camera_hide_nothing() {
        let upright = Pose::IDENTITY;
        assert!(!Occlusion::worth(&upright, Vector::new(0.1, 0.1, 2.0)));
        assert!(Occlusion::worth(&upright, Vector::new(0.01, 0.5, 2.0)));
        // A floor.
        assert!(!Occlusion::worth(&upright, Vector::new(2.0, 3.0, 0.05)));
        let mut occlusion = Occlusion::new(&camera());
        occlusion.add_box(&Pose::IDENTITY, Vector::splat(1.0));
        occlusion.add_box(
            &Pose::from_translation(Vector::new(1.05, 0.0, 0.0)),
            Vector::new(1.0, 1.0, 1.0),
        );
        assert!(!occlusion.hides(Vector::new(5.0, 0.0, 0.0), 0.1));
    }
}
