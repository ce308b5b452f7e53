//! A user-written plugin, the bevy way: a small struct whose `build` adds a system in one of the
//! core's `FrameSet`s. This one orbits the camera a little every frame and logs what Close2GL
//! drew; the example runs it headless for a full turn on the torus primitive. A plain function
//! is a plugin too (`report_plugin` below).
//!
//!     cargo run --example orbit_plugin

use close2gl::config::Config;
use close2gl::core::bevy_ecs::prelude::*;
use close2gl::core::{
    App, CameraAction, CameraActions, Close2glFrame, FrameSet, ModelSource, Plugin, PrimitiveKind,
    Update, Viewport,
};

/// Turns the camera around the look-at point by `step` radians a frame.
struct Orbit {
    step: f32,
}

#[derive(Resource)]
struct OrbitStep(f32);

impl Plugin for Orbit {
    fn build(&self, app: &mut App) {
        // Input's set: the camera plugin applies the action in the same frame.
        app.insert_resource(OrbitStep(self.step))
            .add_systems(Update, orbit.in_set(FrameSet::Input));
    }
}

/// Logs each frame's counts where a frame's results go out (after the Close2GL pipeline).
fn report_plugin(app: &mut App) {
    app.add_systems(Update, report.in_set(FrameSet::Output));
}

fn orbit(step: Res<OrbitStep>, mut actions: ResMut<CameraActions>) {
    actions.0.push(CameraAction::Orbit {
        yaw: step.0,
        pitch: 0.0,
    });
}

fn report(frame: Res<Close2glFrame>) {
    let c = frame.counts;
    println!(
        "drawn {:5}  culled {:5}  clipped {:5}",
        c.drawn, c.culled, c.clipped
    );
}

fn main() -> Result<(), String> {
    let config = Config {
        model: ModelSource::Primitive(PrimitiveKind::Torus),
        ..Config::default()
    };
    // build_app adds DefaultPlugins (adding a plugin twice would be an error).
    let mut app = close2gl::build_app(
        &config,
        Viewport {
            width: 640,
            height: 480,
        },
    )?;
    app.add_plugins(Orbit {
        step: std::f32::consts::TAU / 12.0,
    })
    .add_plugins(report_plugin);
    for _ in 0..12 {
        app.update();
    }
    Ok(())
}
