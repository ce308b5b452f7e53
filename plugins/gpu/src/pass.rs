//! How every view is drawn: one pass recorded and submitted, timed where a view's time is
//! reported. The windows and the offscreen target both go through here, so they draw alike.

use crate::attachments;
use crate::gpu::Gpu;

/// Records one pass into `target` (its depth, when given, cleared to the far plane) and submits
/// it. The windows and the offscreen target draw every view through this, so they draw alike.
pub fn submit_pass(
    gpu: &Gpu,
    target: &wgpu::TextureView,
    depth: Option<&wgpu::TextureView>,
    load: wgpu::LoadOp<wgpu::Color>,
    record: impl FnOnce(&mut wgpu::RenderPass<'_>),
) {
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("view"),
            color_attachments: &[Some(attachments::color_attachment(target, load))],
            depth_stencil_attachment: depth.map(attachments::depth_attachment),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        record(&mut pass);
    }
    gpu.queue.submit([encoder.finish()]);
}

/// [`submit_pass`], then waits for the GPU to finish it: a view's time is its own recording and
/// the GPU's work on it. Returns the milliseconds it took. The windows and the offscreen target
/// time every view this way.
pub fn submit_pass_timed(
    gpu: &Gpu,
    target: &wgpu::TextureView,
    depth: Option<&wgpu::TextureView>,
    load: wgpu::LoadOp<wgpu::Color>,
    record: impl FnOnce(&mut wgpu::RenderPass<'_>),
) -> f64 {
    let start = web_time::Instant::now();
    submit_pass(gpu, target, depth, load, record);
    // A failed wait means a lost device; the next acquire or readback reports it.
    let _ = gpu.device.poll(wgpu::PollType::Wait {
        submission_index: None,
        timeout: Some(std::time::Duration::from_secs(30)),
    });
    start.elapsed().as_secs_f64() * 1e3
}
