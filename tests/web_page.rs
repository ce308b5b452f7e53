//! The web build in a real browser: `scripts/build-web` builds the site, a static server on
//! 127.0.0.1 serves it, and Debian's Chromium, headless, opens it (driven by
//! `tests/web/page.mjs` with playwright-core; WebGL2 runs on SwiftShader there). Each page is
//! opened with `?test=1`, so the app keeps its JSON status in `#status`: the first frame is
//! drawn, both views agree, a link's model and settings are applied and the link follows the
//! view; every mode with both of Close2GL's rasterizers agrees (the reference draws lines and
//! points face by face, WebGL2 having no polygon modes); a page in virtual time, which starts at
//! time zero, draws its first frame. Needs what `.ci/run` installs: the wasm32 target, wasm-bindgen-cli at the lock file's
//! version, Node.js with `npm ci` done in tests/web, and chromium.

use std::io::{BufRead, BufReader, Write};
use std::net::{TcpListener, TcpStream};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

use serde_json::Value;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The site, built once for all the tests, into a target directory of its own (the tests'
/// own cargo holds the workspace's).
fn site() -> &'static Path {
    static SITE: OnceLock<PathBuf> = OnceLock::new();
    SITE.get_or_init(|| {
        let out = root().join("target/web-test/site");
        let status = Command::new(root().join("scripts/build-web"))
            .arg(&out)
            .env("CARGO_TARGET_DIR", root().join("target/web-test/build"))
            .status()
            .expect("scripts/build-web runs");
        assert!(status.success(), "scripts/build-web failed: {status}");
        out
    })
}

/// Serves the site on 127.0.0.1 for as long as the test binary runs; returns its address.
fn server() -> &'static str {
    static ADDRESS: OnceLock<String> = OnceLock::new();
    ADDRESS.get_or_init(|| {
        let listener = TcpListener::bind("127.0.0.1:0").expect("a local port");
        let address = format!("http://{}", listener.local_addr().unwrap());
        let site = site().to_path_buf();
        std::thread::spawn(move || {
            for stream in listener.incoming().flatten() {
                let site = site.clone();
                std::thread::spawn(move || serve(stream, &site));
            }
        });
        address
    })
}

fn serve(mut stream: TcpStream, site: &Path) {
    let mut request = String::new();
    if BufReader::new(&stream).read_line(&mut request).is_err() {
        return;
    }
    let path = request.split_whitespace().nth(1).unwrap_or("/");
    let path = path.split(['?', '#']).next().unwrap_or("/");
    let relative = match path.trim_start_matches('/') {
        "" => "index.html",
        other => other,
    };
    let file = site.join(relative);
    let inside = !relative.split('/').any(|part| part == "..");
    let (status, kind, body) = match std::fs::read(&file) {
        Ok(body) if inside => ("200 OK", content_type(&file), body),
        _ => ("404 Not Found", "text/plain", b"not found".to_vec()),
    };
    let head = format!(
        "HTTP/1.1 {status}\r\nContent-Type: {kind}\r\nContent-Length: {}\r\nConnection: close\r\n\r\n",
        body.len()
    );
    let _ = stream.write_all(head.as_bytes());
    let _ = stream.write_all(&body);
}

fn content_type(file: &Path) -> &'static str {
    match file.extension().and_then(|e| e.to_str()) {
        Some("html") => "text/html; charset=utf-8",
        Some("js") => "text/javascript",
        Some("wasm") => "application/wasm",
        _ => "application/octet-stream",
    }
}

/// Opens `page` (a path and query on the site, with its fragment) and returns what page.mjs
/// reports: the app's status, the page's fragment afterwards and any errors.
fn open(page: &str, screenshot: &str) -> Value {
    open_and_pick(page, screenshot, None)
}

/// [`open`], then `pick` chosen with the page's file input.
fn open_and_pick(page: &str, screenshot: &str, pick: Option<&Path>) -> Value {
    let url = format!("{}/{page}", server());
    let shot = root().join("target/web-test").join(screenshot);
    let mut node = Command::new("node");
    node.arg(root().join("tests/web/page.mjs"))
        .arg(&url)
        .arg(&shot);
    if let Some(pick) = pick {
        node.arg("90000").arg(pick);
    }
    let output = node
        .output()
        .expect("node runs (apt-get install nodejs; npm ci in tests/web)");
    let stdout = String::from_utf8_lossy(&output.stdout);
    let report: Value = stdout
        .lines()
        .last()
        .and_then(|line| serde_json::from_str(line).ok())
        .unwrap_or_else(|| {
            panic!(
                "page.mjs printed no report for {url}: {stdout}\n{}",
                String::from_utf8_lossy(&output.stderr)
            )
        });
    let errors = report["errors"].as_array().cloned().unwrap_or_default();
    assert!(
        errors.is_empty(),
        "{url}: the page reported errors: {errors:?}"
    );
    assert!(shot.is_file(), "{url}: no screenshot");
    report
}

fn number(status: &Value, key: &str) -> f64 {
    status[key]
        .as_f64()
        .unwrap_or_else(|| panic!("status has no number {key}: {status}"))
}

#[test]
fn the_first_frame_is_drawn_and_both_views_agree() {
    let report = open("?test=1", "default.png");
    let status = &report["status"];
    assert!(number(status, "frames") >= 3.0, "{status}");
    let first = number(status, "first_frame_ms");
    assert!(first > 0.0, "{status}");
    assert!(
        ["webgl2", "webgpu"].contains(&status["backend"].as_str().unwrap_or("")),
        "{status}"
    );
    assert!(
        !status["adapter"].as_str().unwrap_or("").is_empty(),
        "{status}"
    );
    assert_eq!(status["model"], "knot.obj", "{status}");
    assert_eq!(status["triangles"], 8192, "{status}");
    assert_eq!(status["panel"], true, "{status}");
    let agreement = number(status, "coverage_agreement");
    assert!(
        agreement >= 0.999,
        "the views disagree: {agreement} ({status})"
    );
    eprintln!("first frame after {first:.0} ms: {status}");
    let wasm = site().join("close2gl_web_bg.wasm");
    let gzipped = gzipped_bytes(&wasm);
    eprintln!("the module: {gzipped} bytes gzipped");
    // 4 MB, not MiB: the stricter reading of the size budget.
    assert!(
        gzipped < 4_000_000,
        "the module is {gzipped} bytes gzipped, over 4 MB"
    );
}

/// The size of `file` compressed with `gzip -9`, as a server would send it.
fn gzipped_bytes(file: &Path) -> usize {
    let output = Command::new("gzip")
        .arg("-9c")
        .arg(file)
        .output()
        .expect("gzip runs");
    assert!(
        output.status.success(),
        "gzip {}: {output:?}",
        file.display()
    );
    output.stdout.len()
}

/// Points, wireframe and solid, each with both Close2GL rasterizers, agree with the reference
/// in the page as on the desktop: WebGL2 has no polygon modes, so the reference draws each kept
/// face's edges or corners itself, and both GPU views draw lines and points as the software
/// rasterizer's one-pixel rectangles and squares (SwiftShader's own line and point rules differ),
/// a line's fragments kept by the software's own edge tests (SwiftShader's 1/16-pixel snapping
/// of the rectangles' corners would change about 2 % of them).
#[test]
fn every_mode_agrees_with_both_rasterizers() {
    let mut failures = String::new();
    for (mode, needed) in [("points", 0.99), ("wireframe", 0.99), ("solid", 0.999)] {
        for raster in ["software", "gpu"] {
            let link = format!("render.mode=%22{mode}%22&render.close2gl_raster=%22{raster}%22");
            let report = open(&format!("?test=1#{link}"), &format!("{mode}-{raster}.png"));
            let status = &report["status"];
            // The status's settings are those that differ from the built-in defaults.
            let setting = |key: &str, default: &'static str| {
                status["settings"][key]
                    .as_str()
                    .unwrap_or(default)
                    .to_string()
            };
            assert_eq!(setting("render.mode", "solid"), mode, "{status}");
            assert_eq!(setting("render.close2gl_raster", "gpu"), raster, "{status}");
            let agreement = number(status, "coverage_agreement");
            eprintln!(
                "{mode}, {raster}: coverage agreement {agreement} ({})",
                status["backend"]
            );
            if agreement < needed {
                failures += &format!("{mode}, {raster}: {agreement} < {needed} ({status})\n");
            }
        }
    }
    assert!(failures.is_empty(), "the views disagree:\n{failures}");
}

/// A page in virtual time (as crawlers and test runners open it) starts its clock at zero and
/// runs it only as fast as the page's work: it must draw its first frame and report it, not
/// stop (the link's throttle once subtracted 250 ms from the clock's first reading).
#[test]
fn a_page_in_virtual_time_draws_its_first_frame() {
    let url = format!("{}/?test=1", server());
    let flags = std::fs::read_to_string(root().join("tests/web/chromium-args.json"))
        .expect("tests/web/chromium-args.json");
    let flags: Vec<String> = serde_json::from_str(&flags).expect("a JSON list of flags");
    // A profile of its own: with the default one, a Chromium already running hands the page to
    // that one and exits at once, with the page not yet started.
    let profile_dir = close2gl_testkit::TempDir::new("virtual_time_profile");
    let profile = format!("--user-data-dir={}", profile_dir.display());
    let output = Command::new(std::env::var("CHROMIUM").unwrap_or("/usr/bin/chromium".into()))
        .args(flags)
        .args([
            "--headless",
            "--virtual-time-budget=20000",
            "--dump-dom",
            &profile,
            &url,
        ])
        .output()
        .expect("chromium runs (apt-get install chromium)");
    let dom = String::from_utf8_lossy(&output.stdout);
    let text = |id: &str| element_text(&dom, id).unwrap_or_else(|| panic!("no #{id} in {dom}"));
    let error = text("error");
    assert!(error.is_empty(), "the page stopped: {error}");
    let status: Value = serde_json::from_str(&text("status"))
        .unwrap_or_else(|e| panic!("no status in virtual time ({e}): {dom}"));
    assert!(number(&status, "frames") >= 1.0, "{status}");
    eprintln!("in virtual time: {status}");
}

/// The text of the element with `id` in a serialized DOM, its entities decoded.
fn element_text(dom: &str, id: &str) -> Option<String> {
    let start = dom.find(&format!("id=\"{id}\""))?;
    let open_end = start + dom[start..].find('>')? + 1;
    let close = open_end + dom[open_end..].find('<')?;
    let raw = &dom[open_end..close];
    Some(
        raw.replace("&lt;", "<")
            .replace("&gt;", ">")
            .replace("&quot;", "\"")
            .replace("&amp;", "&"),
    )
}

#[test]
fn a_links_model_and_settings_are_applied_and_the_link_follows_the_view() {
    let link =
        "model=cube.in&camera.hfov=45&render.clipping=%22simple%22&render.front_face=%22cw%22";
    let report = open(&format!("?test=1#{link}"), "link.png");
    let status = &report["status"];
    assert_eq!(status["model"], "cube.in", "{status}");
    assert_eq!(status["triangles"], 12, "{status}");
    let settings = &status["settings"];
    assert_eq!(settings["camera.hfov"], 45.0, "{status}");
    assert_eq!(settings["render.clipping"], "simple", "{status}");
    assert_eq!(settings["render.front_face"], "cw", "{status}");
    assert!(number(status, "coverage_agreement") >= 0.999, "{status}");
    // The page rewrote its link from the view: the same settings, and the pose pinned.
    let hash = report["hash"].as_str().unwrap_or("");
    for item in [
        "#model=cube.in&",
        "camera.hfov=45",
        "render.clipping=simple",
    ] {
        assert!(hash.contains(item), "the link lacks {item}: {hash}");
    }
    assert!(hash.contains("camera.position="), "{hash}");
    // The rewritten link opens the same view.
    let again = open(&format!("?test=1{hash}"), "link-again.png");
    assert_eq!(again["status"]["settings"], *settings, "{again}");
}

#[test]
fn a_primitive_embedded_without_the_panel() {
    let report = open("?test=1&embed=1#model=torus", "embed.png");
    let status = &report["status"];
    assert_eq!(status["model"], "torus", "{status}");
    assert_eq!(status["panel"], false, "{status}");
    assert!(number(status, "coverage_agreement") >= 0.999, "{status}");
}

#[test]
fn a_broken_link_shows_the_default_view_and_says_why() {
    // Broken links are the user's input: the page still opens, on the default model.
    let report = open(
        "?test=1#model=no_such_model.in&camera.hfov=banana",
        "broken.png",
    );
    let status = &report["status"];
    assert_eq!(status["model"], "knot.obj", "{status}");
}

#[test]
fn a_picked_file_becomes_the_model() {
    let picked = root().join("target/web-test/picked_cube.in");
    std::fs::create_dir_all(picked.parent().unwrap()).unwrap();
    std::fs::copy(root().join("assets/cube.in"), &picked).unwrap();
    let report = open_and_pick("?test=1", "picked.png", Some(&picked));
    let status = &report["status"];
    assert_eq!(status["model"], "picked_cube.in", "{status}");
    assert_eq!(status["triangles"], 12, "{status}");
}

#[test]
fn a_picked_trace_is_shown_with_checks_verdict() {
    // The assignment's program of examples/trace, built here, writes a trace of the cube.
    let dir = root().join("target/web-test/trace");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::copy(root().join("assets/cube.in"), dir.join("cube.in")).unwrap();
    let scene = "close2gl-scene 1\nmodel cube.in\nwindow 640 480\ncamera framed\nrotate v 20\n\
                 move n -1\nculling ccw\nclipping full\n";
    std::fs::write(dir.join("view.scene"), scene).unwrap();
    let program = close2gl_testkit::student::compile_pipeline(&dir, "pipeline", &[]);
    let trace = dir.join("cube_frame.trace");
    let status = Command::new(&program)
        .arg(dir.join("view.scene"))
        .arg(&trace)
        .status()
        .expect("the student program runs");
    assert!(status.success(), "{status}");
    let report = open_and_pick("?test=1#model=cube.in", "trace.png", Some(&trace));
    let shown = &report["status"]["trace"];
    assert_eq!(shown["file"], "cube_frame.trace", "{report}");
    assert_eq!(shown["agrees"], true, "{report}");
}
