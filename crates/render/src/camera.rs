//! Cameras: where one stands, which way it looks, its image size and field of view, and the
//! matrices that take the world onto its image.
//!
//! A camera's frame is the robots' eye frame: it looks along its +x, with +y to the left of the
//! image and +z up. Pixels are counted from the top-left corner, x to the right, y down.

use crate::error::RenderError;
use behavior_sim::{BodyKind, World};
use rapier3d::glamx::{Mat4, Vec4};
use rapier3d::math::{Pose, Vector};
use serde::{Deserialize, Serialize};

/// The closest a camera sees, m.
pub const NEAR: f32 = 0.02;
/// The farthest a camera sees, m.
pub const FAR: f32 = 100.0;

/// The box around the world's fixed objects (a home's walls, floors and furniture), or `None`
/// for a world without any.
pub(crate) fn fixed_bounds(world: &World) -> Option<(Vector, Vector)> {
    let (lo, hi) = world
        .bodies()
        .objects()
        .filter(|(_, o)| o.is_present() && o.body_kind == BodyKind::Fixed)
        .map(|(id, _)| world.bodies().aabb(id))
        .fold(
            (Vector::splat(f32::MAX), Vector::splat(f32::MIN)),
            |(lo, hi), b| (lo.min(b.mins), hi.max(b.maxs)),
        );
    (lo.x <= hi.x).then_some((lo, hi))
}

/// A pinhole camera.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Camera {
    /// Where it is and which way it looks (its +x).
    pub pose: Pose,
    /// Image width, pixels.
    pub width: u32,
    /// Image height, pixels.
    pub height: u32,
    /// The vertical field of view, rad.
    pub vertical_fov: f32,
}

/// The BehaviorRobot's eye camera: 128 × 128 pixels, 120° vertically (iGibson 2.0.3's
/// `robots/behavior_robot.py`).
pub const EYE_SIZE: u32 = 128;
/// The eye camera's vertical field of view, rad (120°).
pub const EYE_FOV: f32 = 2.0 * std::f32::consts::FRAC_PI_3;

impl Camera {
    /// A camera at `pose` with the eye's defaults (128², 120°).
    pub fn eye(pose: Pose) -> Camera {
        Camera {
            pose,
            width: EYE_SIZE,
            height: EYE_SIZE,
            vertical_fov: EYE_FOV,
        }
    }

    /// A camera at `from` looking at `to`, with +z up in the image (a look straight down turns
    /// the image so that +x of the world points up).
    pub fn looking_at(
        from: Vector,
        to: Vector,
        width: u32,
        height: u32,
        vertical_fov: f32,
    ) -> Camera {
        let forward = (to - from).normalize_or(Vector::X);
        let up = if forward.cross(Vector::Z).length() < 1e-4 {
            Vector::X
        } else {
            Vector::Z
        };
        let left = up.cross(forward).normalize();
        let up = forward.cross(left);
        let rotation = rapier3d::math::Rotation::from_mat3(&rapier3d::glamx::Mat3::from_cols(
            forward, left, up,
        ));
        Camera {
            pose: Pose::from_parts(from, rotation),
            width,
            height,
            vertical_fov,
        }
    }

    /// A camera for people: above the middle of the world's fixed objects (a home's walls,
    /// floors and furniture), looking straight down with `vertical_fov`, far enough up to take
    /// them all in. Fails for a world with no fixed objects.
    pub fn overview(
        world: &World,
        width: u32,
        height: u32,
        vertical_fov: f32,
    ) -> Result<Camera, RenderError> {
        let fov = vertical_fov;
        let Some((lo, hi)) = fixed_bounds(world) else {
            return Err(RenderError::BadCamera(
                "an overview needs fixed objects to frame; the world has none".into(),
            ));
        };
        let centre = (lo + hi) * 0.5;
        // Looking down, the image's height spans the world's x and its width the world's y: the
        // half-height that takes in both.
        let aspect = width as f32 / height.max(1) as f32;
        let half = 0.5 * (hi.x - lo.x).max((hi.y - lo.y) / aspect);
        let from = Vector::new(centre.x, centre.y, hi.z + 1.05 * half / (0.5 * fov).tan());
        let camera = Camera::looking_at(
            from,
            Vector::new(centre.x, centre.y, 0.0),
            width,
            height,
            fov,
        );
        camera.check()?;
        Ok(camera)
    }

    /// Checks that it can be drawn from: a finite pose, a size of 1–8192 pixels each way, a
    /// field of view strictly between 0 and 180°.
    pub fn check(&self) -> Result<(), RenderError> {
        if !self.pose.is_finite() {
            return Err(RenderError::BadCamera("its pose is not finite".into()));
        }
        for (what, n) in [("width", self.width), ("height", self.height)] {
            if !(1..=8192).contains(&n) {
                return Err(RenderError::BadCamera(format!(
                    "its {what} is {n} pixels; it must be 1–8192"
                )));
            }
        }
        let fov = self.vertical_fov;
        if !(fov.is_finite() && fov > 0.0 && fov < std::f32::consts::PI) {
            return Err(RenderError::BadCamera(format!(
                "its vertical field of view is {fov} rad; it must be between 0 and π"
            )));
        }
        Ok(())
    }

    /// Width over height.
    pub fn aspect(&self) -> f32 {
        self.width as f32 / self.height as f32
    }

    /// World to camera frame (x forward, y left, z up).
    pub fn view(&self) -> Mat4 {
        let pose = self.pose.inverse();
        Mat4::from_rotation_translation(pose.rotation, pose.translation)
    }

    /// World to clip space (wgpu's: depth 0 at the near plane, 1 at the far one).
    pub fn view_projection(&self) -> Mat4 {
        // The camera frame to a right-handed view frame looking down −z with +y up.
        let to_view = Mat4::from_cols(
            Vec4::new(0.0, 0.0, -1.0, 0.0),
            Vec4::new(-1.0, 0.0, 0.0, 0.0),
            Vec4::new(0.0, 1.0, 0.0, 0.0),
            Vec4::W,
        );
        let projection = rapier3d::glamx::glam::camera::rh::proj::directx::perspective(
            self.vertical_fov,
            self.aspect(),
            NEAR,
            FAR,
        );
        projection * to_view * self.view()
    }

    /// Where a world point falls in the image, in pixels (x right, y down, the centre of the
    /// top-left pixel at (0.5, 0.5)), and its depth along the camera's x; `None` behind the
    /// camera.
    pub fn project(&self, point: Vector) -> Option<([f32; 2], f32)> {
        let depth = self.view().transform_point3(point).x;
        if depth <= 0.0 {
            return None;
        }
        let clip = self.view_projection() * point.extend(1.0);
        let ndc = clip.truncate() / clip.w;
        let x = (ndc.x + 1.0) * 0.5 * self.width as f32;
        let y = (1.0 - ndc.y) * 0.5 * self.height as f32;
        Some(([x, y], depth))
    }

    /// The world-frame direction through a pixel position (x right, y down, in pixels).
    pub fn ray(&self, pixel: [f32; 2]) -> Vector {
        let half = (0.5 * self.vertical_fov).tan();
        let u = (pixel[0] / self.width as f32) * 2.0 - 1.0;
        let v = 1.0 - (pixel[1] / self.height as f32) * 2.0;
        let local = Vector::new(1.0, -u * half * self.aspect(), v * half);
        (self.pose.rotation * local).normalize()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_ahead_is_in_the_middle_and_one_to_the_left_is_left() {
        let camera = Camera::eye(Pose::IDENTITY);
        let ([x, y], depth) = camera.project(Vector::new(2.0, 0.0, 0.0)).unwrap();
        assert!((x - 64.0).abs() < 1e-3 && (y - 64.0).abs() < 1e-3 && (depth - 2.0).abs() < 1e-6);
        let ([x, _], _) = camera.project(Vector::new(2.0, 0.5, 0.0)).unwrap();
        assert!(x < 64.0);
        let ([_, y], _) = camera.project(Vector::new(2.0, 0.0, 0.5)).unwrap();
        assert!(y < 64.0);
        assert!(camera.project(Vector::new(-1.0, 0.0, 0.0)).is_none());
    }

    #[test]
    fn a_pixel_ray_projects_back_onto_its_pixel() {
        let camera = Camera::looking_at(Vector::new(1.0, 2.0, 1.5), Vector::ZERO, 160, 90, 1.0);
        for pixel in [[0.5, 0.5], [80.0, 45.0], [159.5, 10.25]] {
            let point = camera.pose.translation + camera.ray(pixel) * 3.0;
            let (back, _) = camera.project(point).unwrap();
            assert!(
                (back[0] - pixel[0]).abs() < 1e-2 && (back[1] - pixel[1]).abs() < 1e-2,
                "{pixel:?} → {back:?}"
            );
        }
    }

    #[test]
    fn bad_cameras_are_refused_with_the_reason() {
        let mut camera = Camera::eye(Pose::IDENTITY);
        camera.width = 0;
        assert!(camera.check().unwrap_err().to_string().contains("width"));
        let mut camera = Camera::eye(Pose::IDENTITY);
        camera.vertical_fov = 4.0;
        assert!(
            camera
                .check()
                .unwrap_err()
                .to_string()
                .contains("field of view")
        );
    }
}
