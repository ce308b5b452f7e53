// The live difference: the same picture as `close2gl render`'s diff.png (parity::diff_image),
// from the two views drawn this frame. A pixel is covered when its stored bytes differ from the
// background's; covered in one view only, it is painted that view's colour; everywhere else the
// reference shows through, faded three quarters of the way to white.

@group(0) @binding(0) var reference: texture_2d<f32>;
@group(0) @binding(1) var close2gl: texture_2d<f32>;
// The background as a UNORM target stores it, 0..255.
@group(0) @binding(2) var<uniform> background: vec4<f32>;

const ONLY_REFERENCE = vec4<f32>(1.0, 0.0, 1.0, 1.0);
const ONLY_CLOSE2GL = vec4<f32>(0.0, 1.0, 0.0, 1.0);

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    let texel = texel_at(in.uv, textureDimensions(reference));
    // The stored bytes: unorm values times 255, rounded back to the integers they were.
    let r = round(textureLoad(reference, texel, 0).rgb * 255.0);
    let c = round(textureLoad(close2gl, texel, 0).rgb * 255.0);
    let in_reference = any(r != background.rgb);
    let in_close2gl = any(c != background.rgb);
    if in_reference && !in_close2gl {
        return ONLY_REFERENCE;
    }
    if in_close2gl && !in_reference {
        return ONLY_CLOSE2GL;
    }
    // (x + 3 * 255) / 4 in integers, as the CPU's diff does.
    return vec4<f32>(floor((r + 765.0) / 4.0) / 255.0, 1.0);
}
