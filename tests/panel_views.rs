//! The panel driven headless (the testkit's `Harness`, as in the UI crate's tests), followed on
//! through the real GPU views (offscreen, on whatever adapter wgpu finds: Mesa's lavapipe
//! without a GPU) into both images.

use close2gl_testkit::gpu;
use close2gl_testkit::panel::Harness;
use close2gl_testkit::panel::egui::accesskit::Role;

#[test]
fn panel_changes_reach_both_gpu_views() {
    let mut h = Harness::new();
    h.app.add_plugins(close2gl_gpu::OffscreenPlugin(gpu()));
    let covered = |h: &mut Harness| {
        let shot = close2gl_gpu::render_offscreen(&mut h.app).unwrap_or_else(|e| panic!("{e}"));
        let count = |image| {
            close2gl_core::parity::coverage(image, shot.background)
                .into_iter()
                .filter(|&c| c)
                .count()
        };
        (count(&shot.reference), count(&shot.close2gl))
    };
    assert_eq!(
        covered(&mut h),
        (0, 0),
        "the back face is culled in both views"
    );

    h.click(Role::CheckBox, "Backface culling");
    let solid = covered(&mut h);
    assert!(solid.0 > 1000 && solid.1 > 1000, "solid: {solid:?} pixels");

    h.click(Role::Button, "wireframe");
    let wire = covered(&mut h);
    assert!(
        wire.0 > 0 && wire.1 > 0 && wire.0 * 4 < solid.0 && wire.1 * 4 < solid.1,
        "wireframe {wire:?} against solid {solid:?} pixels"
    );
}
