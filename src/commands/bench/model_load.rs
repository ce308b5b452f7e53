//! `close2gl bench --load FILE`: a model file read into a mesh, start to finish, as the viewer
//! loads it (the extension picks the reader), timed over several loads.

use std::hint::black_box;
use std::path::Path;

use close2gl_core::{ModelSource, PrimitiveParams};
use serde_json::{Value, json};

use super::{BenchArgs, median_ms};
use crate::commands::CliError;

/// The median time to load `path`, and what it comes to in megabytes (10^6 bytes) a second.
pub fn load(args: &BenchArgs, path: &Path, pool: &rayon::ThreadPool) -> Result<Value, CliError> {
    let source = ModelSource::File(path.to_path_buf());
    let params = PrimitiveParams::default();
    let bytes = std::fs::metadata(path)
        .map_err(|e| CliError::Input(format!("{}: cannot read: {e}", path.display())))?
        .len();
    // A file that does not load is the user's error, not a time. Only one mesh is held at a
    // time, so that the peak memory of a run is one load's.
    let mesh = pool
        .install(|| close2gl_model::load(&source, &params))
        .map_err(CliError::Input)?
        .mesh;
    let (triangles, vertices) = (mesh.triangles.len(), mesh.positions.len());
    drop(mesh);
    let median_ms = pool.install(|| {
        median_ms(args.frames, || {
            black_box(close2gl_model::load(&source, &params)).ok();
        })
    });
    Ok(json!({
        "load": {
            "file": path.display().to_string(),
            "bytes": bytes,
            "triangles": triangles,
            "vertices": vertices,
            "frames": args.frames,
            "threads": pool.current_num_threads(),
            "median_ms": median_ms,
            "mb_per_s": bytes as f64 / 1e6 / (median_ms / 1e3),
        }
    }))
}
