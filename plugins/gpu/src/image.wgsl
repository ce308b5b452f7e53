// An image in place of a view (the software rasterizer's, a raster trace's), one texel per pixel. textureLoad,
// not a sampler: no filtering, no rounding, the bytes Close2GL wrote are the bytes on screen.

@group(0) @binding(0) var image: texture_2d<f32>;

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    return textureLoad(image, texel_at(in.uv, textureDimensions(image)), 0);
}
