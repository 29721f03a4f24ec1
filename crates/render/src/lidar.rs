//! Lidar: beams cast through the world's batched ray queries ([`behavior_sim::Query::cast_rays`]),
//! as points and as a range image.
//!
//! A planar scan is one fan of beams (Fetch's base laser: 220 beams over 220°, its robot says
//! where); a 3-D scan is rows of such fans at elevations spread over a vertical field of view.

use crate::error::RenderError;
use behavior_sim::{QueryFilter, World};
use rapier3d::math::{Pose, Rotation, Vector};
use serde::{Deserialize, Serialize};

/// Which beams a lidar casts, in its own frame (x forward, z up).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Pattern {
    /// One horizontal fan of `beams` over `fov` rad, centred ahead.
    Planar {
        /// Beams in the fan.
        beams: u32,
        /// Its opening, rad.
        fov: f32,
    },
    /// `rows` fans of `columns` beams all round (360°), at elevations evenly spread over
    /// `vertical_fov` rad centred on the horizon.
    MultiBeam {
        /// Fans, top first.
        rows: u32,
        /// Beams per fan, starting straight ahead and turning left.
        columns: u32,
        /// The spread of the fans' elevations, rad.
        vertical_fov: f32,
    },
}

/// A lidar: where it is, its beams and range.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Lidar {
    /// Its pose in the world (move it with its mount).
    pub pose: Pose,
    /// Its beams.
    pub pattern: Pattern,
    /// Hits closer than this are dropped, m.
    pub min_range: f32,
    /// Farthest hit, m.
    pub max_range: f32,
}

/// One scan.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Scan {
    /// Range image rows (1 for a planar lidar).
    pub rows: usize,
    /// Range image columns.
    pub columns: usize,
    /// Per beam, row-major: the distance to the first hit, m, or 0 for none within range.
    pub ranges: Vec<f32>,
    /// The hits, in the lidar's frame.
    pub points: Vec<[f32; 3]>,
}

impl Lidar {
    /// Its beams' directions in its own frame, row-major.
    pub fn directions(&self) -> (usize, usize, Vec<Vector>) {
        match self.pattern {
            Pattern::Planar { beams, fov } => {
                let n = beams.max(1);
                let dirs = (0..n)
                    .map(|i| {
                        let t = if n == 1 {
                            0.5
                        } else {
                            i as f32 / (n - 1) as f32
                        };
                        let yaw = -0.5 * fov + fov * t;
                        Vector::new(yaw.cos(), yaw.sin(), 0.0)
                    })
                    .collect();
                (1, n as usize, dirs)
            }
            Pattern::MultiBeam {
                rows,
                columns,
                vertical_fov,
            } => {
                let (rows, columns) = (rows.max(1), columns.max(1));
                let mut dirs = Vec::with_capacity((rows * columns) as usize);
                for r in 0..rows {
                    let t = if rows == 1 {
                        0.5
                    } else {
                        r as f32 / (rows - 1) as f32
                    };
                    let pitch = 0.5 * vertical_fov - vertical_fov * t;
                    for c in 0..columns {
                        let yaw = std::f32::consts::TAU * c as f32 / columns as f32;
                        let turn =
                            Rotation::from_rotation_z(yaw) * Rotation::from_rotation_y(-pitch);
                        dirs.push(turn * Vector::X);
                    }
                }
                (rows as usize, columns as usize, dirs)
            }
        }
    }

    /// Casts every beam; `filter` leaves out what the lidar must not see (its own robot).
    pub fn scan(&self, world: &World, filter: &QueryFilter) -> Result<Scan, RenderError> {
        let ok = self.pose.is_finite()
            && self.min_range.is_finite()
            && self.max_range.is_finite()
            && 0.0 <= self.min_range
            && self.min_range < self.max_range;
        if !ok {
            return Err(RenderError::BadCamera(format!(
                "a lidar needs a finite pose and 0 ≤ min range < max range (got {}–{} m)",
                self.min_range, self.max_range
            )));
        }
        let (rows, columns, directions) = self.directions();
        let origin = self.pose.translation;
        let rays: Vec<(Vector, Vector)> = directions
            .iter()
            .map(|d| (origin, self.pose.rotation * *d))
            .collect();
        let hits = world
            .query()
            .cast_rays(&rays, self.max_range, filter)
            .map_err(|e| RenderError::BadCamera(e.to_string()))?;
        let mut scan = Scan {
            rows,
            columns,
            ranges: Vec::with_capacity(hits.len()),
            points: Vec::new(),
        };
        for (hit, d) in hits.iter().zip(&directions) {
            match hit {
                Some(h) if h.distance >= self.min_range => {
                    scan.ranges.push(h.distance);
                    scan.points.push((*d * h.distance).to_array());
                }
                _ => scan.ranges.push(0.0),
            }
        }
        Ok(scan)
    }
}
