//! Reading textures back from the GPU: wgpu copies rows padded to its copy alignment into a
//! mappable buffer, which is mapped once the copy is done and unpadded into pixels.

use crate::gpu::Gpu;

/// A mappable buffer for `layers` textures of `width` x `height` at 4 bytes a pixel, kept
/// between frames by whoever reads back every frame.
pub struct Readback {
    buffer: wgpu::Buffer,
    width: u32,
    height: u32,
    /// A row's bytes in the buffer, padded to `COPY_BYTES_PER_ROW_ALIGNMENT`.
    padded_row: u32,
}

impl Readback {
    pub fn new(device: &wgpu::Device, (width, height): (u32, u32), layers: u32) -> Readback {
        let padded_row = (width * 4).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: layers as u64 * padded_row as u64 * height as u64,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        Readback {
            buffer,
            width,
            height,
            padded_row,
        }
    }

    fn layer_bytes(&self) -> usize {
        self.padded_row as usize * self.height as usize
    }

    /// Copies each texture (of this size, 4 bytes a pixel, at most as many as the layers) into
    /// the buffer, waits for the GPU, and returns each one's pixels, rows from the top, as stored
    /// (BGRA textures come back BGRA).
    pub fn read(
        &self,
        gpu: &Gpu,
        textures: &[&wgpu::Texture],
    ) -> Result<Vec<Vec<[u8; 4]>>, String> {
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        for (layer, texture) in textures.iter().enumerate() {
            encoder.copy_texture_to_buffer(
                texture.as_image_copy(),
                wgpu::TexelCopyBufferInfo {
                    buffer: &self.buffer,
                    layout: wgpu::TexelCopyBufferLayout {
                        offset: (layer * self.layer_bytes()) as u64,
                        bytes_per_row: Some(self.padded_row),
                        rows_per_image: Some(self.height),
                    },
                },
                texture.size(),
            );
        }
        gpu.queue.submit([encoder.finish()]);
        let pixels = self.map(gpu, textures.len())?;
        self.buffer.unmap();
        Ok(pixels)
    }

    /// Maps the buffer once the copies are done and unpads the first `layers` layers.
    fn map(&self, gpu: &Gpu, layers: usize) -> Result<Vec<Vec<[u8; 4]>>, String> {
        let slice = self.buffer.slice(..);
        let bytes = map_read(gpu, &slice, "the image")?;
        let row = self.width as usize * 4;
        Ok(bytes
            .chunks_exact(self.layer_bytes())
            .take(layers)
            .map(|layer| {
                layer
                    .chunks_exact(self.padded_row as usize)
                    .flat_map(|padded| padded[..row].chunks_exact(4))
                    .map(|p| [p[0], p[1], p[2], p[3]])
                    .collect()
            })
            .collect())
    }
}

/// Maps `slice` for reading once the GPU is done with it; `what` names it in the error.
pub(crate) fn map_read<'a>(
    gpu: &Gpu,
    slice: &wgpu::BufferSlice<'a>,
    what: &str,
) -> Result<wgpu::BufferView, String> {
    let failed = |e: &dyn std::fmt::Display| format!("cannot read {what} back from the GPU: {e}");
    let (sender, receiver) = std::sync::mpsc::channel();
    slice.map_async(wgpu::MapMode::Read, move |result| {
        let _ = sender.send(result);
    });
    gpu.device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| failed(&e))?;
    receiver
        .recv()
        .map_err(|e| failed(&e))?
        .map_err(|e| failed(&e))?;
    slice.get_mapped_range().map_err(|e| failed(&e))
}
