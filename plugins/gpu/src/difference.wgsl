// The live difference: the same picture as `close2gl render`'s diff.png (parity::diff_image),
// from the two views drawn this frame into textures cleared with alpha 0. A pixel is covered
// when its view drew it, alpha 1: never decided by colour, which GPUs round differently. Covered
// in one view only, it is painted that view's colour; everywhere else the reference shows
// through, faded three quarters of the way to white.

@group(0) @binding(0) var reference: texture_2d<f32>;
@group(0) @binding(1) var close2gl: texture_2d<f32>;

const ONLY_REFERENCE = vec4<f32>(1.0, 0.0, 1.0, 1.0);
const ONLY_CLOSE2GL = vec4<f32>(0.0, 1.0, 0.0, 1.0);

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    let texel = texel_at(in.uv, textureDimensions(reference));
    let r = textureLoad(reference, texel, 0);
    let c = textureLoad(close2gl, texel, 0);
    // Alpha is stored as 0 or 255: anything above half is a drawn pixel.
    let in_reference = r.a > 0.5;
    let in_close2gl = c.a > 0.5;
    if in_reference && !in_close2gl {
        return ONLY_REFERENCE;
    }
    if in_close2gl && !in_reference {
        return ONLY_CLOSE2GL;
    }
    // The stored bytes (unorm values times 255, rounded back to the integers they were), then
    // (x + 3 * 255) / 4 in integers, as the CPU's diff does.
    let bytes = round(r.rgb * 255.0);
    return vec4<f32>(floor((bytes + 765.0) / 4.0) / 255.0, 1.0);
}
