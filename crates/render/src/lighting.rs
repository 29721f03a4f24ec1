//! The light of the realistic profile: a sun whose direction and colour are the home's, sky
//! and ground ambient, and a lamp under the ceiling of every room that lights that room only
//! (its walls would hide it from the others). The sun casts shadows, and so does the lamp of
//! the camera's room (its main light; the other rooms' lamps light what the camera sees of them
//! through doorways, unshadowed).

use behavior_sim::World;
use bytemuck::{Pod, Zeroable};
use rapier3d::glamx::Mat4;
use rapier3d::math::Vector;

/// At most this many lamps light a frame: those of the rooms nearest the camera.
pub(crate) const LAMPS: usize = 8;
/// What the light is multiplied by before tone mapping.
const EXPOSURE: f32 = 0.8;
/// A room's lamp hangs this high, m (the walls are 2.5 m).
const LAMP_HEIGHT: f32 = 2.3;

/// The light of one home.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Lighting {
    /// Toward the sun, unit.
    pub(crate) sun: Vector,
    /// Linear colour times intensity.
    pub(crate) sun_color: [f32; 3],
    /// Ambient light from above and from below.
    pub(crate) sky: [f32; 3],
    pub(crate) ground: [f32; 3],
    pub(crate) lamps: Vec<Lamp>,
}

/// A room's lamp.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Lamp {
    pub(crate) position: Vector,
    /// Linear colour times intensity.
    pub(crate) color: [f32; 3],
    /// The footprint it lights: min x, min y, max x, max y.
    pub(crate) room: [f32; 4],
}

/// A number in [0, 1) from a seed and a salt.
fn unit(seed: u64, salt: u64) -> f32 {
    let h = (seed ^ salt.wrapping_mul(0x9e37_79b9_7f4a_7c15)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    ((h >> 40) as f32) / (1u64 << 24) as f32
}

impl Lighting {
    /// The light of a home of seed `seed` ([`crate::finish::home_seed`]): the sun 25–60° high from any side, warmer the
    /// lower it is; lamps of a warm white, brighter in bigger rooms.
    pub(crate) fn of(world: &World, seed: u64) -> Lighting {
        let elevation = (25.0 + 35.0 * unit(seed, 1)).to_radians();
        let azimuth = if seed == 0 {
            0.6
        } else {
            std::f32::consts::TAU * unit(seed, 2)
        };
        let sun = Vector::new(
            elevation.cos() * azimuth.cos(),
            elevation.cos() * azimuth.sin(),
            elevation.sin(),
        );
        // Low suns are warmer: from a late-afternoon gold to a midday white.
        let warmth = 1.0 - (elevation.to_degrees() - 25.0) / 35.0;
        let sun_color = [1.0, 0.95 - 0.1 * warmth, 0.88 - 0.2 * warmth].map(|c| 2.2 * c);
        let lamps = world
            .rooms()
            .iter()
            // A lamp over each rectangle of a room (an L-shaped room's alcove has its own).
            .flat_map(|r| r.rects())
            .map(|r| {
                let area = r.area();
                let centre = Vector::new(
                    0.5 * (r.min[0] + r.max[0]),
                    0.5 * (r.min[1] + r.max[1]),
                    LAMP_HEIGHT,
                );
                let intensity = 0.8 + 0.05 * area.min(30.0);
                Lamp {
                    position: centre,
                    color: [1.0, 0.86, 0.68].map(|c| c * intensity),
                    room: [
                        r.min[0] - 0.1,
                        r.min[1] - 0.1,
                        r.max[0] + 0.1,
                        r.max[1] + 0.1,
                    ],
                }
            })
            .collect();
        Lighting {
            sun,
            sun_color,
            sky: [0.34, 0.40, 0.50],
            ground: [0.24, 0.21, 0.18],
            lamps,
        }
    }
}

/// What `realistic.wgsl` calls `Lights`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct LightsUniform {
    pub(crate) camera_to_world: [[f32; 4]; 4],
    pub(crate) static_shadow: [[f32; 4]; 4],
    pub(crate) dynamic_shadow: [[f32; 4]; 4],
    pub(crate) sky_shadow: [[f32; 4]; 4],
    /// World to the main lamp's map (a perspective view down from the lamp).
    pub(crate) lamp_shadow: [[f32; 4]; 4],
    pub(crate) sun: [f32; 4],
    pub(crate) sun_color: [f32; 4],
    pub(crate) sky: [f32; 4],
    pub(crate) ground: [f32; 4],
    /// x, y, z, w: whether the sky map, the static map, the dynamic one and the lamp's hold
    /// anything (the shader runs over all eight lamps, unused ones lighting an empty footprint;
    /// the first is the main lamp).
    pub(crate) counts: [u32; 4],
    pub(crate) lamp_position: [[f32; 4]; LAMPS],
    pub(crate) lamp_color: [[f32; 4]; LAMPS],
    pub(crate) lamp_room: [[f32; 4]; LAMPS],
    /// x: how much of the materials' normal detail is drawn (1 or 0); y, z, w: padding.
    pub(crate) detail: [f32; 4],
}

/// How the shadow maps see the world this frame.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct ShadowMatrices {
    /// World to the static map's clip space, if it holds anything.
    pub(crate) fixed: Option<Mat4>,
    /// World to the dynamic map's, if it holds anything.
    pub(crate) moving: Option<Mat4>,
    /// World to the sky map's (the fixed geometry seen from above), if it holds anything.
    pub(crate) sky: Option<Mat4>,
    /// World to the main lamp's map, if it holds anything.
    pub(crate) lamp: Option<Mat4>,
}

impl Lighting {
    /// The lamp of the room the camera at `eye` is in (the first whose footprint holds it), or
    /// the nearest where it is in none: the one whose shadows are drawn.
    pub(crate) fn main_lamp(&self, eye: Vector) -> Option<&Lamp> {
        let inside = |l: &&Lamp| {
            let r = l.room;
            (r[0]..=r[2]).contains(&eye.x) && (r[1]..=r[3]).contains(&eye.y)
        };
        self.lamps.iter().find(inside).or_else(|| {
            self.lamps.iter().min_by(|a, b| {
                let d = |l: &Lamp| (l.position - eye).length_squared();
                d(a).total_cmp(&d(b))
            })
        })
    }

    /// The uniform for a camera at `eye` whose frame maps to the world by `camera_to_world`.
    pub(crate) fn uniform(
        &self,
        camera_to_world: Mat4,
        eye: Vector,
        shadows: ShadowMatrices,
    ) -> LightsUniform {
        // The main lamp first (its shadows are drawn), then the others, nearest first.
        let mut nearest: Vec<&Lamp> = self.lamps.iter().collect();
        nearest.sort_by(|a, b| {
            let d = |l: &Lamp| (l.position - eye).length_squared();
            d(a).total_cmp(&d(b))
        });
        if let Some(main) = self.main_lamp(eye)
            && let Some(k) = nearest.iter().position(|&l| std::ptr::eq(l, main))
        {
            nearest[..=k].rotate_right(1);
        }
        nearest.truncate(LAMPS);
        let mut u = LightsUniform {
            camera_to_world: camera_to_world.to_cols_array_2d(),
            static_shadow: shadows.fixed.unwrap_or(Mat4::IDENTITY).to_cols_array_2d(),
            dynamic_shadow: shadows.moving.unwrap_or(Mat4::IDENTITY).to_cols_array_2d(),
            sky_shadow: shadows.sky.unwrap_or(Mat4::IDENTITY).to_cols_array_2d(),
            lamp_shadow: shadows.lamp.unwrap_or(Mat4::IDENTITY).to_cols_array_2d(),
            sun: self.sun.extend(0.0).to_array(),
            sun_color: [self.sun_color[0], self.sun_color[1], self.sun_color[2], 0.0],
            sky: [self.sky[0], self.sky[1], self.sky[2], EXPOSURE],
            ground: [self.ground[0], self.ground[1], self.ground[2], 0.0],
            counts: [
                u32::from(shadows.sky.is_some()),
                u32::from(shadows.fixed.is_some()),
                u32::from(shadows.moving.is_some()),
                u32::from(shadows.lamp.is_some()),
            ],
            lamp_position: [[0.0; 4]; LAMPS],
            lamp_color: [[0.0; 4]; LAMPS],
            // An empty footprint (min above max): a lamp not in use lights nothing.
            lamp_room: [[1.0, 1.0, -1.0, -1.0]; LAMPS],
            detail: [1.0, 0.0, 0.0, 0.0],
        };
        for (k, lamp) in nearest.iter().enumerate() {
            u.lamp_position[k] = lamp.position.extend(1.0).to_array();
            u.lamp_color[k] = [lamp.color[0], lamp.color[1], lamp.color[2], 0.0];
            u.lamp_room[k] = lamp.room;
        }
        u
    }
}
