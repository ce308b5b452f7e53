//! The student programs of `examples/trace/` (`pipeline.c`: the assignment's pipeline writing a
//! close2gl trace) and `examples/raster/` (`raster.c`: the rasterizer assignment writing a raster
//! trace), compiled with the system's C compiler as a test needs them: correct, or with
//! catalogue mistakes and variants switched on; and the corpus's C and C++ programs
//! (`examples/corpus/`), compiled the same way.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The repository's root.
pub fn repository() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// A bundled model's path (`cube.in`, `knot.obj`, ...).
pub fn asset(name: &str) -> PathBuf {
    repository().join("assets").join(name)
}

/// The `-D` flag that switches on catalogue mistake `id` (`fov_not_halved` →
/// `-DMISTAKE_FOV_NOT_HALVED`).
pub fn mistake_flag(id: &str) -> String {
    format!("-DMISTAKE_{}", id.to_ascii_uppercase())
}

/// Compiles `pipeline.c` with `flags` into `dir/name`; panics with the compiler's output when it
/// fails (CI installs a C compiler: a test without one is a broken machine, not a skip).
pub fn compile_pipeline(dir: &Path, name: &str, flags: &[&str]) -> PathBuf {
    let source = repository().join("examples/trace/pipeline.c");
    compile_c(&source, &dir.join(name), flags)
}

/// Compiles `examples/raster/raster.c` (the rasterizer assignment's reference) with `flags`
/// into `dir/name`, as [`compile_pipeline`] does.
pub fn compile_raster(dir: &Path, name: &str, flags: &[&str]) -> PathBuf {
    let source = repository().join("examples/raster/raster.c");
    compile_c(&source, &dir.join(name), flags)
}

/// `raster.c` built with `flags` as `dir/name`, run on `examples/raster/`'s `scene`: the raster
/// trace it wrote, `dir/name.raster` (its buffers beside it).
pub fn raster_trace(dir: &Path, name: &str, flags: &[&str], scene: &str) -> PathBuf {
    let program = compile_raster(dir, name, flags);
    let trace = dir.join(format!("{name}.raster"));
    let examples = repository().join("examples/raster");
    let ran = Command::new(&program)
        .arg(examples.join(scene))
        .arg(&trace)
        .current_dir(&examples)
        .status()
        .expect("run raster");
    assert!(ran.success(), "{} {scene} failed", program.display());
    trace
}

/// Compiles the C99 file `source` with `flags` into the program `out` (warnings are errors),
/// as [`compile_pipeline`] does: for the programs a test writes itself (a hostile one, say).
pub fn compile_c(source: &Path, out: &Path, flags: &[&str]) -> PathBuf {
    compile(
        "cc",
        &["-std=c99", "-O2", "-Wall", "-Wextra", "-Werror"],
        source,
        out,
        flags,
    )
}

/// Compiles the C++17 file `source` with `flags` into the program `out` (warnings are errors),
/// with the system's C++ compiler (`c++`; CI installs g++).
pub fn compile_cpp(source: &Path, out: &Path, flags: &[&str]) -> PathBuf {
    compile(
        "c++",
        &["-std=c++17", "-O2", "-Wall", "-Wextra", "-Werror"],
        source,
        out,
        flags,
    )
}

fn compile(
    compiler: &str,
    standard: &[&str],
    source: &Path,
    out: &Path,
    flags: &[&str],
) -> PathBuf {
    let compiled = Command::new(compiler)
        .args(standard)
        .args(flags)
        .arg("-o")
        .arg(out)
        .arg(source)
        .arg("-lm")
        .output()
        .unwrap_or_else(|e| panic!("a compiler ({compiler}) on PATH: {e}"));
    assert!(
        compiled.status.success(),
        "{compiler} {flags:?} {} failed:\n{}",
        source.display(),
        String::from_utf8_lossy(&compiled.stderr)
    );
    out.to_path_buf()
}

/// The programs of `examples/corpus` (every .c, .cpp and .py file but the shared loader), in
/// name order: `check`'s corpus test and `grade`'s both run them.
pub fn corpus_programs() -> Vec<PathBuf> {
    let corpus = repository().join("examples/corpus");
    let mut found: Vec<PathBuf> = std::fs::read_dir(&corpus)
        .expect("examples/corpus")
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| {
            matches!(
                p.extension().and_then(|e| e.to_str()),
                Some("c" | "cpp" | "py")
            )
        })
        .filter(|p| p.file_stem().is_some_and(|s| s != "model"))
        .collect();
    found.sort();
    found
}
