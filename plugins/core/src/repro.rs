//! "Copy as command": the `close2gl render` line that reproduces what the views show, headless.
//! The pose is written as position, target and the camera's own u, v, n, and every number so
//! that it reads back to the same bits: the command's images are the views' pixels, not an
//! approximation of them. Render settings, lighting and primitive sizes are written only where
//! they differ from the defaults, so the line stays readable.

use std::path::{Path, PathBuf};

use bevy_ecs::world::World;
use glam::Vec3;

use crate::{
    Camera, Lighting, ModelSource, ModelStatus, NamedEnum, OutsideView, PrimitiveParams,
    RenderSettings, Texture, Viewport,
};

/// Everything that decides the two views' pixels.
#[derive(Clone, Debug)]
pub struct Repro {
    pub model: ModelSource,
    /// The image given for the texture (`None`: the built-in checkerboard).
    pub texture: Option<PathBuf>,
    pub camera: Camera,
    pub settings: RenderSettings,
    pub lighting: Lighting,
    pub primitives: PrimitiveParams,
    /// The size of each view.
    pub size: Viewport,
    /// The outside view, shown or not, and its stage (`render` writes outside.png when shown).
    pub outside: OutsideView,
}

impl Repro {
    /// What the world shows now; `None` before a model and a camera exist.
    pub fn of_world(world: &mut World) -> Option<Repro> {
        let camera = *world.query::<&Camera>().iter(world).next()?;
        let model = world.get_resource::<ModelStatus>()?.source.clone()?;
        Some(Repro {
            model,
            texture: world
                .get_resource::<Texture>()
                .and_then(|t| t.source.clone()),
            camera,
            settings: *world.get_resource::<RenderSettings>()?,
            lighting: *world.get_resource::<Lighting>()?,
            // Only a primitive's own view depends on them.
            primitives: world
                .get_resource::<PrimitiveParams>()
                .copied()
                .unwrap_or_default(),
            size: *world.get_resource::<Viewport>()?,
            outside: world
                .get_resource::<OutsideView>()
                .copied()
                .unwrap_or_default(),
        })
    }

    /// The arguments after `close2gl`, unquoted: `render MODEL --size WxH --set ... --out DIR`.
    pub fn args(&self, out: &str) -> Vec<String> {
        let model = match &self.model {
            ModelSource::File(path) => absolute(path).display().to_string(),
            ModelSource::Primitive(kind) => kind.name().to_string(),
        };
        let size = format!("{}x{}", self.size.width, self.size.height);
        let mut args = vec!["render".into(), model, "--size".into(), size];
        for set in self.overrides() {
            args.extend(["--set".into(), set]);
        }
        args.extend(["--out".into(), out.into()]);
        args
    }

    /// The command line, each argument quoted for a POSIX shell where it needs to be.
    pub fn command(&self, out: &str) -> String {
        let mut line = String::from("close2gl");
        for arg in self.args(out) {
            line.push(' ');
            line.push_str(&shell_quote(&arg));
        }
        line
    }

    /// `section.key=value` for the pose, the lens, and every setting off its default.
    fn overrides(&self) -> Vec<String> {
        let c = &self.camera;
        let mut sets = Overrides::default();
        sets.vec3("camera.position", c.position);
        sets.vec3("camera.target", c.target);
        sets.vec3("camera.u", c.u);
        sets.vec3("camera.v", c.v);
        sets.vec3("camera.n", c.n);
        for (key, value) in [
            ("camera.hfov", c.hfov),
            ("camera.vfov", c.vfov),
            ("camera.near", c.near),
            ("camera.far", c.far),
        ] {
            sets.number(key, value);
        }
        if let Some(texture) = &self.texture {
            sets.text("model.texture", &absolute(texture).display().to_string());
        }
        self.render_overrides(&mut sets);
        self.lighting_overrides(&mut sets);
        let (o, d) = (&self.outside, &OutsideView::default());
        sets.flag_if("outside.show", o.show, d.show);
        sets.number_if("outside.stage", o.stage, d.stage);
        if matches!(self.model, ModelSource::Primitive(_)) {
            self.primitive_overrides(&mut sets);
        }
        sets.0
    }

    fn render_overrides(&self, sets: &mut Overrides) {
        let (s, d) = (&self.settings, &RenderSettings::default());
        sets.named_if("render.mode", s.mode, d.mode);
        sets.named_if("render.front_face", s.front_face, d.front_face);
        sets.flag_if(
            "render.backface_culling",
            s.backface_culling,
            d.backface_culling,
        );
        sets.named_if("render.clipping", s.clipping, d.clipping);
        sets.vec3_if("render.color", s.color, d.color);
        sets.named_if("render.shading", s.shading, d.shading);
        sets.vec3_if("render.background", s.background, d.background);
        sets.named_if(
            "render.close2gl_raster",
            s.close2gl_raster,
            d.close2gl_raster,
        );
        sets.flag_if("render.texture", s.texture, d.texture);
        sets.named_if("render.texture_filter", s.texture_filter, d.texture_filter);
        sets.named_if("render.overlay", s.overlay, d.overlay);
    }

    fn lighting_overrides(&self, sets: &mut Overrides) {
        let (l, d) = (&self.lighting, &Lighting::default());
        sets.vec3_if(
            "lighting.light_position",
            l.light_position,
            d.light_position,
        );
        sets.vec3_if("lighting.ia", l.ia, d.ia);
        sets.vec3_if("lighting.il", l.il, d.il);
        sets.number_if("lighting.ka", l.ka, d.ka);
        sets.number_if("lighting.kd", l.kd, d.kd);
        sets.number_if("lighting.ks", l.ks, d.ks);
        sets.number_if("lighting.shininess", l.shininess, d.shininess);
        if l.attenuation != d.attenuation {
            sets.push("lighting.attenuation", list(&l.attenuation));
        }
    }

    fn primitive_overrides(&self, sets: &mut Overrides) {
        let (p, d) = (&self.primitives, &PrimitiveParams::default());
        sets.vec3_if("primitives.box_size", p.box_size, d.box_size);
        for (key, value, default) in [
            ("sphere_radius", p.sphere_radius, d.sphere_radius),
            ("torus_r0", p.torus_r0, d.torus_r0),
            ("torus_r1", p.torus_r1, d.torus_r1),
            ("cone_radius", p.cone_radius, d.cone_radius),
            ("cone_height", p.cone_height, d.cone_height),
            ("cylinder_radius", p.cylinder_radius, d.cylinder_radius),
            ("cylinder_height", p.cylinder_height, d.cylinder_height),
        ] {
            sets.number_if(&format!("primitives.{key}"), value, default);
        }
        for (key, value, default) in [
            ("sphere_stacks", p.sphere_stacks, d.sphere_stacks),
            ("sphere_slices", p.sphere_slices, d.sphere_slices),
            ("torus_n0", p.torus_n0, d.torus_n0),
            ("torus_n1", p.torus_n1, d.torus_n1),
            ("cone_slices", p.cone_slices, d.cone_slices),
            ("cylinder_slices", p.cylinder_slices, d.cylinder_slices),
        ] {
            if value != default {
                sets.push(&format!("primitives.{key}"), value.to_string());
            }
        }
    }
}

/// The `section.key=value` list being written.
#[derive(Default)]
struct Overrides(Vec<String>);

impl Overrides {
    fn push(&mut self, key: &str, value: String) {
        self.0.push(format!("{key}={value}"));
    }

    fn number(&mut self, key: &str, x: f32) {
        self.push(key, exact(x));
    }

    fn vec3(&mut self, key: &str, v: Vec3) {
        self.push(key, list(&v.to_array()));
    }

    fn text(&mut self, key: &str, text: &str) {
        // A TOML basic string: backslashes and quotes escaped.
        let escaped = text.replace('\\', "\\\\").replace('"', "\\\"");
        self.push(key, format!("\"{escaped}\""));
    }

    fn number_if(&mut self, key: &str, x: f32, default: f32) {
        if x != default {
            self.number(key, x);
        }
    }

    fn vec3_if(&mut self, key: &str, v: Vec3, default: Vec3) {
        if v != default {
            self.vec3(key, v);
        }
    }

    fn flag_if(&mut self, key: &str, on: bool, default: bool) {
        if on != default {
            self.push(key, on.to_string());
        }
    }

    fn named_if<T: NamedEnum + PartialEq>(&mut self, key: &str, value: T, default: T) {
        if value != default {
            self.push(key, value.name().to_string());
        }
    }
}

/// A number that reads back (as TOML's f64, then f32, as the config reads it) to the same
/// bits: the shortest form when that round-trips, else the f64 form, which always does.
fn exact(x: f32) -> String {
    let short = format!("{x:?}");
    if short.parse::<f64>().is_ok_and(|back| back as f32 == x) {
        short
    } else {
        format!("{:?}", x as f64)
    }
}

fn list(values: &[f32]) -> String {
    let items: Vec<String> = values.iter().map(|&x| exact(x)).collect();
    format!("[{}]", items.join(","))
}

/// The path as the command's reader's shell will find it from anywhere.
fn absolute(path: &Path) -> PathBuf {
    std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf())
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
    use crate::{PrimitiveKind, Shading};

    fn repro() -> Repro {
        Repro {
            model: ModelSource::Primitive(PrimitiveKind::Torus),
            texture: None,
            camera: Camera::default(),
            settings: RenderSettings::default(),
            lighting: Lighting::default(),
            primitives: PrimitiveParams::default(),
            size: Viewport {
                width: 640,
                height: 480,
            },
            outside: OutsideView::default(),
        }
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
        let mut r = repro();
        let plain = r.command("out");
        assert!(plain.starts_with("close2gl render torus --size 640x480 --set "));
        assert!(!plain.contains("render."), "{plain}");
        r.settings.shading = Shading::Phong;
        r.primitives.torus_n0 = 7;
        r.lighting.attenuation = [1.0, 0.5, 0.0];
        r.outside.show = true;
        r.outside.stage = 1.25;
        let changed = r.args("out");
        for set in [
            "render.shading=phong",
            "primitives.torus_n0=7",
            "lighting.attenuation=[1.0,0.5,0.0]",
            "camera.u=[1.0,0.0,0.0]",
            "outside.show=true",
            "outside.stage=1.25",
        ] {
            assert!(changed.iter().any(|a| a == set), "{set} in {changed:?}");
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
