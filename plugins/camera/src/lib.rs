//! The camera plugin. It owns framing (on every newly loaded `Mesh`, the `Camera` is placed to
//! show the whole model, honouring the `Framing` resource's explicit pose and pinned planes, and
//! that pose is stored as `CameraHome`; `CameraSpeeds::model_radius` follows the model's size)
//! and camera motion (it drains `CameraActions` into the `Camera`: translations along u, v, n,
//! rotations about them, orbits of the look-at point, zoom, reset, mode toggle). It is the one
//! writer of the `Camera` inside a frame: the others ask through `CameraRequest` (the panel's
//! and a watched configuration's edits, applied first; a trace's camera, applied last). It owns
//! `CameraActions`, `CameraRequest`, `CameraSpeeds`, `Framing` and `KeepPose` (set, a new mesh
//! leaves the camera where it is: a watched file reloaded); its systems run in
//! `FrameSet::Camera`, after `FrameSet::Load`, so a mesh loaded this frame is framed this frame.

pub mod framing;
pub mod motion;

use bevy_ecs::prelude::*;
use close2gl_core::{
    App, Camera, CameraActions, CameraHome, CameraRequest, CameraSpeeds, FrameSet, Framing,
    KeepPose, Mesh, Plugin, Update,
};

pub struct CameraPlugin;

impl Plugin for CameraPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<CameraActions>()
            .init_resource::<CameraRequest>()
            .init_resource::<CameraSpeeds>()
            .init_resource::<Framing>()
            .init_resource::<KeepPose>()
            .add_systems(
                Update,
                (
                    apply_camera_edit,
                    frame_new_model,
                    apply_camera_actions,
                    apply_camera_replacement,
                )
                    .chain()
                    .in_set(FrameSet::Camera),
            );
    }
}

/// The camera as edited this frame (the panel, a watched configuration, a redraw), before a new
/// model is framed and the actions move it: as if it had been so when the frame began.
pub fn apply_camera_edit(mut request: ResMut<CameraRequest>, mut camera: Single<&mut Camera>) {
    if let Some(edited) = request.edited.take() {
        **camera = edited;
    }
}

/// A camera that replaces this frame's (a trace's own), over the framing and the actions.
pub fn apply_camera_replacement(
    mut request: ResMut<CameraRequest>,
    mut camera: Single<&mut Camera>,
) {
    if let Some(replacement) = request.replacement.take() {
        **camera = replacement;
    }
}

/// Frames the camera on a model that just arrived and remembers the pose for reset; with
/// `KeepPose` set, only the speeds follow the new model's size.
pub fn frame_new_model(
    mut commands: Commands,
    mesh: Single<Ref<Mesh>>,
    camera: Single<(Entity, &mut Camera)>,
    framing: Res<Framing>,
    mut keep_pose: ResMut<KeepPose>,
    mut speeds: ResMut<CameraSpeeds>,
) {
    if !mesh.is_changed() {
        return;
    }
    let (centre, radius) = mesh.bounding_sphere();
    speeds.model_radius = radius.max(f32::MIN_POSITIVE);
    if std::mem::take(&mut keep_pose.0) {
        return;
    }
    let (entity, mut camera) = camera.into_inner();
    *camera = framing::frame(centre, radius, &camera, &framing);
    commands.entity(entity).insert(CameraHome(*camera));
}

/// Applies this frame's camera actions, in order.
pub fn apply_camera_actions(
    mut actions: ResMut<CameraActions>,
    camera: Single<(&mut Camera, Option<&CameraHome>)>,
) {
    if actions.0.is_empty() {
        return;
    }
    let (mut camera, home) = camera.into_inner();
    for action in actions.0.drain(..) {
        motion::apply(&mut camera, action, home.map(|h| &h.0));
    }
}
