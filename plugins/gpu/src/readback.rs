//! Reading textures back from the GPU: wgpu copies rows padded to its copy alignment into a
//! mappable buffer, which is mapped once the copy is done and unpadded into pixels.

use std::sync::{Arc, Condvar, Mutex};

use crate::gpu::Gpu;

/// A mappable buffer for `layers` textures of `width` x `height` at 4 bytes a pixel, kept
/// between frames by whoever reads back every frame.
#[derive(Clone)]
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

    /// The first `layers` layers of the mapped `bytes`, each row without its padding.
    fn unpad(&self, bytes: &[u8], layers: usize) -> Vec<Vec<[u8; 4]>> {
        let row = self.width as usize * 4;
        bytes
            .chunks_exact(self.layer_bytes())
            .take(layers)
            .map(|layer| {
                layer
                    .chunks_exact(self.padded_row as usize)
                    .flat_map(|padded| padded[..row].chunks_exact(4))
                    .map(|p| [p[0], p[1], p[2], p[3]])
                    .collect()
            })
            .collect()
    }

    /// Copies each texture (of this size, 4 bytes a pixel, at most as many as the layers) into
    /// the buffer, waits for the GPU, and returns each one's pixels, rows from the top, as stored
    /// (BGRA textures come back BGRA).
    pub fn read(
        &self,
        gpu: &Gpu,
        textures: &[&wgpu::Texture],
    ) -> Result<Vec<Vec<[u8; 4]>>, String> {
        let pending = self.start(gpu, textures);
        pending
            .mapping
            .wait(gpu, "the image", |bytes| self.unpad(bytes, pending.layers))
    }

    /// [`Self::read`] without the wait: the copies are submitted and the buffer is mapped once
    /// the GPU is done, which [`Pending::finish`] asks after. In a browser nothing can wait for
    /// the GPU (WebGL2 sees it done only once the page's task has ended): ask again each frame.
    pub fn start(&self, gpu: &Gpu, textures: &[&wgpu::Texture]) -> Pending {
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
        Pending {
            mapping: Mapping::start(self.buffer.clone()),
            readback: self.clone(),
            layers: textures.len(),
        }
    }
}

/// Textures on their way back from the GPU ([`Readback::start`]).
pub struct Pending {
    mapping: Mapping,
    readback: Readback,
    layers: usize,
}

impl Pending {
    /// Each texture's pixels once the GPU has copied them; `None` while it has not yet.
    pub fn finish(&self, gpu: &Gpu) -> Option<Result<Vec<Vec<[u8; 4]>>, String>> {
        self.mapping.finish(gpu, "the image", |bytes| {
            self.readback.unpad(bytes, self.layers)
        })
    }
}

/// A buffer asked to be mapped for reading once the GPU is done writing it: asked after each
/// frame in a browser (where nothing can wait for the GPU), waited for elsewhere.
pub(crate) struct Mapping {
    buffer: wgpu::Buffer,
    mapped: Arc<MapSlot>,
}

/// Where wgpu's callback leaves the mapping's outcome, and the signal that it has: the callback
/// may run on another thread's poll of the shared device, after this thread's poll has returned.
#[derive(Default)]
struct MapSlot {
    outcome: Mutex<Option<Result<(), wgpu::BufferAsyncError>>>,
    arrived: Condvar,
}

impl Mapping {
    /// Asks for `buffer` (its copies already submitted) to be mapped.
    pub(crate) fn start(buffer: wgpu::Buffer) -> Mapping {
        let mapped = Arc::new(MapSlot::default());
        let slot = Arc::clone(&mapped);
        buffer
            .slice(..)
            .map_async(wgpu::MapMode::Read, move |result| {
                if let Ok(mut outcome) = slot.outcome.lock() {
                    *outcome = Some(result);
                    slot.arrived.notify_all();
                }
            });
        Mapping { buffer, mapped }
    }

    /// `read` of the buffer's bytes once it is mapped (then unmapped); `None` while it is not
    /// yet. `what` names the bytes in the error.
    pub(crate) fn finish<T>(
        &self,
        gpu: &Gpu,
        what: &str,
        read: impl FnOnce(&[u8]) -> T,
    ) -> Option<Result<T, String>> {
        let _ = gpu.device.poll(wgpu::PollType::Poll);
        let outcome = self.mapped.outcome.lock().ok()?.take()?;
        Some(self.read(outcome, what, read))
    }

    /// [`Self::finish`], waiting for the GPU and then for the callback, wherever it runs.
    pub(crate) fn wait<T>(
        &self,
        gpu: &Gpu,
        what: &str,
        read: impl FnOnce(&[u8]) -> T,
    ) -> Result<T, String> {
        gpu.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| failed(what, &e))?;
        let lock = self.mapped.outcome.lock().map_err(|e| failed(what, &e))?;
        let mut outcome = self
            .mapped
            .arrived
            .wait_while(lock, |outcome| outcome.is_none())
            .map_err(|e| failed(what, &e))?;
        let outcome = outcome.take().unwrap_or(Ok(()));
        self.read(outcome, what, read)
    }

    fn read<T>(
        &self,
        outcome: Result<(), wgpu::BufferAsyncError>,
        what: &str,
        read: impl FnOnce(&[u8]) -> T,
    ) -> Result<T, String> {
        let value = outcome.map_err(|e| failed(what, &e)).and_then(|()| {
            let bytes = self.buffer.slice(..).get_mapped_range();
            Ok(read(&bytes.map_err(|e| failed(what, &e))?))
        });
        self.buffer.unmap();
        value
    }
}

fn failed(what: &str, e: &dyn std::fmt::Display) -> String {
    format!("cannot read {what} back from the GPU: {e}")
}
