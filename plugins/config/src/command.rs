//! "Copy as command": the `close2gl render` line that reproduces what the views show, headless;
//! [`CommandPlugin`] makes it the app's `CommandLine`, which the panel's Copy as command and the
//! screenshot key call. It is written from the same key table the configuration is read with
//! ([`super::keys::KEYS`], its pairs from [`pixel_keys`]):
//! the pose as position, target and the camera's own u, v, n, every number so that it reads back
//! to the same bits (the command's images are the views' pixels, not an approximation of them),
//! and the other settings only where they differ from the defaults, so the line stays readable.

use close2gl_core::bevy_ecs::world::World;
use close2gl_core::{
    App, Camera, CommandLine, Lighting, ModelSource, ModelStatus, OutsideView, Plugin,
    PrimitiveParams, Texture, Viewport,
};

use super::keys::{absolute, pixel_keys};
use super::{CameraConfig, Config, RenderConfig};

/// Puts [`of_world_command`] in the app as its `CommandLine`.
pub struct CommandPlugin;

impl Plugin for CommandPlugin {
    fn build(&self, app: &mut App) {
        app.insert_resource(CommandLine(of_world_command));
    }
}

/// What the world shows now, as a configuration (the pose pinned, near and far too); `None`
/// before a model and a camera exist.
pub fn of_world(world: &mut World) -> Option<Config> {
    let c = *world.query::<&Camera>().iter(world).next()?;
    let mut config = Config {
        model: world.get_resource::<ModelStatus>()?.source.clone()?,
        texture: world
            .get_resource::<Texture>()
            .and_then(|t| t.source.clone()),
        render: RenderConfig::of_world(world)?,
        lighting: *world.get_resource::<Lighting>()?,
        // Only a primitive's own view depends on them.
        primitives: world
            .get_resource::<PrimitiveParams>()
            .copied()
            .unwrap_or_default(),
        outside: world
            .get_resource::<OutsideView>()
            .copied()
            .unwrap_or_default(),
        ..Config::default()
    };
    config.camera = CameraConfig::pinning(&c);
    Some(config)
}

/// The arguments after `close2gl`, unquoted: `render MODEL --size WxH --set ... --out DIR`.
pub fn args(config: &Config, size: Viewport, out: &str) -> Vec<String> {
    let model = match &config.model {
        ModelSource::File(path) => absolute(path).display().to_string(),
        ModelSource::Primitive(kind) => kind.name().to_string(),
    };
    let size = format!("{}x{}", size.width, size.height);
    let mut args = vec!["render".into(), model, "--size".into(), size];
    for (key, value) in pixel_keys(config) {
        args.extend(["--set".into(), format!("{key}={value}")]);
    }
    args.extend(["--out".into(), out.into()]);
    args
}

/// The command line, each argument quoted for a POSIX shell where it needs to be.
pub fn command(config: &Config, size: Viewport, out: &str) -> String {
    let mut line = String::from("close2gl");
    for arg in args(config, size, out) {
        line.push(' ');
        line.push_str(&shell_quote(&arg));
    }
    line
}

/// The command for what `world` shows, writing its images to `out` (the app's `CommandLine`);
/// `None` before anything shows.
pub fn of_world_command(world: &mut World, out: &str) -> Option<String> {
    let size = *world.get_resource::<Viewport>()?;
    of_world(world).map(|config| command(&config, size, out))
}

/// Quoted for a POSIX shell unless it is made only of characters no shell treats specially.
fn shell_quote(arg: &str) -> String {
    let plain = |c: char| c.is_ascii_alphanumeric() || "-_./=,:+@%".contains(c);
    if !arg.is_empty() && arg.chars().all(plain) {
        arg.to_string()
    } else {
        format!("'{}'", arg.replace('\'', "'\\''"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::keys::{KEYS, Write, exact};
    use crate::load;
    use close2gl_core::PrimitiveKind;

    const SIZE: Viewport = Viewport {
        width: 640,
        height: 480,
    };

    fn torus() -> Config {
        let mut config = Config {
            model: ModelSource::Primitive(PrimitiveKind::Torus),
            ..Config::default()
        };
        let camera = &mut config.camera;
        (camera.position, camera.target) =
            (Some(glam_vec(0.0, 0.0, 5.0)), Some(glam_vec(0.0, 0.0, 0.0)));
        config
    }

    fn glam_vec(x: f32, y: f32, z: f32) -> close2gl_core::glam::Vec3 {
        close2gl_core::glam::Vec3::new(x, y, z)
    }

    #[test]
    fn numbers_read_back_to_the_same_bits() {
        for x in [0.1f32, 1.0 / 3.0, 1e-7, 123456.79, -0.0, 60.0, f32::MAX] {
            let text = exact(x);
            assert_eq!(text.parse::<f64>().unwrap() as f32, x, "{x} as {text}");
        }
        assert_eq!(exact(0.25), "0.25");
    }

    #[test]
    fn only_settings_off_their_defaults_are_written() {
        let plain = command(&torus(), SIZE, "out");
        assert!(plain.starts_with("close2gl render torus --size 640x480 --set "));
        assert!(!plain.contains("render."), "{plain}");
        assert!(plain.contains("camera.position=[0.0,0.0,5.0]"), "{plain}");
    }

    /// Every key the command writes, set off its default, written and read back: the same
    /// configuration. A key added to the table without a sample here fails the test.
    #[test]
    fn every_key_the_command_writes_round_trips() {
        let samples = [
            "model.texture=\"/nonexistent/texture.png\"",
            "camera.u=[1.0,0.0,0.0]",
            "camera.v=[0.0,1.0,0.0]",
            "camera.n=[0.0,0.0,1.0]",
            "camera.hfov=50.5",
            "camera.vfov=40.25",
            "camera.near=0.3",
            "camera.far=70.0",
            "render.mode=wireframe",
            "render.front_face=cw",
            "render.backface_culling=false",
            "render.clipping=simple",
            "render.color=[0.1,0.2,0.3]",
            "render.shading=gouraud_ad",
            "render.background=[0.3,0.2,0.1]",
            "render.close2gl_raster=software",
            "render.texture=false",
            "render.texture_filter=nearest",
            "render.overlay=fate_view",
            "render.mistake=fov_not_halved",
            "render.raster_mistake=uv_affine",
            "lighting.light_position=[1.0,2.0,3.0]",
            "lighting.ia=[0.1,0.1,0.2]",
            "lighting.il=[0.9,0.8,0.7]",
            "lighting.ka=0.15",
            "lighting.kd=0.55",
            "lighting.ks=0.35",
            "lighting.shininess=12.5",
            "lighting.attenuation=[1.0,0.5,0.25]",
            "primitives.box_size=[1.0,2.0,3.0]",
            "primitives.sphere_radius=1.5",
            "primitives.sphere_stacks=9",
            "primitives.sphere_slices=11",
            "primitives.torus_r0=2.5",
            "primitives.torus_r1=0.75",
            "primitives.torus_n0=13",
            "primitives.torus_n1=7",
            "primitives.cone_radius=1.25",
            "primitives.cone_height=3.5",
            "primitives.cone_slices=17",
            "primitives.cylinder_radius=0.5",
            "primitives.cylinder_height=4.5",
            "primitives.cylinder_slices=19",
            "outside.show=true",
            "outside.stage=1.25",
        ];
        let mut sets: Vec<String> = samples.iter().map(|s| s.to_string()).collect();
        sets.extend(
            [
                "model.primitive=torus",
                "camera.position=[0,0,5]",
                "camera.target=[0,0,0]",
            ]
            .map(String::from),
        );
        let dir = close2gl_testkit::TempDir::new("round_trip");
        let empty = dir.write("empty.toml", b"");
        let original = load(Some(&empty), &sets).expect("the samples are valid");
        let written = args(&original, SIZE, "out");
        let back: Vec<String> = written
            .windows(2)
            .filter(|w| w[0] == "--set")
            .map(|w| w[1].clone())
            .collect();
        let mut again = back.clone();
        again.push("model.primitive=torus".into());
        let read = load(Some(&empty), &again).expect("the command's settings read back");
        assert_eq!(read, original);
        for key in KEYS.iter().filter(|k| !matches!(k.write, Write::Never)) {
            let name = format!("{}.{}=", key.section, key.name);
            let fixed = ["camera.position=", "camera.target="].contains(&name.as_str());
            assert!(
                fixed || samples.iter().any(|s| s.starts_with(&name)),
                "no sample for {name}"
            );
            assert!(
                back.iter().any(|s| s.starts_with(&name)),
                "the command lacks {name}: {back:?}"
            );
        }
    }

    /// The pairs a link would carry too: the table's keys in the table's order, their values as
    /// the configuration reads them, which the command writes as `--set key=value`.
    #[test]
    fn the_pixel_keys_are_the_tables_in_its_order() {
        let pairs = pixel_keys(&torus());
        assert_eq!(
            pairs[0],
            ("camera.position".to_string(), "[0.0,0.0,5.0]".to_string())
        );
        let table: Vec<String> = KEYS
            .iter()
            .map(|k| format!("{}.{}", k.section, k.name))
            .collect();
        let places: Vec<usize> = pairs
            .iter()
            .map(|(key, _)| {
                table
                    .iter()
                    .position(|k| k == key)
                    .expect("a key of the table")
            })
            .collect();
        assert!(places.is_sorted(), "{pairs:?}");
        let words = args(&torus(), SIZE, "out");
        for (key, value) in &pairs {
            assert!(
                words.contains(&format!("{key}={value}")),
                "{key} in {words:?}"
            );
        }
    }

    #[test]
    fn arguments_a_shell_would_change_are_quoted() {
        assert_eq!(shell_quote("camera.hfov=60.0"), "camera.hfov=60.0");
        assert_eq!(
            shell_quote("camera.u=[1.0,0.0,0.0]"),
            "'camera.u=[1.0,0.0,0.0]'"
        );
        assert_eq!(shell_quote("it's"), "'it'\\''s'");
        assert_eq!(shell_quote(""), "''");
    }
}
