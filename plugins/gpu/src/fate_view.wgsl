// The fate view: Close2GL's own clip coordinates (P·M·p, computed on the CPU by Close2GL's
// matrices), each triangle in its fate's colour. The GPU only clips and fills; depth comes from
// the host's back-to-front order, not a depth buffer.

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
