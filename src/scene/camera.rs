//! The lecture's camera: an eye, an orthonormal frame (u right, v up, n backward),
//! an image plane at `n = -N` with half-sizes `W` and `H`, and `N_c × N_r` pixels.
//!
//! Two pixel conventions meet here, and are converted in one place,
//! [`Camera::pixel_ray`]:
//! - **lecture coordinates** `(c, r)`: column `c` from the left, row `r` from the
//!   *bottom*; the point `(u_c, v_r)` is where the lecture's ray goes;
//! - **image coordinates** `(x, y)`: `x = c` to the right, `y` down from the *top*
//!   row, as image files, viewers, `raytree trace --pixel` and the renderer use.
//!   So `y = N_r - 1 - r`.
//!
//! **Where samples fall.** The lecture's point `(u_c, v_r)` is the *center* of pixel
//! `(c, r)`: a pixel covers `c ± ½` by `r ± ½` in continuous lecture coordinates.
//! One sample per pixel traces exactly the lecture's ray; `n × n` stratified
//! supersampling traces the centers of an `n × n` grid of equal cells inside that
//! square ([`stratum_offset`]), which for `n = 1` is the lecture's point again.

use glam::DVec3;

use crate::math::ray::Ray;

/// How a scene gives its camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CameraSpec {
    /// Eye, look-at point, up vector and horizontal field of view; the frame and
    /// `W` follow from them, and `H` from the image's aspect so pixels are square.
    LookAt {
        /// Eye position.
        eye: DVec3,
        /// The point seen at the image's center.
        look_at: DVec3,
        /// Which way is up (need not be perpendicular to the view).
        up: DVec3,
        /// Horizontal field of view in degrees, between the outermost pixel centers.
        fov_degrees: f64,
    },
    /// The lecture's parameters given directly.
    Frame {
        /// Eye position.
        eye: DVec3,
        /// Unit vector to the right.
        u: DVec3,
        /// Unit vector up.
        v: DVec3,
        /// Unit vector backward (the camera looks along -n).
        n: DVec3,
        /// Half-width `W` of the image plane.
        half_width: f64,
        /// Half-height `H` of the image plane.
        half_height: f64,
        /// Distance `N` from the eye to the image plane.
        distance: f64,
    },
}

/// A camera ready to make rays for an image of a given size.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Eye position.
    pub eye: DVec3,
    /// Right.
    pub u: DVec3,
    /// Up.
    pub v: DVec3,
    /// Backward.
    pub n: DVec3,
    /// `W`.
    pub half_width: f64,
    /// `H`.
    pub half_height: f64,
    /// `N`.
    pub distance: f64,
    /// `N_c`, the image width in pixels.
    pub columns: u32,
    /// `N_r`, the image height in pixels.
    pub rows: u32,
}

impl Camera {
    /// The camera of `spec` for an image of `columns × rows` pixels.
    pub fn new(spec: &CameraSpec, columns: u32, rows: u32) -> Self {
        match *spec {
            CameraSpec::LookAt {
                eye,
                look_at,
                up,
                fov_degrees,
            } => {
                let n = (eye - look_at).normalize();
                let u = up.cross(n).normalize();
                let v = n.cross(u);
                let distance = 1.0;
                let half_width = distance * (fov_degrees.to_radians() / 2.0).tan();
                // Equal spacing horizontally and vertically: 2W/(N_c-1) = 2H/(N_r-1).
                let spacing = 2.0 * half_width / f64::from(columns.saturating_sub(1).max(1));
                let half_height = spacing * f64::from(rows.saturating_sub(1)) / 2.0;
                Camera {
                    eye,
                    u,
                    v,
                    n,
                    half_width,
                    half_height,
                    distance,
                    columns,
                    rows,
                }
            }
            CameraSpec::Frame {
                eye,
                u,
                v,
                n,
                half_width,
                half_height,
                distance,
            } => Camera {
                eye,
                u,
                v,
                n,
                half_width,
                half_height,
                distance,
                columns,
                rows,
            },
        }
    }

    /// The lecture's `(u_c, v_r) = (-W + W·2c/(N_c-1), -H + H·2r/(N_r-1))`, for
    /// continuous `c` and `r` (a one-pixel-wide or -high image has its one
    /// center at 0).
    pub fn plane_coords(&self, c: f64, r: f64) -> (f64, f64) {
        (
            lecture_coord(c, self.half_width, self.columns),
            lecture_coord(r, self.half_height, self.rows),
        )
    }

    /// The world point `eye - N·n + u_c·u + v_r·v` on the image plane.
    pub fn plane_point(&self, c: f64, r: f64) -> DVec3 {
        let (uc, vr) = self.plane_coords(c, r);
        self.eye - self.distance * self.n + uc * self.u + vr * self.v
    }

    /// The lecture's `ray(r, c, t) = eye + t·(P(r, c) - eye)`, in lecture
    /// coordinates (row 0 at the bottom). `t = 1` is on the image plane.
    pub fn lecture_ray(&self, c: f64, r: f64) -> Ray {
        Ray::new(self.eye, self.plane_point(c, r) - self.eye)
    }

    /// The ray through image coordinates `(x, y)` (row 0 at the top); integers
    /// are pixel centers. The one conversion between the two conventions.
    pub fn pixel_ray(&self, x: f64, y: f64) -> Ray {
        self.lecture_ray(x, f64::from(self.rows) - 1.0 - y)
    }
}

fn lecture_coord(i: f64, half: f64, count: u32) -> f64 {
    if count > 1 {
        -half + half * 2.0 * i / f64::from(count - 1)
    } else {
        2.0 * half * i
    }
}

/// The offset from a pixel's center to the center of stratum `i` of `n` along one
/// axis: `(i + ½)/n - ½`, in pixels.
pub fn stratum_offset(i: u32, n: u32) -> f64 {
    (f64::from(i) + 0.5) / f64::from(n) - 0.5
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(columns: u32, rows: u32) -> Camera {
        let spec = CameraSpec::Frame {
            eye: DVec3::new(0.0, 0.0, 5.0),
            u: DVec3::X,
            v: DVec3::Y,
            n: DVec3::Z,
            half_width: 2.0,
            half_height: 1.0,
            distance: 3.0,
        };
        Camera::new(&spec, columns, rows)
    }

    #[test]
    fn pixel_coordinates_follow_the_lecture() {
        // N_c = 5, W = 2: u_c = -2 + 2·2c/4 = -2, -1, 0, 1, 2.
        // N_r = 3, H = 1: v_r = -1 + 1·2r/2 = -1, 0, 1.
        let cam = frame(5, 3);
        let us: Vec<f64> = (0..5)
            .map(|c| cam.plane_coords(f64::from(c), 0.0).0)
            .collect();
        assert_eq!(us, [-2.0, -1.0, 0.0, 1.0, 2.0]);
        let vs: Vec<f64> = (0..3)
            .map(|r| cam.plane_coords(0.0, f64::from(r)).1)
            .collect();
        assert_eq!(vs, [-1.0, 0.0, 1.0]);
    }

    #[test]
    fn ray_through_pixel_follows_the_lecture() {
        // Pixel (r = 0, c = 4): P = eye - N·n + u_c·u + v_r·v = (0,0,5) - 3z + 2x - y
        // = (2, -1, 2); the ray's direction is P - eye = (2, -1, -3).
        let cam = frame(5, 3);
        let ray = cam.lecture_ray(4.0, 0.0);
        assert_eq!(ray.origin, DVec3::new(0.0, 0.0, 5.0));
        assert_eq!(ray.dir, DVec3::new(2.0, -1.0, -3.0));
        assert_eq!(ray.at(1.0), DVec3::new(2.0, -1.0, 2.0));
    }

    #[test]
    fn image_row_zero_is_the_lecture_top_row() {
        let cam = frame(5, 3);
        // Image (x = 4, y = 0) is the top-right pixel: lecture (c = 4, r = 2), v_r = +1.
        assert_eq!(cam.pixel_ray(4.0, 0.0), cam.lecture_ray(4.0, 2.0));
        assert_eq!(cam.pixel_ray(4.0, 0.0).dir.y, 1.0);
        assert_eq!(cam.pixel_ray(0.0, 2.0), cam.lecture_ray(0.0, 0.0));
    }

    #[test]
    fn look_at_builds_a_right_handed_frame_with_square_pixels() {
        let spec = CameraSpec::LookAt {
            eye: DVec3::new(0.0, 0.0, 5.0),
            look_at: DVec3::ZERO,
            up: DVec3::Y,
            fov_degrees: 90.0,
        };
        let cam = Camera::new(&spec, 101, 51);
        assert!(
            (cam.u - DVec3::X).length() < 1e-15
                && (cam.v - DVec3::Y).length() < 1e-15
                && (cam.n - DVec3::Z).length() < 1e-15
        );
        // fov 90°, N = 1: W = tan 45° = 1, spacing 2/100, H = 0.02·50/2 = 0.5.
        assert!((cam.half_width - 1.0).abs() < 1e-15 && (cam.half_height - 0.5).abs() < 1e-15);
        // The center pixel looks straight at the look-at point.
        let center = cam.pixel_ray(50.0, 25.0);
        assert!(center.dir.normalize().abs_diff_eq(DVec3::NEG_Z, 1e-15));
    }

    #[test]
    fn strata_are_centered_in_the_pixel() {
        assert_eq!(stratum_offset(0, 1), 0.0);
        assert_eq!([stratum_offset(0, 2), stratum_offset(1, 2)], [-0.25, 0.25]);
        let thirds: Vec<f64> = (0..3).map(|i| stratum_offset(i, 3)).collect();
        assert!(
            (thirds[0] + 1.0 / 3.0).abs() < 1e-15
                && thirds[1] == 0.0
                && (thirds[2] - 1.0 / 3.0).abs() < 1e-15
        );
    }
}
