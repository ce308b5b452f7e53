//! The panel driven the way a user drives it, without a window (the testkit's headless
//! `Harness`), and the change checked where the render systems read it: in the resources, and
//! through the real Close2GL system in the 2D frame. `tests/panel_views.rs` at the root follows
//! it on into both GPU views.

use close2gl_core::glam::Vec2;
use close2gl_core::{
    Action, Appearance, CameraAction, CameraActions, Close2glFrame, CommandLine, FateKind, Fates,
    InputBindings, ModelRequest, ModelSource, ModelStatus, OutsideView, Overlay, PipelineSettings,
    PrimitiveKind, RenderMode, SelectedTriangle, TextureFilter, TextureRequest, ToolRequests,
    Topology,
};
use close2gl_core::{Camera, Mesh, ProbeClick, RecordFates, Scene, Viewport};
use close2gl_raster::coverage_probe::probe;
use close2gl_testkit::panel::Harness;
use close2gl_ui::{Notice, PanelState, ProbeAnswer};
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

    assert!(!h.world().resource::<PipelineSettings>().backface_culling);
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
        h.world().resource::<PipelineSettings>().mode,
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
fn a_typed_path_is_requested_trimmed_and_an_empty_one_is_not() {
    let mut h = Harness::new();
    // The first frame shows the current model's path in the field.
    h.frame(Vec::new());
    h.world().resource_mut::<PanelState>().path = "   ".into();
    h.click(Role::Button, "Load");
    assert_eq!(h.world().resource::<ModelRequest>().0, None);
    h.world().resource_mut::<PanelState>().path = " models/cube.in ".into();
    h.click(Role::Button, "Load");
    assert_eq!(
        h.world().resource::<ModelRequest>().0,
        Some(ModelSource::File("models/cube.in".into()))
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
    // Locked, they zoom as the scroll wheel does: tan(fov/2) of both scaled by the same factor,
    // so hfov moves by more degrees than vfov's 10, and the image keeps its aspect.
    let half_tan = |fov: f32| (fov.to_radians() / 2.0).tan();
    assert!((camera.vfov - 70.0).abs() < 1e-3, "vfov {}", camera.vfov);
    assert!(
        (half_tan(camera.hfov) / half_tan(camera.vfov) - half_tan(90.0) / half_tan(60.0)).abs()
            < 1e-5,
        "locked: the aspect stays ({}, {})",
        camera.hfov,
        camera.vfov
    );
    assert!(camera.hfov > 100.5, "hfov {}", camera.hfov);
    h.click(Role::CheckBox, "Backface culling");
    assert_ne!(
        h.world().resource::<Close2glFrame>().vertices,
        frame.vertices,
        "the wider lens shrinks the triangle on screen"
    );
}

#[test]
fn the_views_get_the_window_beside_the_panel_whatever_it_shows() {
    let views = close2gl_ui::views_area(Harness::SCREEN, false);
    assert_eq!(views.min, egui::Pos2::ZERO);
    assert_eq!(views.height(), 2400.0);
    assert_eq!(views.width(), 1280.0 - close2gl_ui::PANEL_WIDTH);
    // Hidden (a page embedded in a course's page), the panel leaves the views everything.
    assert_eq!(
        close2gl_ui::views_area(Harness::SCREEN, true),
        Harness::SCREEN
    );
    let mut h = Harness::new();
    h.world().resource_mut::<ModelStatus>().error = Some(format!(
        "models/tri.in:12: expected three vertex indices {}",
        "and then some more words ".repeat(20)
    ));
    h.frame(Vec::new());
    h.frame(Vec::new());
    let texts = h.texts();
    let error = texts
        .iter()
        .find(|(t, _)| t.starts_with("models/tri.in:12:"))
        .unwrap_or_else(|| panic!("the error is shown: {texts:?}"));
    let panel = views.max.x..=1280.0;
    assert!(
        panel.contains(&error.1.min.x) && panel.contains(&error.1.max.x),
        "a long error wraps inside the panel: {error:?}"
    );
}

#[test]
fn the_texture_section_switches_texturing_and_the_filter_and_asks_for_an_image() {
    let mut h = Harness::new();
    assert!(h.world().resource::<Appearance>().texture);
    h.click(Role::CheckBox, "Texture");
    h.click(Role::Button, "nearest");
    let settings = *h.world().resource::<Appearance>();
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
    h.world().resource_mut::<RecordFates>().0 = true;
    h.click(Role::Button, "fate_view");
    assert_eq!(*h.world().resource::<Overlay>(), Overlay::FateView);
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
        "world",
        "eye = M·p",
        "clip = P·M·p",
        "ndc (÷ w)",
        "window (V·ndc)",
        "Culling: culled",
    ] {
        assert!(h.shows(stage), "{stage}");
    }
    assert!(!h.shows("clipped at the left plane"), "no clip step");
    assert!(!h.shows("M (Close2GL)"), "the matrices start folded");
    h.click(Role::DisclosureTriangle, "Matrices");
    assert!(h.shows("M (Close2GL)") && h.shows("projection (reference)"));
    // Clearing the selection takes the highlight off the views and the journey off the panel.
    h.click(Role::Button, "Clear");
    assert_eq!(h.world().resource::<SelectedTriangle>().0, None);
    assert!(!h.shows("Fate: culled"));
}

/// The journey's numbers in columns that say what they are, all inside the panel: a user reads
/// every column at the default width without scrolling sideways.
#[test]
fn the_journey_and_the_matrices_are_tables_with_headers_inside_the_panel() {
    let mut h = Harness::new();
    h.click(Role::Button, "Select");
    h.click(Role::DisclosureTriangle, "Matrices");
    // The section opens over a few frames' animation, meanwhile overlapping what is below.
    for _ in 0..10 {
        h.frame(Vec::new());
    }
    let texts = h.texts();
    let count = |text: &str| texts.iter().filter(|(t, _)| t == text).count();
    // world, eye, ndc and window have three columns; clip and the five matrices four.
    assert_eq!(count("x"), 4 + 1 + 5, "{texts:?}");
    assert_eq!(count("w"), 1 + 5);
    assert_eq!(count("depth"), 1, "the window's third column");
    // Across: the panel's columns (down, it scrolls).
    let panel = 1280.0 - close2gl_ui::PANEL_WIDTH..=1280.0;
    let at = |text: &str| texts.iter().find(|(t, _)| t == text).expect(text).1;
    // From the journey's first table to the section below the inspector.
    let tables = at("world").min.y..at("Stats").min.y;
    let numbers: Vec<_> = texts
        .iter()
        .filter(|(_, r)| tables.contains(&r.min.y))
        .filter(|(t, _)| {
            t.parse::<f32>().is_ok() || ["x", "y", "z", "w", "depth"].contains(&t.as_str())
        })
        .collect();
    assert!(numbers.len() > 100, "{}", numbers.len());
    for (text, rect) in &numbers {
        assert!(
            panel.contains(&rect.min.x) && panel.contains(&rect.max.x),
            "{text:?} at {rect:?} leaves the panel {panel:?}"
        );
    }
    // No two cells of a row overlap: the numbers do not run together.
    for (i, (a, ra)) in numbers.iter().enumerate() {
        for (b, rb) in &numbers[i + 1..] {
            assert!(
                !ra.shrink(0.5).intersects(rb.shrink(0.5)),
                "{a:?} {ra:?} overlaps {b:?} {rb:?}"
            );
        }
    }
}

/// Each view showing an overlay says what its colours mean in its corner; the reference only in
/// the fate view (the difference replaces Close2GL's view alone), the outside view while it shows
/// the fates; the legend's close button and the Inspector's checkbox hide them all.
#[test]
fn the_views_show_the_legend_of_their_overlay_until_hidden() {
    let mut h = Harness::new();
    let titles = [
        "The GPU's answers",
        "Close2GL's fates",
        "Where the views differ",
        "Outside view: fates",
    ];
    let shown = |h: &Harness| titles.map(|t| h.shows(t));
    assert_eq!(shown(&h), [false; 4], "no overlay, no legend");

    h.click(Role::Button, "fate_view");
    h.frame(Vec::new());
    assert_eq!(shown(&h), [true, true, false, false]);
    h.world().insert_resource(OutsideView {
        show: true,
        ..OutsideView::default()
    });
    // A new egui area sizes itself unseen in its first frame.
    h.frame(Vec::new());
    h.frame(Vec::new());
    assert_eq!(shown(&h), [true, true, false, true]);
    assert!(h.shows("dimmed: outside the view volume"));

    h.click(Role::Button, "difference");
    h.frame(Vec::new());
    assert_eq!(shown(&h), [false, false, true, false]);
    assert!(h.shows("covered in the reference only"));

    h.click(Role::Button, "×");
    assert!(h.world().resource::<PanelState>().hide_legends);
    h.frame(Vec::new());
    assert_eq!(shown(&h), [false; 4], "hidden by its close button");
    h.click(Role::CheckBox, "Legends in the views");
    h.frame(Vec::new());
    assert_eq!(shown(&h), [false, false, true, false], "shown again");
    h.click(Role::CheckBox, "Legends in the views");
    assert_eq!(shown(&h), [false; 4], "hidden by the checkbox");
}

/// A probe as the viewer answers a Ctrl+click: Close2GL's side from the raster crate's probe of
/// the harness's scene (its one triangle, a back face, culled there), the GPU's as if it drew
/// that triangle. The answer opens beside the click, says the views differ and why, opens the
/// triangle's journey, says when the camera moved since, and closes with Esc; the panel keeps it.
#[test]
fn a_probe_opens_its_answer_beside_the_click_until_escape() {
    let mut h = Harness::new();
    h.world().resource_mut::<RecordFates>().0 = true;
    h.click(Role::Button, "fate_view");
    let camera = h.camera();
    let world = h.world();
    let mesh = world
        .query::<&Mesh>()
        .single(world)
        .expect("a mesh")
        .clone();
    let scene = Scene {
        mesh: &mesh,
        camera: &camera,
        pipeline: world.resource::<PipelineSettings>(),
        viewport: *world.resource::<Viewport>(),
    };
    let close2gl = probe(scene, world.resource::<Fates>(), (100, 50), None);
    world.insert_resource(ProbeAnswer {
        view: "Close2GL",
        reference: Ok(Some((0, 0.98))),
        close2gl,
        trace: None,
        click: ProbeClick {
            at: Vec2::new(300.0, 200.0),
            close2gl_window: false,
        },
        camera,
        window: true,
        fixed_frame: false,
    });
    // A new egui window sizes itself unseen in its first frame.
    h.frame(Vec::new());
    h.frame(Vec::new());

    let title = "Pixel 100, 50 of the Close2GL view";
    let at = h.texts().into_iter().find(|(t, _)| t == title);
    let (_, rect) = at.unwrap_or_else(|| panic!("{title}: {:?}", h.texts()));
    assert!(
        (300.0..360.0).contains(&rect.min.x) && (200.0..280.0).contains(&rect.min.y),
        "beside the click at 300, 200: {rect:?}"
    );
    for line in [
        "Reference (GPU): triangle 0, depth 0.98000",
        "Close2GL: background",
        "The views differ: the GPU drew triangle 0, Close2GL nothing (triangle 0 in Close2GL: a \
         back face, removed by culling).",
    ] {
        assert!(h.shows(line), "{line}");
    }
    let candidate = |(t, _): &(String, egui::Rect)| {
        t.starts_with("triangle 0 culled (depth ")
            && t.ends_with("): a back face, removed by culling")
    };
    assert!(
        h.texts().iter().any(candidate),
        "Close2GL's candidate and why it lost"
    );
    assert!(!h.shows("Fate: culled"), "no triangle selected yet");
    h.click(Role::Button, "Journey of triangle 0");
    assert_eq!(h.world().resource::<SelectedTriangle>().0, Some(0));
    h.frame(Vec::new());
    assert!(h.shows("Fate: culled") && h.shows("window (V·ndc)"));

    let stale = "Stale: the camera moved since this probe (Ctrl+click again).";
    assert!(!h.shows(stale));
    let world = h.world();
    world
        .query::<&mut Camera>()
        .single_mut(world)
        .expect("a camera")
        .near = 0.5;
    h.frame(Vec::new());
    assert!(h.shows(stale));

    h.frame(vec![egui::Event::Key {
        key: egui::Key::Escape,
        physical_key: None,
        pressed: true,
        repeat: false,
        modifiers: egui::Modifiers::NONE,
    }]);
    h.frame(Vec::new());
    assert!(!h.world().resource::<ProbeAnswer>().window);
    assert!(!h.shows(title), "closed");
    assert!(
        h.shows("Probe: pixel 100, 50 (clicked on Close2GL)"),
        "the panel keeps it"
    );
}
