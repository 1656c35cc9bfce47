//! The scene file's `camera` block, checked into a [`CameraSpec`]: a look-at
//! camera, or the lecture's own frame, which must be right-handed.
//!
//! Errors name the field at fault: `(field, message)`, e.g.
//! `("camera.n", "…")`; the loader adds the file.

use glam::DVec3;

use crate::scene::camera::CameraSpec;
use crate::scene::format::CameraFile;
use crate::scene::limits;

/// A field's path and what is wrong with it.
pub(super) type FieldError = (String, String);

fn at(field: &str, message: impl Into<String>) -> FieldError {
    (format!("camera.{field}"), message.into())
}

/// The camera of a scene file.
pub(super) fn spec(c: &CameraFile) -> Result<CameraSpec, FieldError> {
    let eye =
        limits::point(c.eye.unwrap_or(DVec3::new(0.0, 0.0, 5.0))).map_err(|e| at("eye", e))?;
    let frame_given = c.u.is_some()
        || c.v.is_some()
        || c.n.is_some()
        || c.half_width.is_some()
        || c.half_height.is_some()
        || c.distance.is_some();
    if !frame_given {
        return look_at(eye, c);
    }
    if c.look_at.is_some() || c.up.is_some() || c.fov.is_some() {
        return Err((
            "camera".to_owned(),
            "give either look_at/up/fov or u/v/n/half_width/half_height/distance, not both"
                .to_owned(),
        ));
    }
    frame(eye, c)
}

/// A camera given by eye, look-at point, up and field of view.
fn look_at(eye: DVec3, c: &CameraFile) -> Result<CameraSpec, FieldError> {
    let look_at = limits::point(c.look_at.unwrap_or(DVec3::ZERO)).map_err(|e| at("look_at", e))?;
    let up = limits::point(c.up.unwrap_or(DVec3::Y)).map_err(|e| at("up", e))?;
    let fov = c.fov.unwrap_or(60.0);
    if (look_at - eye).length() == 0.0 {
        return Err(at("look_at", "must differ from camera.eye"));
    }
    if up.cross(look_at - eye).length() <= 1e-9 * up.length() * (look_at - eye).length() {
        return Err(at(
            "up",
            "must not be zero or parallel to the view direction",
        ));
    }
    let (low, high) = limits::FOV;
    if !(low..=high).contains(&fov) {
        return Err(at(
            "fov",
            format!(
                "must be from {low} to {high} degrees, got {}",
                limits::num(fov)
            ),
        ));
    }
    Ok(CameraSpec::LookAt {
        eye,
        look_at,
        up,
        fov_degrees: fov,
    })
}

/// A camera given by the lecture's own parameters: u, v, n, W, H and N.
/// The frame must be right-handed (`u × v = n`, as the look-at camera makes it):
/// a left-handed one would silently mirror the image left to right.
fn frame(eye: DVec3, c: &CameraFile) -> Result<CameraSpec, FieldError> {
    let missing = "missing (an explicit camera needs u, v, n, half_width and half_height)";
    let unit = |v: Option<DVec3>, name: &str| {
        let v = v.ok_or_else(|| at(name, missing))?;
        limits::direction(v).map_err(|e| at(name, e))
    };
    let (u, v, n) = (unit(c.u, "u")?, unit(c.v, "v")?, unit(c.n, "n")?);
    if u.dot(v).abs() > 1e-6 || u.dot(n).abs() > 1e-6 || v.dot(n).abs() > 1e-6 {
        return Err((
            "camera".to_owned(),
            "u, v and n must be mutually perpendicular".to_owned(),
        ));
    }
    if u.cross(v).dot(n) < 0.0 {
        return Err(at(
            "n",
            "makes a left-handed frame (u × v = -n), which would mirror the image: turn n around, or swap u for -u",
        ));
    }
    let length = |x: Option<f64>, name: &str, default: Option<f64>| {
        let x = x.or(default).ok_or_else(|| at(name, missing))?;
        limits::length(x).map_err(|e| at(name, e))
    };
    Ok(CameraSpec::Frame {
        eye,
        u,
        v,
        n,
        half_width: length(c.half_width, "half_width", None)?,
        half_height: length(c.half_height, "half_height", None)?,
        distance: length(c.distance, "distance", Some(1.0))?,
    })
}
