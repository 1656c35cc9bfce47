//! The render settings a scene file's `render` block and the command line may
//! set: one struct for both, read by serde from the file and by clap from the
//! flags, so a new setting is one field in [`RenderSettings`] and one line here.
//!
//! This is the one file of the scene model that names clap, by design: the
//! flags are these fields.

use serde::{Deserialize, Serialize};

use crate::methods::{Accel, Antialiasing, Level, Offset, SphereMethod, TriangleMethod, Weights};
use crate::scene::settings::RenderSettings;

/// Declares [`Overrides`], one `Option` per listed setting, and its `apply`,
/// which puts each given value in place; listing a setting once here is all
/// it takes (the field's doc comment is its `--help` line).
macro_rules! overrides {
    ($($(#[$attr:meta])* $field:ident: $ty:ty,)*) => {
        /// Settings to change; a field left out keeps the value it is applied to.
        /// Each field has the name and type of its [`RenderSettings`] field,
        /// wrapped in `Option` (a test checks the two structs stay in step).
        #[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize, clap::Args)]
        #[serde(deny_unknown_fields)]
        pub struct Overrides {
            $(
                $(#[$attr])*
                #[serde(skip_serializing_if = "Option::is_none")]
                pub $field: Option<$ty>,
            )*
        }

        impl Overrides {
            /// `settings` with every field given here put in its place.
            pub fn apply(&self, settings: &RenderSettings) -> RenderSettings {
                let mut out = *settings;
                $(
                    if let Some(value) = self.$field {
                        out.$field = value;
                    }
                )*
                out
            }
        }
    };
}

overrides! {
    /// Image width in pixels, 1 to 32768, and at most 67108864 pixels (8192×8192) with the height [default: 640, or the scene's own].
    #[arg(long, value_name = "W", value_parser = side, allow_negative_numbers = true)]
    width: u32,
    /// Image height in pixels, 1 to 32768, and at most 67108864 pixels (8192×8192) with the width [default: 480, or the scene's own].
    #[arg(long, value_name = "H", value_parser = side, allow_negative_numbers = true)]
    height: u32,
    /// Samples per pixel, a square number up to 1024 (1, 4, 9, 16, …) for an n×n stratified grid [default: 1].
    #[arg(long, value_name = "N", value_parser = spp, allow_negative_numbers = true)]
    spp: u32,
    /// Deepest ray traced, 1 to 1000: 1 traces only primary rays [default: 8].
    #[arg(long, value_name = "D", value_parser = max_depth, allow_negative_numbers = true)]
    max_depth: u32,
    /// Skip reflected and refracted rays whose weight (product of coefficients) is below this, from 0 up to (not including) 1; 0 turns it off [default: 0.0009765625, 1/1024].
    #[arg(long, value_name = "W", value_parser = cutoff, allow_negative_numbers = true)]
    cutoff: f64,
    /// Ray–sphere intersection: the lecture's quadratic as written, or the stable form [default: stable].
    #[arg(long, value_enum)]
    sphere: SphereMethod,
    /// Where secondary rays start: none (at the hit: acne), epsilon=E (E along the normal), robust [default: robust].
    #[arg(long, value_name = "none|robust|epsilon=E")]
    offset: Offset,
    /// Reflection/refraction weights of transparent surfaces: constant k_rfl/k_rfa, Schlick, or Fresnel [default: constant].
    #[arg(long, value_enum)]
    weights: Weights,
    /// Anti-aliasing: grid (the --spp grid; --spp is refused with the others), corners (one ray through each pixel corner, four averaged to a pixel: the SPD protocol's) or adaptive corner subdivision (Whitted 1980) with an optional threshold in linear RGB (adaptive alone: 0.05) [default: grid].
    #[arg(long, value_name = "grid|corners|adaptive[=T]")]
    aa: Antialiasing,
    /// Ray–triangle intersection: Woop et al.'s watertight test, or the textbook Möller–Trumbore [default: watertight].
    #[arg(long, value_enum)]
    triangle: TriangleMethod,
    /// Acceleration: none (test every object), bvh (a bounding volume hierarchy), grid (a uniform voxel grid), octree, bsp (a k-d tree), auto (a hierarchy from 16 bounded objects up) [default: auto].
    #[arg(long, value_enum)]
    accel: Accel,
    /// With --accel grid only (refused under the others and under auto, which never builds a grid): cells along the scene's longest side, 1 to 160, the other sides in proportion; auto gives about four cells an object [default: auto].
    #[arg(long, value_name = "auto|N")]
    grid_res: Level,
    /// With --accel octree or bsp only (refused under the others and under auto, which never builds a tree): the tree's deepest level, 0 (one leaf) to 48; auto is 10 for the octree, 8 + 1.3·log₂(objects) for the k-d tree [default: auto].
    #[arg(long, value_name = "auto|D")]
    tree_depth: Level,
}

// The numeric flags' parsers: any number is read, so that a value out of
// range, a negative one too, is refused with the rule the scene file's field
// is held to, not with the limits of the integer type.

fn whole(s: &str) -> Result<i128, String> {
    s.trim()
        .parse()
        .map_err(|_| format!("'{s}' is not a whole number"))
}

fn side(s: &str) -> Result<u32, String> {
    let n = whole(s)?;
    RenderSettings::side_rule(n).map(|()| n as u32)
}

fn spp(s: &str) -> Result<u32, String> {
    let n = whole(s)?;
    RenderSettings::spp_rule(n).map(|()| n as u32)
}

fn max_depth(s: &str) -> Result<u32, String> {
    let n = whole(s)?;
    RenderSettings::max_depth_rule(n).map(|()| n as u32)
}

fn cutoff(s: &str) -> Result<f64, String> {
    let c: f64 = (s.trim().parse()).map_err(|_| format!("'{s}' is not a number"))?;
    RenderSettings::cutoff_rule(c).map(|()| c)
}

/// A benchmark's fixed way of rendering, so that counts and times compare
/// with the ones it publishes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Protocol {
    /// Eric Haines's Standard Procedural Databases (1987).
    //
    // 512×512 pixels, rays through the 513×513 pixel corners (four averaged to
    // a pixel), a maximum depth of 5 (the eye ray is depth 1), no weight
    // cutoff, and Fresnel weights, so that every hit on a transmitting surface
    // spawns a reflected ray too (as the protocol asks, also where the
    // material's own reflection coefficient is 0).
    Spd,
}

impl Protocol {
    /// The settings the protocol fixes, as overrides: flags given beside it
    /// are applied after them, and win.
    pub fn overrides(self) -> Overrides {
        match self {
            Protocol::Spd => Overrides {
                width: Some(512),
                height: Some(512),
                aa: Some(Antialiasing::Corners),
                max_depth: Some(5),
                cutoff: Some(0.0),
                weights: Some(Weights::Fresnel),
                ..Overrides::default()
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Settings with every field away from its default.
    fn unusual() -> RenderSettings {
        RenderSettings {
            width: 33,
            height: 21,
            spp: 9,
            max_depth: 3,
            cutoff: 0.125,
            sphere: SphereMethod::Lecture,
            offset: Offset::Epsilon(0.25),
            weights: Weights::Fresnel,
            aa: Antialiasing::Adaptive {
                threshold: 0.5,
                levels: 2,
            },
            triangle: TriangleMethod::MollerTrumbore,
            accel: Accel::Bvh,
            grid_res: Level::Given(7),
            tree_depth: Level::Given(3),
        }
    }

    #[test]
    fn every_setting_has_an_override_and_each_applies() {
        // Reading the settings' own JSON as overrides fails on a setting that has
        // no override (unknown field); applying them must give every value back.
        let json = serde_json::to_value(unusual()).unwrap();
        let all: Overrides = serde_json::from_value(json).unwrap();
        assert_eq!(all.apply(&RenderSettings::default()), unusual());
        // And an override with no setting would not serialize back into one.
        let back: RenderSettings = serde_json::from_value(serde_json::to_value(all).unwrap())
            .expect("every override names a setting");
        assert_eq!(back, unusual());
    }

    #[test]
    fn fields_left_out_keep_their_value() {
        let only = Overrides {
            spp: Some(4),
            ..Overrides::default()
        };
        let s = only.apply(&unusual());
        assert_eq!(
            s,
            RenderSettings {
                spp: 4,
                ..unusual()
            }
        );
        assert_eq!(Overrides::default().apply(&unusual()), unusual());
    }

    /// The defaults `--help` states are the settings' own (the scene's
    /// `render` block may set others; the help says what raytree falls back to).
    #[test]
    fn the_help_states_the_settings_defaults() {
        use clap::{Args, Command};
        let command = Overrides::augment_args(Command::new("render"));
        let defaults = serde_json::to_value(RenderSettings::default()).unwrap();
        let mut stated = 0;
        for arg in command.get_arguments() {
            let help = arg.get_help().map(|h| h.to_string()).unwrap_or_default();
            let Some((_, rest)) = help.split_once("[default: ") else {
                continue;
            };
            let value = rest.split([',', ']']).next().unwrap();
            let field = arg.get_id().as_str();
            let want = match &defaults[field] {
                serde_json::Value::String(s) => s.clone(),
                serde_json::Value::Object(o) => o.keys().next().unwrap().clone(),
                v => v.to_string(),
            };
            assert_eq!(value, want, "--{field}'s help");
            stated += 1;
        }
        assert!(stated >= 9, "only {stated} flags state their default");
    }
}
