//! Embeds the page in the binary, so an installed `behavior serve` needs no network: our own
//! files from `ui/`, and three.js's modules from its npm package.
//!
//! three.js comes from `ui/node_modules` when `npm ci` was run there (the browser tests need it
//! anyway), else this script runs `npm ci --omit=dev` into the build's own directory, the way
//! cargo itself fetches crates. It writes `assets.rs`: a table of (URL path, MIME type, bytes).

use std::env;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Our own files, served at `/<name>`.
const OWN: &[(&str, &str)] = &[
    ("index.html", "text/html; charset=utf-8"),
    ("app.js", "text/javascript; charset=utf-8"),
    ("scene.js", "text/javascript; charset=utf-8"),
    ("controls.js", "text/javascript; charset=utf-8"),
    ("panel.js", "text/javascript; charset=utf-8"),
    ("xr.js", "text/javascript; charset=utf-8"),
    ("timeline.js", "text/javascript; charset=utf-8"),
    ("style.css", "text/css; charset=utf-8"),
];

/// three.js's files, from its package's root, served at `/three/<path>`.
const THREE: &[&str] = &[
    "build/three.module.js",
    "build/three.core.js",
    "examples/jsm/controls/OrbitControls.js",
    // The scene's glTF file, and what its loader imports.
    "examples/jsm/loaders/GLTFLoader.js",
    "examples/jsm/utils/BufferGeometryUtils.js",
    "examples/jsm/utils/SkeletonUtils.js",
];

fn main() {
    let ui = PathBuf::from(env::var("CARGO_MANIFEST_DIR").expect("cargo sets it")).join("ui");
    let out = PathBuf::from(env::var("OUT_DIR").expect("cargo sets it"));
    println!("cargo:rerun-if-changed=ui/package.json");
    println!("cargo:rerun-if-changed=ui/package-lock.json");
    let three = three_package(&ui, &out);
    let mut table = String::from("&[\n");
    for (name, mime) in OWN {
        println!("cargo:rerun-if-changed=ui/{name}");
        entry(&mut table, &format!("/{name}"), mime, &ui.join(name));
    }
    for file in THREE {
        let served = file
            .trim_start_matches("build/")
            .replace("examples/jsm/", "addons/");
        entry(
            &mut table,
            &format!("/three/{served}"),
            "text/javascript; charset=utf-8",
            &three.join(file),
        );
    }
    table.push(']');
    fs::write(out.join("assets.rs"), table).expect("OUT_DIR is writable");
}

fn entry(table: &mut String, path: &str, mime: &str, file: &Path) {
    assert!(file.is_file(), "the page needs {}", file.display());
    table.push_str(&format!(
        "    ({path:?}, {mime:?}, include_bytes!({:?}).as_slice()),\n",
        file.display().to_string()
    ));
}

/// The root of the `three` package: `ui/node_modules/three`, else installed by npm into
/// `OUT_DIR`.
fn three_package(ui: &Path, out: &Path) -> PathBuf {
    let local = ui.join("node_modules/three");
    if local.join("package.json").is_file() {
        println!("cargo:rerun-if-changed=ui/node_modules/three/package.json");
        return local;
    }
    let prefix = out.join("ui");
    let installed = prefix.join("node_modules/three");
    if installed.join("package.json").is_file() {
        return installed;
    }
    fs::create_dir_all(&prefix).expect("OUT_DIR is writable");
    for file in ["package.json", "package-lock.json"] {
        fs::copy(ui.join(file), prefix.join(file)).expect("ui/ has the npm manifest");
    }
    let status = Command::new("npm")
        .args([
            "ci",
            "--omit=dev",
            "--ignore-scripts",
            "--no-audit",
            "--no-fund",
        ])
        .current_dir(&prefix)
        .status();
    match status {
        Ok(s) if s.success() => installed,
        Ok(s) => panic!(
            "`npm ci` for the viewer's three.js failed ({s}); run it in {} by hand",
            ui.display()
        ),
        Err(e) => panic!(
            "the viewer embeds three.js from npm, and npm could not run ({e}): install Node.js \
             and npm, or build the `behavior` binary without its `web` feature"
        ),
    }
}
