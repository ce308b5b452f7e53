//! Records the views into a window's texture, one timed submission per view.

use web_time::{Duration, Instant};

use close2gl_core::View;
use close2gl_gpu::outside::OutsideRenderer;
use close2gl_gpu::{Gpu, Views, submit_pass_timed};
use close2gl_ui::ViewStats;

use crate::view_layout::Placed;

/// The GPU state of every view: the two compared, and the outside view when there is one.
#[derive(Clone, Copy)]
pub struct AllViews<'a> {
    pub views: &'a Views,
    pub outside: Option<&'a OutsideRenderer>,
}

/// When each compared view was drawn this frame and how long it took, for `ViewStats`.
#[derive(Default)]
pub struct ViewTimes {
    reference: Option<(Instant, Duration)>,
    close2gl: Option<(Instant, Duration)>,
}

/// Clears `target` to `clear` (the background: opaque for a window, alpha 0 for a capture whose
/// alpha is the views' coverage) and draws `placed` into it. Each view is its own submission,
/// waited on, so that its time covers the GPU's work as well as the recording; the two compared
/// views' times go to `times` when given.
pub fn draw_views(
    gpu: &Gpu,
    all: AllViews<'_>,
    (target, depth): (&wgpu::TextureView, &wgpu::TextureView),
    clear: wgpu::Color,
    placed: &[Placed],
    mut times: Option<&mut ViewTimes>,
) {
    let mut load = wgpu::LoadOp::Clear(clear);
    if placed.is_empty() {
        submit_pass_timed(gpu, target, None, load, |_| ());
    }
    for p in placed {
        let start = Instant::now();
        let ms = draw_view(gpu, all, target, depth, *p, load);
        load = wgpu::LoadOp::Load;
        if let Some(times) = times.as_deref_mut() {
            let took = Some((start, Duration::from_secs_f64(ms / 1e3)));
            match p.view {
                View::Reference => times.reference = took,
                View::Close2gl => times.close2gl = took,
                View::Outside => {}
            }
        }
    }
}

/// The compared views' times into the panel's frame timers.
pub fn record_times(stats: &mut ViewStats, times: &ViewTimes) {
    for (timer, time) in [
        (&mut stats.reference, times.reference),
        (&mut stats.close2gl, times.close2gl),
    ] {
        if let Some((start, took)) = time {
            timer.record(start, took);
        }
    }
}

/// One view into its rectangle of `target` (the reference with the depth buffer), submitted
/// and waited on, so that each view's frame time is its own; returns its milliseconds.
fn draw_view(
    gpu: &Gpu,
    AllViews { views, outside }: AllViews<'_>,
    target: &wgpu::TextureView,
    depth: &wgpu::TextureView,
    placed: Placed,
    load: wgpu::LoadOp<wgpu::Color>,
) -> f64 {
    let rect = placed.rect;
    let set_viewport = |pass: &mut wgpu::RenderPass<'_>| {
        let (x, y) = (rect.x as f32, rect.y as f32);
        pass.set_viewport(x, y, rect.width as f32, rect.height as f32, 0.0, 1.0);
    };
    match placed.view {
        View::Reference => submit_pass_timed(gpu, target, Some(depth), load, |pass| {
            set_viewport(pass);
            views.draw_reference(pass);
        }),
        View::Close2gl => submit_pass_timed(gpu, target, None, load, |pass| {
            set_viewport(pass);
            views.draw_close2gl(pass);
        }),
        View::Outside => submit_pass_timed(gpu, target, Some(depth), load, |pass| {
            set_viewport(pass);
            if let Some(outside) = outside {
                outside.draw(pass);
            }
        }),
    }
}
