//! The reference view's half of the fate view: the GPU's own answers, not Close2GL's. After the
//! shaded draw, the mesh is drawn twice more with the same vertex stage, culling and polygon
//! mode: once with the depth test `LessEqual` (the fragments that won it) coloured by WGSL's
//! `front_facing` (front: the drawn colour, back: the culled colour), once with the test reversed
//! (`Greater`: the fragments it rejected) in the hidden colour, as RenderDoc's depth overlay.

use close2gl_core::FateKind;

use super::{Drawing, PipelineKey, Reference};

/// The two overlay pipelines for one reference pipeline key.
pub(super) struct OverlayPipelines {
    facing: wgpu::RenderPipeline,
    depth_failed: wgpu::RenderPipeline,
}

/// A legend colour as the shader's packed override (0x00BBGGRR, `unpack4x8unorm`'s order).
fn packed(kind: FateKind) -> f64 {
    let [r, g, b] = kind.color();
    f64::from(u32::from_le_bytes([r, g, b, 0]))
}

impl Reference {
    pub(super) fn create_overlays(
        &self,
        device: &wgpu::Device,
        key: PipelineKey,
    ) -> OverlayPipelines {
        let colors = [
            ("FRONT_COLOR", packed(FateKind::Drawn)),
            ("BACK_COLOR", packed(FateKind::Culled)),
            ("FAILED_COLOR", packed(FateKind::Hidden)),
        ];
        let overlay = |fragment, depth_compare| Drawing {
            fragment,
            depth_write: false,
            depth_compare,
            blend: Some(wgpu::BlendState::ALPHA_BLENDING),
            constants: &colors,
        };
        let facing = overlay("fs_facing", wgpu::CompareFunction::LessEqual);
        let depth_failed = overlay("fs_depth_failed", wgpu::CompareFunction::Greater);
        OverlayPipelines {
            facing: self.create_drawing(device, key, &facing),
            depth_failed: self.create_drawing(device, key, &depth_failed),
        }
    }

    /// Records the overlays over the shaded reference, in the same pass (its depth buffer holds
    /// the winners). Nothing before the first update.
    pub(super) fn draw_overlays(&self, pass: &mut wgpu::RenderPass<'_>) {
        let Some((key, _)) = self.current else {
            return;
        };
        let Some(overlays) = self.overlays.get(&key) else {
            return;
        };
        for pipeline in [&overlays.facing, &overlays.depth_failed] {
            self.draw_with(pass, pipeline);
        }
    }
}
