//! The line test of `pixel_shapes.wgsl` on a real adapter: the fragments a line's rectangle
//! keeps without polygon modes (`line_covers`, in emulated 64-bit integer arithmetic) are the
//! pixels Close2GL's software rasterizer draws for the same line, for many lines: short and
//! long (products of fixed-point differences far beyond i32), any slope, ends on the pixel grid
//! and off it, sides exactly through pixel centres, and lines of no length.

use close2gl_core::{
    Appearance, Camera, Close2glFrame, Lighting, RasterGeometry, RasterVertex, Topology, Viewport,
};
use close2gl_gpu::wgpu;
use close2gl_gpu::wgpu::util::DeviceExt;
use close2gl_testkit::gpu;

/// The viewport both draw into: one u32 of coverage bits a row.
const SIZE: u32 = 32;

/// For each line (x0, y0, x1, y1) and row: the bits of the row's pixels `line_covers` keeps;
/// and for each line its exact rectangle (ends, then across), to count the centres on its sides.
const TEST_SHADER: &str = r#"
@group(0) @binding(0) var<storage, read> lines: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read_write> rows: array<u32>;
@group(0) @binding(2) var<storage, read_write> exact: array<vec4<i32>>;

@compute @workgroup_size(32)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let line = id.x / 32u;
    if line >= arrayLength(&lines) {
        return;
    }
    let ends = lines[line];
    let rectangle = line_corner(0u, ends.xy, ends.zw).line;
    var bits = 0u;
    for (var x = 0u; x < 32u; x++) {
        let centre = vec3<f32>(vec2<f32>(f32(x), f32(id.x % 32u)) + 0.5, 1.0);
        bits |= select(0u, 1u << x, line_covers(rectangle, centre));
    }
    rows[id.x] = bits;
    exact[line * 2u] = rectangle.ends;
    exact[line * 2u + 1u] = vec4<i32>(rectangle.across, 0, 0);
}
"#;

/// A small xorshift generator: the same lines on every run.
struct Random(u64);

impl Random {
    fn next(&mut self) -> f32 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f32 / (1u64 << 53) as f32
    }

    fn between(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.next()
    }
}

/// Lines over and around the viewport, a fifth of each kind.
fn lines(count: usize) -> Vec<[f32; 4]> {
    let mut random = Random(0x2545_f491_4f6c_dd1d);
    let size = SIZE as f32;
    (0..count)
        .map(|i| {
            let mut point = |grid: f32| {
                let p = random.between(-4.0, size + 4.0);
                (p * grid).round() / grid
            };
            match i % 5 {
                // Across or down, ends on whole and half pixels: sides through rows of centres.
                0 => {
                    let (x, y, along) = (point(2.0), point(2.0), point(2.0));
                    match i % 2 {
                        0 => [x, y, along, y],
                        _ => [x, y, x, along],
                    }
                }
                // Ends on whole and half pixels, any slope.
                1 => [point(2.0), point(2.0), point(2.0), point(2.0)],
                // Ends anywhere on the 1/256 grid, and off it.
                2 => [point(256.0), point(256.0), point(1e6), point(1e6)],
                // Long: through the viewport, ends up to a million pixels away.
                3 => {
                    let (x, y) = (point(4.0), point(4.0));
                    let angle = random.between(0.0, std::f32::consts::TAU);
                    let (s, c) = angle.sin_cos();
                    let (near, far) = (random.between(1e3, 1e6), random.between(1e3, 1e6));
                    [x - c * near, y - s * near, x + c * far, y + s * far]
                }
                // No length, or ends a fraction of a grid step apart.
                _ => {
                    let (x, y) = (point(256.0), point(256.0));
                    let d = random.between(0.0, 1.0 / 1024.0);
                    [x, y, x + d, y - d * random.next()]
                }
            }
        })
        .collect()
}

/// The pixels the software rasterizer draws for the line, a row's bits at a time.
fn software_rows(line: [f32; 4]) -> Vec<u32> {
    let vertex = |x, y| RasterVertex {
        window: [x, y, 0.5, 1.0],
        ..Default::default()
    };
    let viewport = Viewport {
        width: SIZE,
        height: SIZE,
    };
    let frame = Close2glFrame {
        topology: Topology::Lines,
        vertices: vec![[line[0], line[1]], [line[2], line[3]]],
        raster: RasterGeometry {
            vertices: vec![vertex(line[0], line[1]), vertex(line[2], line[3])],
            primitives: vec![0, 1],
            ..Default::default()
        },
        viewport,
        ..Default::default()
    };
    let settings = Appearance::default();
    let drawn = close2gl_raster::textbook::draw(
        &frame,
        &Camera::default(),
        &settings,
        &Lighting::default(),
        None,
    );
    drawn
        .depth
        .chunks(SIZE as usize)
        .map(|row| {
            let covered = row.iter().enumerate().filter(|(_, d)| **d < 1.0);
            covered.fold(0, |bits, (x, _)| bits | 1 << x)
        })
        .collect()
}

/// What the shader answered: the rows' bits, and each line's exact rectangle.
struct Answers {
    rows: Vec<u32>,
    exact: Vec<[i32; 4]>,
}

fn shader_answers(lines: &[[f32; 4]]) -> Answers {
    let gpu = gpu();
    let device = &gpu.device;
    let source = format!(
        "{TEST_SHADER}\n{}",
        include_str!("../src/pixel_shapes.wgsl")
    );
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("exact lines"),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some("exact lines"),
        layout: None,
        module: &module,
        entry_point: Some("main"),
        compilation_options: Default::default(),
        cache: None,
    });
    let input = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("lines"),
        contents: bytemuck::cast_slice(lines),
        usage: wgpu::BufferUsages::STORAGE,
    });
    let storage = |bytes: usize| {
        device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: bytes as u64,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        })
    };
    let rows = storage(lines.len() * SIZE as usize * 4);
    let exact = storage(lines.len() * 32);
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[entry(0, &input), entry(1, &rows), entry(2, &exact)],
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_compute_pass(&Default::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind_group, &[]);
        pass.dispatch_workgroups(lines.len() as u32, 1, 1);
    }
    gpu.queue.submit([encoder.finish()]);
    Answers {
        rows: bytemuck::cast_slice(&read(&gpu, &rows)).to_vec(),
        exact: bytemuck::cast_slice(&read(&gpu, &exact)).to_vec(),
    }
}

fn entry(binding: u32, buffer: &wgpu::Buffer) -> wgpu::BindGroupEntry<'_> {
    wgpu::BindGroupEntry {
        binding,
        resource: buffer.as_entire_binding(),
    }
}

/// The contents of a storage buffer, copied to a mappable one and read back.
fn read(gpu: &close2gl_gpu::Gpu, buffer: &wgpu::Buffer) -> Vec<u8> {
    let staging = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: buffer.size(),
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    encoder.copy_buffer_to_buffer(buffer, 0, &staging, 0, buffer.size());
    gpu.queue.submit([encoder.finish()]);
    let slice = staging.slice(..);
    slice.map_async(wgpu::MapMode::Read, |result| result.expect("map"));
    gpu.device
        .poll(wgpu::PollType::wait_indefinitely())
        .expect("the GPU finishes");
    slice.get_mapped_range().expect("mapped").to_vec()
}

/// The rectangle's four sides (corners a − t, b − t, b + t, a + t, in 1/256 pixel).
fn sides(ends: [i32; 4], across: [i32; 4]) -> [([i64; 2], [i64; 2]); 4] {
    let [ax, ay, bx, by] = ends.map(i64::from);
    let [tx, ty, ..] = across.map(i64::from);
    let corners = [
        [ax - tx, ay - ty],
        [bx - tx, by - ty],
        [bx + tx, by + ty],
        [ax + tx, ay + ty],
    ];
    std::array::from_fn(|i| (corners[i], corners[(i + 1) % 4]))
}

/// How many of the viewport's pixel centres lie exactly on one of the rectangle's sides, and
/// the largest product of two differences its edge functions take at them.
fn centres_on_sides(ends: [i32; 4], across: [i32; 4]) -> (usize, i64) {
    let (mut on, mut largest) = (0, 0i64);
    for (p, q) in sides(ends, across) {
        for (x, y) in (0..SIZE as i64).flat_map(|y| (0..SIZE as i64).map(move |x| (x, y))) {
            let s = [x * 256, y * 256];
            let (m, n) = ((p[1] - q[1]) * (p[0] - s[0]), (p[0] - q[0]) * (p[1] - s[1]));
            largest = largest.max(m.abs()).max(n.abs());
            let between = |k: usize| p[k].min(q[k]) <= s[k] && s[k] <= p[k].max(q[k]);
            on += usize::from(m == n && between(0) && between(1));
        }
    }
    (on, largest)
}

#[test]
fn a_lines_kept_fragments_are_the_software_rasterizers_pixels() {
    let lines = lines(2000);
    let answers = shader_answers(&lines);
    let mut wrong = Vec::new();
    let (mut on_sides, mut largest, mut drawn) = (0, 0, 0);
    for (i, line) in lines.iter().enumerate() {
        let shader = &answers.rows[i * SIZE as usize..(i + 1) * SIZE as usize];
        let software = software_rows(*line);
        if shader != software {
            wrong.push((line, shader.to_vec(), software.clone()));
        }
        drawn += software
            .iter()
            .map(|r| r.count_ones() as usize)
            .sum::<usize>();
        let (on, product) = centres_on_sides(answers.exact[2 * i], answers.exact[2 * i + 1]);
        on_sides += on;
        largest = largest.max(product);
    }
    assert!(
        wrong.is_empty(),
        "{} of {} lines differ, the first: {:?}",
        wrong.len(),
        lines.len(),
        wrong.first()
    );
    // The cases the arithmetic can get wrong are met, and often.
    assert!(drawn > 20_000, "{drawn} pixels drawn");
    assert!(on_sides > 2_000, "{on_sides} centres on a side");
    assert!(largest > 1 << 50, "products up to {largest}");
}
