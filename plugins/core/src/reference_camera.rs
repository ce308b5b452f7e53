//! The reference renderer's camera matrices, here rather than in the GPU crate so that the
//! panel and the headless tools can show them beside Close2GL's own without knowing a GPU.

use glam::Mat4;
use glam::camera::rh::proj::directx::perspective;
use glam::camera::rh::view::look_at_mat4;

use crate::Camera;

/// The camera's view and projection from glam's own functions, deliberately independent of
/// Close2GL's hand-written matrices so that agreement between the views means something. The
/// projection's aspect comes from the two fields of view, not from the window, as in Close2GL;
/// depth maps to wgpu's 0..1 (glam's right-handed look-at and WebGPU perspective).
pub fn camera_matrices(camera: &Camera) -> (Mat4, Mat4) {
    let view = look_at_mat4(camera.position, camera.position - camera.n, camera.v);
    let half_h = (camera.hfov.to_radians() * 0.5).tan();
    let half_v = (camera.vfov.to_radians() * 0.5).tan();
    let projection = perspective(
        camera.vfov.to_radians(),
        half_h / half_v,
        camera.near,
        camera.far,
    );
    (view, projection)
}
