// Corners already in clip coordinates (computed on the CPU: Close2GL's own P·M·p, or glam's for
// the reference), each with its colour: the fate view and the selected triangle's highlight. The
// GPU only clips and fills.

struct Corner {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec4<f32>,
}

@vertex
fn vs_main(@location(0) clip: vec4<f32>, @location(1) color: vec4<f32>) -> Corner {
    var out: Corner;
    out.clip = clip;
    out.color = color;
    return out;
}

@fragment
fn fs_main(in: Corner) -> @location(0) vec4<f32> {
    return in.color;
}
