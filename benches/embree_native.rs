//! Embree 4's side of `benches/embree/native.sh`, called natively: no Python
//! binding between the timer and `rtcIntersect1`.
//!
//! ```text
//! embree_native LIB check
//! embree_native LIB mesh DIR SET [--passes P]
//! embree_native LIB spheres DIR N [--passes P]
//! ```
//!
//! LIB is Embree 4's shared library (`libembree4.so.4`; `native.sh` takes the
//! one inside the embreex wheel), loaded at run time: no Embree headers are
//! needed, the few functions and structures used are declared below from
//! Embree 4's documented C API. The device runs on one thread
//! (`threads=1`), every scene has the flag `RTC_SCENE_FLAG_ROBUST` and
//! Embree's default build quality.
//!
//! `check` casts known rays at one triangle and two spheres and fails unless
//! Embree reports the known `t`, primitive and geometry (the structure layouts
//! below are right); `mesh` and `spheres` run it first too.
//!
//! `mesh` reads `closest_hit export`'s triangles and the ray set SET
//! (`primary`, `random` or `inside`) from DIR; `spheres` reads
//! `closest_hit spheres export`'s N spheres and their rays, as one user
//! geometry whose bounds and intersect callbacks are raytree's sphere in f64
//! (`Sphere::roots`, the same test per sphere as raytree's own loop, so the
//! two sides differ in the hierarchy and its traversal). Embree's rays are
//! single precision: origin and direction rounded to f32. Each prints
//! `seconds=<fastest of P passes (default 3)> rays=<n> hits=<n> t_sum=<Σ t>`,
//! like `closest_hit time`.

use std::ffi::{CStr, c_char, c_void};
use std::path::Path;
use std::time::Instant;

use glam::DVec3;
use raytree::geometry::sphere::Sphere;
use raytree::math::ray::Ray;

type Handle = *mut c_void;

/// `RTC_SCENE_FLAG_ROBUST`: no ray slips through a shared edge, at some cost.
const SCENE_FLAG_ROBUST: i32 = 1 << 2;
const GEOMETRY_TYPE_TRIANGLE: i32 = 0;
const GEOMETRY_TYPE_USER: i32 = 120;
const BUFFER_TYPE_INDEX: i32 = 0;
const BUFFER_TYPE_VERTEX: i32 = 1;
const FORMAT_UINT3: i32 = 0x5003;
const FORMAT_FLOAT3: i32 = 0x9003;
const INVALID_ID: u32 = u32::MAX;
const PROPERTY_VERSION: i32 = 0;
const PROPERTY_USER_GEOMETRY_SUPPORTED: i32 = 100;
const PROPERTY_TASKING_SYSTEM: i32 = 128;

/// `RTCRayHit`: `RTCRay` (48 bytes) then `RTCHit`. The hit ends in arrays whose
/// length depends on how the library was built (`instID` for each instance
/// level, and `instPrimID` in builds with instance arrays): `inst` leaves room
/// for 8 levels of each, more than any build writes.
#[repr(C, align(16))]
#[derive(Clone, Copy)]
#[allow(
    dead_code,
    reason = "Embree's fields, whether or not this file reads them"
)]
struct RayHit {
    org: [f32; 3],
    tnear: f32,
    dir: [f32; 3],
    time: f32,
    tfar: f32,
    mask: u32,
    id: u32,
    flags: u32,
    ng: [f32; 3],
    u: f32,
    v: f32,
    prim_id: u32,
    geom_id: u32,
    inst: [u32; 16],
}

impl RayHit {
    fn new(ray: &Ray) -> Self {
        let f = |v: DVec3| [v.x as f32, v.y as f32, v.z as f32];
        RayHit {
            org: f(ray.origin),
            tnear: 0.0,
            dir: f(ray.dir),
            time: 0.0,
            tfar: f32::INFINITY,
            mask: u32::MAX,
            id: 0,
            flags: 0,
            ng: [0.0; 3],
            u: 0.0,
            v: 0.0,
            prim_id: INVALID_ID,
            geom_id: INVALID_ID,
            inst: [INVALID_ID; 16],
        }
    }
}

/// `RTCBounds`.
#[repr(C, align(16))]
#[allow(
    dead_code,
    reason = "Embree's fields, whether or not this file reads them"
)]
struct Bounds {
    lower: [f32; 3],
    align0: f32,
    upper: [f32; 3],
    align1: f32,
}

/// `RTCBoundsFunctionArguments`.
#[repr(C)]
#[allow(
    dead_code,
    reason = "Embree's fields, whether or not this file reads them"
)]
struct BoundsArgs {
    user: *mut c_void,
    prim_id: u32,
    time_step: u32,
    bounds: *mut Bounds,
}

/// `RTCIntersectFunctionNArguments` (Embree 4: the context is an
/// `RTCRayQueryContext*`, and the geometry's ID comes last).
#[repr(C)]
#[allow(
    dead_code,
    reason = "Embree's fields, whether or not this file reads them"
)]
struct IntersectArgs {
    valid: *const i32,
    user: *mut c_void,
    prim_id: u32,
    context: *mut c_void,
    rayhit: *mut f32,
    n: u32,
    geom_id: u32,
}

/// The Embree 4 functions used, looked up in the library at run time.
struct Embree {
    release_device: unsafe extern "C" fn(Handle),
    device_error: unsafe extern "C" fn(Handle) -> i32,
    set_error_function:
        unsafe extern "C" fn(Handle, extern "C" fn(*mut c_void, i32, *const c_char), *mut c_void),
    device_property: unsafe extern "C" fn(Handle, i32) -> isize,
    new_scene: unsafe extern "C" fn(Handle) -> Handle,
    release_scene: unsafe extern "C" fn(Handle),
    set_scene_flags: unsafe extern "C" fn(Handle, i32),
    new_geometry: unsafe extern "C" fn(Handle, i32) -> Handle,
    set_new_buffer: unsafe extern "C" fn(Handle, i32, u32, i32, usize, usize) -> *mut c_void,
    set_user_data: unsafe extern "C" fn(Handle, *mut c_void),
    set_primitive_count: unsafe extern "C" fn(Handle, u32),
    set_bounds_function:
        unsafe extern "C" fn(Handle, unsafe extern "C" fn(*const BoundsArgs), *mut c_void),
    set_intersect_function:
        unsafe extern "C" fn(Handle, unsafe extern "C" fn(*const IntersectArgs)),
    commit_geometry: unsafe extern "C" fn(Handle),
    attach_geometry: unsafe extern "C" fn(Handle, Handle) -> u32,
    release_geometry: unsafe extern "C" fn(Handle),
    commit_scene: unsafe extern "C" fn(Handle),
    intersect1: unsafe extern "C" fn(Handle, *mut RayHit, *mut c_void),
    device: Handle,
    // Never closed: TBB's worker threads, started by Embree, may still be
    // running the library's code as the process ends, and crash if it is
    // unloaded under them.
    _library: std::mem::ManuallyDrop<libloading::Library>,
}

extern "C" fn report_error(_: *mut c_void, code: i32, message: *const c_char) {
    let text = if message.is_null() {
        String::new()
    } else {
        // SAFETY: Embree passes a NUL-terminated message that lives for the call.
        unsafe { CStr::from_ptr(message) }
            .to_string_lossy()
            .into_owned()
    };
    eprintln!("embree error {code}: {text}");
}

impl Embree {
    fn load(path: &Path) -> Embree {
        // SAFETY: loading Embree runs its initializers, which are sound; each
        // symbol is given the signature Embree 4's headers declare for it.
        unsafe {
            let library = libloading::Library::new(path)
                .unwrap_or_else(|e| fail(&format!("{}: {e}", path.display())));
            macro_rules! get {
                ($name:literal) => {
                    *library
                        .get(concat!($name, "\0").as_bytes())
                        .unwrap_or_else(|e| fail(&format!("{}: {e}", $name)))
                };
            }
            let new_device: unsafe extern "C" fn(*const c_char) -> Handle = get!("rtcNewDevice");
            let device = new_device(c"threads=1".as_ptr());
            if device.is_null() {
                fail("rtcNewDevice failed");
            }
            let embree = Embree {
                release_device: get!("rtcReleaseDevice"),
                device_error: get!("rtcGetDeviceError"),
                set_error_function: get!("rtcSetDeviceErrorFunction"),
                device_property: get!("rtcGetDeviceProperty"),
                new_scene: get!("rtcNewScene"),
                release_scene: get!("rtcReleaseScene"),
                set_scene_flags: get!("rtcSetSceneFlags"),
                new_geometry: get!("rtcNewGeometry"),
                set_new_buffer: get!("rtcSetNewGeometryBuffer"),
                set_user_data: get!("rtcSetGeometryUserData"),
                set_primitive_count: get!("rtcSetGeometryUserPrimitiveCount"),
                set_bounds_function: get!("rtcSetGeometryBoundsFunction"),
                set_intersect_function: get!("rtcSetGeometryIntersectFunction"),
                commit_geometry: get!("rtcCommitGeometry"),
                attach_geometry: get!("rtcAttachGeometry"),
                release_geometry: get!("rtcReleaseGeometry"),
                commit_scene: get!("rtcCommitScene"),
                intersect1: get!("rtcIntersect1"),
                device,
                _library: std::mem::ManuallyDrop::new(library),
            };
            (embree.set_error_function)(device, report_error, std::ptr::null_mut());
            embree
        }
    }

    /// Fails on any error the device has recorded since the last call.
    fn check(&self, what: &str) {
        // SAFETY: the device is alive.
        let code = unsafe { (self.device_error)(self.device) };
        if code != 0 {
            fail(&format!("{what}: embree error {code}"));
        }
    }

    fn property(&self, property: i32) -> isize {
        // SAFETY: the device is alive; an unknown property is an error, not UB.
        unsafe { (self.device_property)(self.device, property) }
    }

    /// A new robust scene.
    fn scene(&self) -> Handle {
        // SAFETY: the device is alive.
        let scene = unsafe { (self.new_scene)(self.device) };
        // SAFETY: the scene was just made.
        unsafe { (self.set_scene_flags)(scene, SCENE_FLAG_ROBUST) };
        self.check("new scene");
        scene
    }

    /// Adds the triangles, one vertex per corner as given, as one mesh.
    fn add_triangles(&self, scene: Handle, corners: &[f32]) -> u32 {
        let count = corners.len() / 9;
        // SAFETY: Embree allocates both buffers with the sizes asked for (and
        // padding of its own); the copies write exactly those sizes.
        unsafe {
            let geometry = (self.new_geometry)(self.device, GEOMETRY_TYPE_TRIANGLE);
            let vertices = (self.set_new_buffer)(
                geometry,
                BUFFER_TYPE_VERTEX,
                0,
                FORMAT_FLOAT3,
                12,
                3 * count,
            );
            let indices =
                (self.set_new_buffer)(geometry, BUFFER_TYPE_INDEX, 0, FORMAT_UINT3, 12, count);
            self.check("triangle buffers");
            std::ptr::copy_nonoverlapping(corners.as_ptr(), vertices.cast::<f32>(), 9 * count);
            let index: Vec<u32> = (0..3 * count as u32).collect();
            std::ptr::copy_nonoverlapping(index.as_ptr(), indices.cast::<u32>(), 3 * count);
            self.attach(scene, geometry)
        }
    }

    /// Adds the spheres as one user geometry; they must outlive the scene.
    fn add_spheres(&self, scene: Handle, spheres: &[Sphere]) -> u32 {
        // SAFETY: the callbacks read the slice through the user pointer, and
        // the caller keeps it alive and unmoved as long as the scene.
        unsafe {
            let geometry = (self.new_geometry)(self.device, GEOMETRY_TYPE_USER);
            let user = Box::into_raw(Box::new(spheres));
            (self.set_primitive_count)(geometry, spheres.len() as u32);
            (self.set_user_data)(geometry, user.cast());
            (self.set_bounds_function)(geometry, sphere_bounds, user.cast());
            (self.set_intersect_function)(geometry, sphere_intersect);
            self.attach(scene, geometry)
        }
    }

    fn attach(&self, scene: Handle, geometry: Handle) -> u32 {
        // SAFETY: both are alive; the scene keeps its own reference.
        let id = unsafe {
            (self.commit_geometry)(geometry);
            let id = (self.attach_geometry)(scene, geometry);
            (self.release_geometry)(geometry);
            id
        };
        self.check("geometry");
        id
    }

    fn commit(&self, scene: Handle) {
        // SAFETY: the scene is alive, its geometries committed.
        unsafe { (self.commit_scene)(scene) };
        self.check("rtcCommitScene");
    }

    /// The closest hit: `(t, primitive, geometry)`.
    #[inline(always)]
    fn intersect(&self, scene: Handle, ray: &mut RayHit) -> Option<(f32, u32, u32)> {
        // SAFETY: the scene is committed; `ray` has room for any build's hit.
        unsafe { (self.intersect1)(scene, ray, std::ptr::null_mut()) };
        (ray.geom_id != INVALID_ID).then_some((ray.tfar, ray.prim_id, ray.geom_id))
    }
}

impl Drop for Embree {
    fn drop(&mut self) {
        // SAFETY: every scene is released before; nothing uses the device after.
        unsafe { (self.release_device)(self.device) };
    }
}

unsafe extern "C" fn sphere_bounds(args: *const BoundsArgs) {
    // SAFETY: Embree passes valid arguments; the user pointer is `add_spheres`'s.
    unsafe {
        let args = &*args;
        let spheres: &[Sphere] = *args.user.cast::<&[Sphere]>();
        let s = spheres[args.prim_id as usize];
        // Rounded outward, so the f32 box holds the whole f64 sphere.
        let lower = s.center - DVec3::splat(s.radius);
        let upper = s.center + DVec3::splat(s.radius);
        *args.bounds = Bounds {
            lower: lower.to_array().map(|x| (x as f32).next_down()),
            align0: 0.0,
            upper: upper.to_array().map(|x| (x as f32).next_up()),
            align1: 0.0,
        };
    }
}

/// Raytree's sphere test for each valid ray of the packet (one ray, from
/// `rtcIntersect1`), reporting a hit as Embree's own primitives do: `tfar`
/// shortened to it, and the hit written (the `N`-wide layout: field `k` of
/// ray `i` at `k·N + i`, the hit after the ray's 12 fields).
unsafe extern "C" fn sphere_intersect(args: *const IntersectArgs) {
    // SAFETY: Embree passes valid arguments and a ray-and-hit packet of `n` rays.
    unsafe {
        let args = &*args;
        let spheres: &[Sphere] = *args.user.cast::<&[Sphere]>();
        let sphere = spheres[args.prim_id as usize];
        let n = args.n as usize;
        let field = |k: usize, i: usize| args.rayhit.add(k * n + i);
        for i in 0..n {
            if *args.valid.add(i) == 0 {
                continue;
            }
            let at = |k: usize| f64::from(*field(k, i));
            let ray = Ray::new(
                DVec3::new(at(0), at(1), at(2)),
                DVec3::new(at(4), at(5), at(6)),
            );
            let Some(t) = sphere.roots(&ray).first_in(at(3), at(8)) else {
                continue;
            };
            *field(8, i) = t as f32;
            let hit = |k: usize| field(12 + k, i);
            for k in 0..5 {
                *hit(k) = 0.0;
            }
            *hit(5).cast::<u32>() = args.prim_id;
            *hit(6).cast::<u32>() = args.geom_id;
            // No instances: the first level's instance ID stays invalid.
            *hit(7).cast::<u32>() = INVALID_ID;
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| a != "--bench")
        .collect();
    let passes = args
        .iter()
        .position(|a| a == "--passes")
        .and_then(|i| args.get(i + 1))
        .map_or(3, |v| {
            v.parse()
                .unwrap_or_else(|_| fail(&format!("--passes: {v}")))
        });
    let words: Vec<&str> = args
        .iter()
        .enumerate()
        .filter(|&(i, a)| !a.starts_with("--") && (i == 0 || !args[i - 1].starts_with("--")))
        .map(|(_, a)| a.as_str())
        .collect();
    match words.as_slice() {
        [lib, "check"] => {
            let embree = Embree::load(Path::new(lib));
            self_check(&embree);
            println!(
                "embree={} tasking={} user_geometry={} ok",
                version(embree.property(PROPERTY_VERSION)),
                embree.property(PROPERTY_TASKING_SYSTEM),
                embree.property(PROPERTY_USER_GEOMETRY_SUPPORTED)
            );
        }
        [lib, "mesh", dir, set] => {
            let embree = Embree::load(Path::new(lib));
            self_check(&embree);
            let corners: Vec<f32> = std::fs::read(Path::new(dir).join("triangles.f32"))
                .unwrap_or_else(|e| fail(&format!("{dir}/triangles.f32: {e}")))
                .chunks_exact(4)
                .map(|b| f32::from_le_bytes(b.try_into().expect("4 bytes")))
                .collect();
            let scene = embree.scene();
            embree.add_triangles(scene, &corners);
            embree.commit(scene);
            cast(
                &embree,
                scene,
                &rays(&Path::new(dir).join(format!("{set}.f64"))),
                passes,
            );
            // SAFETY: nothing uses the scene after.
            unsafe { (embree.release_scene)(scene) };
        }
        [lib, "spheres", dir, n] => {
            let embree = Embree::load(Path::new(lib));
            self_check(&embree);
            let spheres: Vec<Sphere> = doubles(&Path::new(dir).join(format!("spheres-{n}.f64")))
                .chunks_exact(4)
                .map(|v| Sphere {
                    center: DVec3::new(v[0], v[1], v[2]),
                    radius: v[3],
                })
                .collect();
            let scene = embree.scene();
            embree.add_spheres(scene, &spheres);
            embree.commit(scene);
            let rays = rays(&Path::new(dir).join(format!("spheres-{n}-rays.f64")));
            cast(&embree, scene, &rays, passes);
            // SAFETY: nothing uses the scene after (the spheres outlive it).
            unsafe { (embree.release_scene)(scene) };
        }
        // `cargo test --benches` runs every bench target once: nothing to do.
        _ if args.is_empty() || args.iter().any(|a| a == "--test") => {}
        _ => fail(
            "usage: embree_native LIB check | LIB mesh DIR primary|random|inside [--passes P] | LIB spheres DIR N [--passes P]",
        ),
    }
}

fn fail(message: &str) -> ! {
    eprintln!("error: {message}");
    std::process::exit(2)
}

/// Embree's version number (40302) as 4.3.2.
fn version(v: isize) -> String {
    format!("{}.{}.{}", v / 10000, v / 100 % 100, v % 100)
}

fn doubles(path: &Path) -> Vec<f64> {
    std::fs::read(path)
        .unwrap_or_else(|e| fail(&format!("{}: {e}", path.display())))
        .chunks_exact(8)
        .map(|b| f64::from_le_bytes(b.try_into().expect("8 bytes")))
        .collect()
}

fn rays(path: &Path) -> Vec<Ray> {
    doubles(path)
        .chunks_exact(6)
        .map(|v| Ray::new(DVec3::new(v[0], v[1], v[2]), DVec3::new(v[3], v[4], v[5])))
        .collect()
}

/// Times the closest hit of every ray, one after another on this thread.
fn cast(embree: &Embree, scene: Handle, rays: &[Ray], passes: usize) {
    // Rounded to single precision before the timer starts, as an Embree
    // renderer makes its rays: each pass casts a fresh copy.
    let fresh: Vec<RayHit> = rays.iter().map(RayHit::new).collect();
    let mut best = f64::INFINITY;
    let (mut hits, mut t_sum) = (0, 0.0);
    for _ in 0..passes.max(1) {
        let start = Instant::now();
        (hits, t_sum) = (0, 0.0);
        for ray in &fresh {
            let mut ray = *ray;
            if let Some((t, _, _)) = embree.intersect(scene, &mut ray) {
                hits += 1;
                t_sum += f64::from(t);
            }
        }
        best = best.min(start.elapsed().as_secs_f64());
    }
    println!(
        "seconds={best:.6} rays={} hits={hits} t_sum={t_sum:.6}",
        rays.len()
    );
}

/// Known rays at one triangle (geometry 0) and two spheres (geometry 1): a
/// wrong structure layout or constant shows up as a wrong `t`, primitive or
/// geometry, or as a hit written past where this file reads it.
fn self_check(embree: &Embree) {
    // The triangle (0,0,5), (2,0,5), (0,2,5); spheres of radius 1 at z = 10
    // and radius 0.5 at (10, 0, 3).
    let triangle = [0.0, 0.0, 5.0, 2.0, 0.0, 5.0, 0.0, 2.0, 5.0];
    let spheres = [
        Sphere {
            center: DVec3::new(0.0, 0.0, 10.0),
            radius: 1.0,
        },
        Sphere {
            center: DVec3::new(10.0, 0.0, 3.0),
            radius: 0.5,
        },
    ];
    let scene = embree.scene();
    let mesh = embree.add_triangles(scene, &triangle);
    let user = embree.add_spheres(scene, &spheres);
    embree.commit(scene);
    let ray = |o: [f64; 3], d: [f64; 3]| Ray::new(DVec3::from(o), DVec3::from(d));
    let cases = [
        // Through the triangle at t = 5, in front of the first sphere.
        (ray([0.5, 0.5, 0.0], [0.0, 0.0, 1.0]), Some((5.0, 0, mesh))),
        // Beside the triangle, into the first sphere: √0.5 off its axis, so
        // √(1 - 0.5) before its center's depth.
        (
            ray([-0.5, -0.5, 0.0], [0.0, 0.0, 1.0]),
            Some((10.0 - 0.5f64.sqrt(), 0, user)),
        ),
        // From the first sphere's center: its far side at t = 1 (the root
        // behind the origin is not a hit).
        (ray([0.0, 0.0, 10.0], [1.0, 0.0, 0.0]), Some((1.0, 0, user))),
        // The second sphere alone, from beside it: t = 9.5.
        (ray([0.0, 0.0, 3.0], [1.0, 0.0, 0.0]), Some((9.5, 1, user))),
        // Nothing.
        (ray([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]), None),
    ];
    for (i, (ray, want)) in cases.iter().enumerate() {
        let mut hit = RayHit::new(ray);
        let got = embree.intersect(scene, &mut hit);
        // 1e-5: t is single precision in Embree's ray.
        let same = match (got, want) {
            (None, None) => true,
            (Some((t, p, g)), Some((wt, wp, wg))) => {
                (f64::from(t) - wt).abs() < 1e-5 && p == *wp && g == *wg
            }
            _ => false,
        };
        // Nothing written past the first instance level (the part this file
        // cannot know), and the first level left as no instance.
        let untouched = hit.inst.iter().all(|&v| v == INVALID_ID);
        if !same || !untouched {
            fail(&format!(
                "embree self-check ray {i}: got {got:?}, want {want:?}; instance fields {:?}",
                hit.inst
            ));
        }
    }
    // SAFETY: nothing uses the scene after.
    unsafe { (embree.release_scene)(scene) };
}
