//! The render settings both views share, split by who reads them (the pipeline's switches, the
//! model's appearance, the overlay), and the named choices in them (shading, clipping, overlay,
//! the injected mistake, ...).

use bevy_ecs::prelude::*;
use glam::Vec3;

named_enum!(
    /// glPolygonMode: what each surviving triangle becomes.
    RenderMode { Points = "points", Wireframe = "wireframe", Solid = "solid" }
);
named_enum!(
    /// glFrontFace: which winding, as seen on screen, faces the camera.
    FrontFace { Ccw = "ccw", Cw = "cw" }
);
named_enum!(
    /// How Close2GL clips against the view volume.
    Clipping {
        /// The assignment's rule: drop a triangle when any vertex is outside |x|,|y|,|z| <= w.
        Simple = "simple",
        /// Cut triangles against the view volume in clip space, as a GPU does.
        Full = "full"
    }
);
named_enum!(
    /// Who turns Close2GL's output into pixels.
    Rasterizer {
        /// The assignment's rule: the GPU draws Close2GL's 2D primitives in one flat colour.
        Gpu = "gpu",
        /// Close2GL's own software rasterizer: z-buffer, fill rule and the four shadings.
        Software = "software"
    }
);
named_enum!(
    /// How a texture is sampled between and across its texels (OpenGL's min/mag filters).
    TextureFilter {
        /// The texel the point falls in (GL_NEAREST), from the full-size image.
        Nearest = "nearest",
        /// The four nearest texels, weighted (GL_LINEAR), from the full-size image.
        Bilinear = "bilinear",
        /// Bilinear in the two mipmap levels whose texel size brackets the pixel's footprint,
        /// blended (GL_LINEAR_MIPMAP_LINEAR).
        Trilinear = "trilinear"
    }
);
named_enum!(
    /// The lighting of both views (with the GPU rasterizer, Close2GL's view stays flat colour).
    Shading {
        None = "none",
        GouraudAd = "gouraud_ad",
        GouraudAds = "gouraud_ads",
        Phong = "phong"
    }
);

impl Shading {
    /// Whether its lighting has the specular term (Gouraud ADS and Phong; Gouraud AD is
    /// ambient and diffuse alone).
    pub fn specular(self) -> bool {
        matches!(self, Shading::GouraudAds | Shading::Phong)
    }

    /// Whether it lights each vertex and interpolates the intensity (Gouraud), rather than
    /// each pixel from the interpolated position and normal (Phong).
    pub fn per_vertex(self) -> bool {
        matches!(self, Shading::GouraudAd | Shading::GouraudAds)
    }
}

named_enum!(
    /// What the two views show over the model: nothing, or one of the inspector's displays. A
    /// resource of its own: the GPU views, the panel's legends and the fate recording read it,
    /// and switching it recomputes nothing of the pipeline's.
    #[derive(Resource, Default)]
    Overlay {
        /// The model as rendered.
        #[default]
        Off = "off",
        /// Close2GL's view coloured by each triangle's fate (`Fates`), with ghosts of what
        /// clipping and culling removed; the reference view with what its GPU knows (facing,
        /// the depth test's outcome).
        FateView = "fate_view",
        /// Close2GL's view replaced by where the two views differ: covered only in the
        /// reference (magenta), only in Close2GL (green), the reference faded elsewhere.
        Difference = "difference"
    }
);

named_enum!(
    /// A classic mistake of the assignment, injected into Close2GL so that its symptom shows
    /// beside the reference: one line each here, every choice pinned in the pipeline's
    /// `mistakes` module and `trace-format.md`.
    Mistake {
        /// Close2GL as the textbook has it.
        None = "none",
        /// right = near·tan(hfov), top = near·tan(vfov).
        FovNotHalved = "fov_not_halved",
        /// The tangent of half the angle's number of degrees, taken as radians.
        FovInDegrees = "fov_in_degrees",
        /// The vertical extent from hfov, the horizontal from vfov.
        FovsSwapped = "fovs_swapped",
        /// right = top·hfov/vfov.
        AspectFromAngles = "aspect_from_angles",
        /// M transposed.
        ModelviewTransposed = "modelview_transposed",
        /// M's translation is −c.
        TranslationUnrotated = "translation_unrotated",
        /// M's translation is (+c·u, +c·v, +c·n).
        TranslationSign = "translation_sign",
        /// u = n × v.
        LeftHanded = "left_handed",
        /// clip = (M·P)·p.
        ProductOrder = "product_order",
        /// Divide first; drop a triangle with w = 0 or |x/w| > 1 or |y/w| > 1 at a corner.
        DivideBeforeClip = "divide_before_clip",
        /// Every triangle drawn whole, except one with a corner at w = 0.
        NoClipping = "no_clipping",
        /// P's third row negated.
        DepthRowSign = "depth_row_sign",
        /// V's y scale negated.
        ViewportYFlipped = "viewport_y_flipped",
        /// V scales by R−L and T−B instead of their halves.
        ViewportFullScale = "viewport_full_scale",
        /// The opposite winding is front.
        CullingInverted = "culling_inverted",
        /// Back when N·(c − p0) < 0, N the file's face normal.
        CullingByFileNormals = "culling_by_file_normals",
        /// Back when ((p1 − p0) × (p2 − p0))·n < 0.
        CullingByViewAxis = "culling_by_view_axis",
        /// Culling declared, nothing culled.
        NeverCulls = "never_culls",
        /// Counter-clockwise is front, whatever is declared.
        CullingIgnoresFrontFace = "culling_ignores_front_face"
    }
);

/// How Close2GL's pipeline turns the mesh into primitives, as the assignment names its
/// switches: glPolygonMode (`mode`), glFrontFace and backface culling, the clipping rule, the
/// classic mistake it makes on purpose, and who rasterizes its output (the pipeline hands the
/// software rasterizer its per-vertex data only when asked). The pipeline reads all of it; the
/// reference view follows the same mode and culling, the raster plugin and the GPU upload ask who
/// rasterizes. A change recomputes the Close2GL frame.
#[derive(Resource, Clone, Copy, Debug, PartialEq)]
pub struct PipelineSettings {
    pub mode: RenderMode,
    pub front_face: FrontFace,
    pub backface_culling: bool,
    pub clipping: Clipping,
    /// Who draws the Close2GL view's pixels.
    pub close2gl_raster: Rasterizer,
    /// A classic mistake Close2GL makes on purpose (`none`: the right pipeline).
    pub mistake: Mistake,
}

impl Default for PipelineSettings {
    fn default() -> Self {
        Self {
            mode: RenderMode::Solid,
            front_face: FrontFace::Ccw,
            backface_culling: true,
            clipping: Clipping::Full,
            close2gl_raster: Rasterizer::Gpu,
            mistake: Mistake::None,
        }
    }
}

/// How the model looks in both views: its colour and shading, the background, its texture and
/// the texture's filter, and the rasterizer assignment's mistake Close2GL's own rasterizer makes
/// on purpose. The software rasterizer and the GPU views read it; the pipeline never does, so a
/// change redraws pixels without recomputing the geometry.
#[derive(Resource, Clone, Copy, Debug, PartialEq)]
pub struct Appearance {
    /// The model's colour, RGB in 0..1.
    pub color: Vec3,
    pub shading: Shading,
    /// The background both views clear to.
    pub background: Vec3,
    /// Whether a model with texture coordinates is textured (the texture modulates the shaded
    /// colour).
    pub texture: bool,
    pub texture_filter: TextureFilter,
    /// A classic mistake of the rasterizer assignment (`none`: the right rasterizer), which
    /// Close2GL's software rasterizer makes when it draws: the textbook rasterizer then draws
    /// the view, with the mistake (docs/checking.md, "The rasterizer assignment").
    pub raster_mistake: crate::RasterMistake,
}

impl Default for Appearance {
    fn default() -> Self {
        Self {
            color: Vec3::new(0.85, 0.65, 0.25),
            shading: Shading::None,
            background: Vec3::new(0.08, 0.08, 0.1),
            texture: true,
            texture_filter: TextureFilter::Trilinear,
            raster_mistake: crate::RasterMistake::None,
        }
    }
}

/// Inserts `value` unless `world` already holds an equal one. Inserting marks a resource
/// changed even when its value is the same, and every system that follows it (the pipeline,
/// the rasterizer) would run again: a reload that changed only the background would recompute
/// the geometry.
pub fn insert_if_changed<R: Resource + PartialEq>(world: &mut World, value: R) {
    if world.get_resource::<R>() != Some(&value) {
        world.insert_resource(value);
    }
}

/// The lighting of the shading lecture (002): I = Ia·ka + f_att·Il·(kd·cosθ + ks·cosⁿα), with
/// f_att = min(1 / (c0 + c1·d + c2·d²), 1). The light is given in world coordinates.
#[derive(Resource, Clone, Copy, Debug, PartialEq)]
pub struct Lighting {
    pub light_position: Vec3,
    pub ia: Vec3,
    pub il: Vec3,
    pub ka: f32,
    pub kd: f32,
    pub ks: f32,
    pub shininess: f32,
    pub attenuation: [f32; 3],
}

impl Default for Lighting {
    fn default() -> Self {
        Self {
            light_position: Vec3::new(10.0, 10.0, 3.0),
            ia: Vec3::new(0.3, 1.0, 0.3),
            il: Vec3::ONE,
            ka: 0.3,
            kd: 0.8,
            ks: 0.5,
            shininess: 10.0,
            attenuation: [0.01, 0.001, 0.0],
        }
    }
}
