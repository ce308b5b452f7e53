//! What close2gl's test suites share, so that no test file keeps its own copy: meshes built by
//! hand ([`cube`], [`sphere`]), big model files written on the spot ([`write_grid_in`],
//! [`write_grid_obj`]), the world a test starts from ([`world_with`], [`camera`],
//! [`mesh`]), with feature `gpu` the one headless GPU adapter a test binary uses (`gpu`), and
//! with feature `panel` the egui control panel driven headless (`panel::Harness`), and the
//! student program of `examples/trace/` compiled with the C compiler ([`student`]). Used as a
//! dev-dependency only.

mod big_model;
mod meshes;
#[cfg(feature = "panel")]
pub mod panel;
pub mod student;
mod temp_dir;

use close2gl_core::bevy_ecs::prelude::Resource;
use close2gl_core::{
    App, Appearance, Camera, Lighting, Mesh, Overlay, PipelineSettings, RecordFates,
    SelectedTriangle, Viewport, insert_if_changed,
};

pub use big_model::{GridFile, write_grid_in, write_grid_obj};
pub use meshes::{cube, sphere};
pub use temp_dir::TempDir;

/// An app whose world has the settings resources at their defaults (`PipelineSettings`,
/// `Appearance`, `Overlay`: insert the ones a test changes), `viewport`, the default lighting,
/// one `camera` and one `mesh` (what the settings plugin and a loaded model provide): add the
/// plugins under test, then run frames.
pub fn world_with(mesh: Mesh, camera: Camera, viewport: Viewport) -> App {
    let mut app = App::new();
    app.init_resource::<PipelineSettings>()
        .init_resource::<Appearance>()
        .init_resource::<Overlay>()
        .insert_resource(viewport)
        .init_resource::<Lighting>()
        .init_resource::<SelectedTriangle>()
        .init_resource::<RecordFates>();
    app.world_mut().spawn(camera);
    app.world_mut().spawn(mesh);
    app
}

/// Changes one of the app's settings resources as a configuration applied does: it is set
/// again only when its value changed, so that only a real change wakes its readers.
pub fn change_settings<R: Resource + PartialEq + Clone>(
    app: &mut App,
    change: impl FnOnce(&mut R),
) {
    let mut value = app.world().resource::<R>().clone();
    change(&mut value);
    insert_if_changed(app.world_mut(), value);
}

/// The app's one camera.
pub fn camera(app: &mut App) -> Camera {
    let world = app.world_mut();
    *world
        .query::<&Camera>()
        .single(world)
        .expect("the app has one camera")
}

/// The app's one camera, to change (which marks it changed).
pub fn camera_mut(app: &mut App) -> &mut Camera {
    let world = app.world_mut();
    world
        .query::<&mut Camera>()
        .single_mut(world)
        .expect("the app has one camera")
        .into_inner()
}

/// The app's one mesh.
pub fn mesh(app: &mut App) -> &Mesh {
    let world = app.world_mut();
    world
        .query::<&Mesh>()
        .single(world)
        .expect("the app has one mesh")
}

/// The headless GPU adapter, made once per test binary (wgpu's handles are cheap to clone). No
/// adapter is a failure that says what to install, never a silent pass.
#[cfg(feature = "gpu")]
pub fn gpu() -> close2gl_gpu::Gpu {
    static GPU: GpuCell = std::sync::OnceLock::new();
    shared(&GPU, close2gl_gpu::Gpu::headless)
}

/// [`gpu`]'s adapter opened without the polygon-mode features, as WebGL2 offers it: lines and
/// points are drawn face by face. Made once per test binary.
#[cfg(feature = "gpu")]
pub fn gpu_without_polygon_modes() -> close2gl_gpu::Gpu {
    static GPU: GpuCell = std::sync::OnceLock::new();
    shared(&GPU, |backends| {
        close2gl_gpu::Gpu::headless_with(backends, close2gl_gpu::wgpu::Features::empty())
    })
}

#[cfg(feature = "gpu")]
type GpuCell = std::sync::OnceLock<Result<close2gl_gpu::Gpu, String>>;

/// The device in `cell`, opened by `open` on the primary backends the first time.
#[cfg(feature = "gpu")]
fn shared(
    cell: &GpuCell,
    open: impl FnOnce(close2gl_gpu::wgpu::Backends) -> Result<close2gl_gpu::Gpu, String>,
) -> close2gl_gpu::Gpu {
    match cell.get_or_init(|| open(close2gl_gpu::wgpu::Backends::PRIMARY)) {
        Ok(gpu) => gpu.clone(),
        Err(e) => panic!("these tests need a GPU adapter: {e}"),
    }
}
