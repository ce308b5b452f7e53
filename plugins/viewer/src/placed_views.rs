//! The views as the viewer placed them for this frame ([`ViewPlacement`], written before the
//! frame from the windows' sizes and the panel's fixed width), and the system that keeps the
//! world's `Viewport` equal to the Close2GL view's size.

use bevy_ecs::prelude::*;
use close2gl_core::Viewport;

use crate::view_layout::Placement;

/// Where each view is in each window this frame: the viewer's, read by the systems that need
/// the layout (the viewport, which view a probe click is in).
#[derive(Resource, Default)]
pub struct ViewPlacement(pub Placement);

/// Keeps `Viewport` equal to the Close2GL view's size; written only when it changed, so that the
/// pipeline does not run again for nothing.
pub fn set_viewport(placement: Res<ViewPlacement>, mut viewport: ResMut<Viewport>) {
    if let Some(size) = placement.0.viewport {
        viewport.set_if_neq(size);
    }
}
