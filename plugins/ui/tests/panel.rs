//! The panel driven the way a user drives it, without a window (the testkit's headless
//! `Harness`), and the change checked where the render systems read it: in the resources, and
//! through the real Close2GL system in the 2D frame. `tests/panel_views.rs` at the root follows
//! it on into both GPU views.

use close2gl_core::{
    Action, CameraAction, CameraActions, Close2glFrame, CommandLine, FateKind, Fates,
    InputBindings, ModelRequest, ModelSource, ModelStatus, Overlay, PrimitiveKind, RenderMode,
    RenderSettings, SelectedTriangle, TextureFilter, TextureRequest, ToolRequests, Topology,
};
use close2gl_testkit::panel::Harness;
use close2gl_ui::{Notice, PanelState};
use egui::accesskit::Role;

#[test]
fn unticking_backface_culling_reaches_the_settings_and_the_close2gl_frame() {
    let mut h = Harness::new();
    let before = h.world().resource::<Close2glFrame>().counts;
    assert_eq!(
        (before.culled, before.drawn),
        (1, 0),
        "the back face starts culled"
    );

    h.click(Role::CheckBox, "Backface culling");

    assert!(!h.world().resource::<RenderSettings>().backface_culling);
    let after = h.world().resource::<Close2glFrame>().counts;
    assert_eq!(
        (after.culled, after.drawn),
        (0, 1),
        "the back face is drawn now"
    );
}

#[test]
fn choosing_wireframe_changes_the_mode_and_the_topology() {
    let mut h = Harness::new();
    h.click(Role::CheckBox, "Backface culling");
    h.click(Role::Button, "wireframe");
    assert_eq!(
        h.world().resource::<RenderSettings>().mode,
        RenderMode::Wireframe
    );
    let frame = h.world().resource::<Close2glFrame>();
    assert_eq!(frame.topology, Topology::Lines);
    assert_eq!(frame.vertices.len(), 6, "three edges of the one triangle");
}

#[test]
fn a_primitive_button_requests_that_primitive() {
    let mut h = Harness::new();
    h.click(Role::Button, "torus");
    // Nothing here takes the request (no model plugin), so it is still waiting.
    assert_eq!(
        h.world().resource::<ModelRequest>().0,
        Some(ModelSource::Primitive(PrimitiveKind::Torus))
    );
}

#[test]
fn reload_requests_the_current_model_again() {
    let mut h = Harness::new();
    h.click(Role::Button, "Reload");
    assert_eq!(
        h.world().resource::<ModelRequest>().0,
        Some(ModelSource::File("models/tri.in".into()))
    );
}

#[test]
fn reset_pushes_a_reset_action() {
    let mut h = Harness::new();
    h.world().resource_mut::<CameraActions>().0.clear();
    h.click(Role::Button, "Reset");
    // No camera plugin drains the actions here, so the reset is still queued.
    assert_eq!(
        h.world().resource::<CameraActions>().0,
        vec![CameraAction::Reset]
    );
}

#[test]
fn fields_of_view_change_alone_or_together() {
    let mut h = Harness::new();
    h.set_value(Role::Slider, "hfov", 90.0);
    let camera = h.camera();
    assert_eq!(
        (camera.hfov, camera.vfov),
        (90.0, 60.0),
        "unlocked: vfov stays"
    );
    let frame = h.world().resource::<Close2glFrame>().clone();

    h.click(Role::CheckBox, "Lock hfov and vfov");
    h.set_value(Role::Slider, "vfov", 70.0);
    let camera = h.camera();
    assert_eq!(
        (camera.hfov, camera.vfov),
        (100.0, 70.0),
        "locked: both move by 10°"
    );
    h.click(Role::CheckBox, "Backface culling");
    assert_ne!(
        h.world().resource::<Close2glFrame>().vertices,
        frame.vertices,
        "the wider lens shrinks the triangle on screen"
    );
}

#[test]
fn the_views_get_the_window_beside_the_panel_whatever_it_shows() {
    let mut h = Harness::new();
    let views = h.views;
    assert_eq!(views.min, egui::Pos2::ZERO);
    assert_eq!(views.height(), 2400.0);
    assert!(
        views.width() < 1280.0 - 200.0 && views.width() > 1280.0 - close2gl_ui::PANEL_WIDTH - 50.0,
        "views {views:?}"
    );
    h.world().resource_mut::<ModelStatus>().error = Some(format!(
        "models/tri.in:12: expected three vertex indices {}",
        "and then some more words ".repeat(20)
    ));
    h.frame(Vec::new());
    h.frame(Vec::new());
    assert_eq!(h.views, views, "a long error wraps inside the panel");
}

#[test]
fn the_texture_section_switches_texturing_and_the_filter_and_asks_for_an_image() {
    let mut h = Harness::new();
    assert!(h.world().resource::<RenderSettings>().texture);
    h.click(Role::CheckBox, "Texture");
    h.click(Role::Button, "nearest");
    let settings = *h.world().resource::<RenderSettings>();
    assert!(!settings.texture);
    assert_eq!(settings.texture_filter, TextureFilter::Nearest);
    h.world().resource_mut::<PanelState>().texture_path = "wood.png".into();
    h.click(Role::Button, "Load image");
    assert_eq!(
        h.world().resource::<TextureRequest>().0,
        Some("wood.png".into()),
        "nothing here takes the request (no model plugin), so it is still waiting"
    );
}

#[test]
fn the_key_cheat_sheet_lists_every_key_as_configured() {
    let mut h = Harness::new();
    let mut bindings = InputBindings::default();
    bindings.0.insert(Action::Forward, "i".into());
    h.world().insert_resource(bindings);
    h.frame(Vec::new());
    assert!(!h.shows("move forward (along -n)"), "hidden until asked");

    h.click(Role::Button, "Keys (f1 or ?)");
    assert!(h.world().resource::<PanelState>().help);
    // A new egui window sizes itself unseen in its first frame.
    h.frame(Vec::new());
    assert!(h.shows("move forward (along -n)"));
    assert!(h.shows("i"), "the configured key, not the default w");
    assert!(!h.shows("w"));
    assert!(h.shows("f12") && h.shows("save both views as PNGs"));

    // The help key, as the input plugin passes it on, hides it again.
    h.world().resource_mut::<ToolRequests>().toggle_help = true;
    h.frame(Vec::new());
    h.frame(Vec::new());
    assert!(!h.shows("move forward (along -n)"));
}

/// The panel's part of copy as command: it asks the app's writer (the configuration's, tested
/// with the command line in the root crate and end to end in tests/tools.rs) and says what it did.
#[test]
fn copy_as_command_says_what_it_copied() {
    let mut h = Harness::new();
    h.world().insert_resource(InputBindings::default());
    h.frame(Vec::new());
    h.click(Role::Button, "Copy as command (c)");
    let notice = h.world().resource::<Notice>().text.clone();
    assert!(
        notice.starts_with("Nothing to copy yet"),
        "no writer: {notice}"
    );

    let writer = |_: &mut close2gl_core::bevy_ecs::world::World, out: &str| {
        Some(format!("close2gl render box --out {out}"))
    };
    h.world().insert_resource(CommandLine(writer));
    h.click(Role::Button, "Copy as command (c)");
    let notice = h.world().resource::<Notice>().text.clone();
    assert!(notice.starts_with("Copied the command"), "{notice}");
    assert!(
        !h.world().resource::<ToolRequests>().copy_command,
        "carried out once"
    );
}

#[test]
fn a_model_loading_in_the_background_shows_a_bar_with_its_name_and_percent() {
    let mut h = Harness::new();
    assert!(!h.shows("loading big.in: 42%"));
    h.world().resource_mut::<ModelStatus>().loading = Some(close2gl_core::Loading {
        source: ModelSource::File("models/big.in".into()),
        fraction: 0.425,
    });
    h.frame(Vec::new());
    h.node(Role::ProgressIndicator, "loading big.in: 42%");
    h.world().resource_mut::<ModelStatus>().loading = None;
    h.frame(Vec::new());
    assert!(!h.shows("loading big.in: 42%"), "gone once loaded");
}

#[test]
fn the_inspector_switches_the_fate_view_and_shows_the_picked_triangles_fate_and_the_matrices() {
    let mut h = Harness::new();
    // The GPU plugin asks for fates while the fate view is shown; the harness has no GPU.
    h.world().resource_mut::<Fates>().record = true;
    h.click(Role::Button, "fates");
    assert_eq!(
        h.world().resource::<RenderSettings>().overlay,
        Overlay::Fates
    );
    // The real pipeline recorded the harness's back face.
    let fate = *h.world().resource::<Fates>().of(0).expect("recorded");
    assert_eq!(fate.kind, FateKind::Culled);
    h.frame(Vec::new()); // the legend, now with counts, moves the widgets below it
    assert!(!h.shows("Fate: culled"), "no triangle selected yet");
    h.click(Role::Button, "Select");
    assert_eq!(h.world().resource::<SelectedTriangle>().0, Some(0));
    h.set_value(Role::SpinButton, "Triangle", 0.0);
    assert!(h.shows("Fate: culled"));
    let area = format!("Signed area (x2, y down): {:.3}", fate.signed_area);
    assert!(h.shows(&area), "{area}");
    // The journey: a triangle inside the volume has no clip steps, and is divided as it is.
    for stage in [
        "world 1",
        "eye 2",
        "clip 0",
        "ndc 1",
        "window 2",
        "Culling: culled",
    ] {
        assert!(h.shows(stage), "{stage}");
    }
    assert!(!h.shows("left 0"), "no clip step");
    assert!(!h.shows("M (Close2GL)"), "the matrices start folded");
    h.click(Role::DisclosureTriangle, "Matrices");
    assert!(h.shows("M (Close2GL)") && h.shows("projection (reference)"));
    // Clearing the selection takes the highlight off the views and the journey off the panel.
    h.click(Role::Button, "Clear");
    assert_eq!(h.world().resource::<SelectedTriangle>().0, None);
    assert!(!h.shows("Fate: culled"));
}
