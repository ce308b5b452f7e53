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
            close2gl_core::parity::coverage(image)
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

/// A Ctrl+click as a recording holds it (a replay's frame, applied to the input as the viewer
/// applies it) on the Close2GL view of the split layout: the viewer's probe asks both views (the
/// reference's ID pass on the GPU, Close2GL's candidates), and the panel opens its window beside
/// the click with the answer.
#[test]
fn a_recorded_ctrl_click_opens_the_probe_window_with_both_answers() {
    use close2gl_core::InputState;
    use close2gl_core::bevy_ecs::system::RunSystemOnce;
    use close2gl_viewer::placed_views::ViewPlacement;
    use close2gl_viewer::view_layout::{self, PixelRect};

    let mut h = Harness::new();
    h.click(Role::CheckBox, "Backface culling");
    assert!(
        !h.world().resource::<close2gl_core::RecordFates>().0,
        "the fate view is off: the probe works the fates out itself"
    );
    // Two 200 × 100 views side by side; the click is in the middle of the Close2GL one.
    let dir = close2gl_testkit::TempDir::new("probe_recording");
    let recording = dir.write(
        "probe.rec",
        b"{\"close2gl_recording\":1,\"size\":[690,100]}\n\
          {\"frame\":0,\"dt\":0.016666668,\"probe\":[300,50],\"probe_close2gl_window\":false}\n",
    );
    let recording = close2gl_viewer::Recording::read(&recording).unwrap_or_else(|e| panic!("{e}"));
    let mut input = InputState::default();
    recording.frames[0].apply(&mut input);
    h.world().insert_resource(input);
    let placement = view_layout::split(PixelRect::whole(400, 100), false);
    h.world().insert_resource(gpu());
    h.world().insert_resource(ViewPlacement(placement));
    h.world()
        .run_system_once(close2gl_viewer::pixel_probe::answer_probe)
        .expect("the probe's system runs");
    // A new egui window sizes itself unseen in its first frame.
    h.frame(Vec::new());
    h.frame(Vec::new());
    let texts: Vec<String> = h.texts().into_iter().map(|(t, _)| t).collect();
    let shows = |start: &str| texts.iter().any(|t| t.starts_with(start));
    for line in [
        "Pixel 100, 50 of the Close2GL view",
        "Reference (GPU): triangle 0, depth",
        "Close2GL: triangle 0, depth",
        "Both views drew triangle 0 here.",
        "Journey of triangle 0",
    ] {
        assert!(shows(line), "{line}: {texts:?}");
    }
}
