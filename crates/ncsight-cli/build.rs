//! Builds the page's engine (crates/ncsight-wasm for wasm32-unknown-unknown, without debug
//! information) so `ncsight app` and `ncsight report` can write it into their page. It is built
//! in its own target directory (`target/engine`), so the outer build's lock is not in the way.
//!
//! The Rust target is added with rustup when it is missing (so a fresh checkout's `cargo build`
//! needs nothing more); where that cannot be done the command line is still built, and `app` and
//! `report` say what is missing instead of writing a page.

use std::path::PathBuf;
use std::process::Command;

fn main() {
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").unwrap());
    let root = manifest.join("../..");
    for dir in [
        "crates/ncsight/src",
        "crates/ncsight-io/src",
        "crates/ncsight-wasm/src",
        "crates/ncsight-wasm/Cargo.toml",
        "crates/ncsight/Cargo.toml",
        "crates/ncsight-io/Cargo.toml",
        "Cargo.toml",
        "Cargo.lock",
    ] {
        println!("cargo:rerun-if-changed={}", root.join(dir).display());
    }
    println!("cargo:rerun-if-env-changed=NCSIGHT_ENGINE_WASM");
    let out = PathBuf::from(std::env::var("OUT_DIR").unwrap()).join("engine.wasm");
    // A prebuilt engine can be given (a packager's build); otherwise it is built here.
    let built = match std::env::var_os("NCSIGHT_ENGINE_WASM") {
        Some(path) => {
            println!("cargo:rerun-if-changed={}", PathBuf::from(&path).display());
            std::fs::copy(&path, &out).map(|_| ()).map_err(|e| format!("NCSIGHT_ENGINE_WASM={}: {e}", PathBuf::from(&path).display()))
        }
        None => build(&root, &out),
    };
    if let Err(why) = built {
        println!("cargo:warning=ncsight's page engine was not built ({why}); `ncsight app` and `ncsight report` will say so");
        std::fs::write(&out, b"").unwrap();
        // Try again on the next build (the target may have been added since).
        println!("cargo:rerun-if-changed={}", root.join("target/engine/.try-again").display());
    }
}

/// Whether the toolchain building us has the wasm32-unknown-unknown standard library; if not,
/// rustup is asked for it.
fn ensure_target() {
    let rustc = std::env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
    let sysroot = Command::new(rustc).args(["--print", "sysroot"]).output().ok().map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string());
    let present = sysroot.map(|s| PathBuf::from(s).join("lib/rustlib/wasm32-unknown-unknown").is_dir()).unwrap_or(false);
    if !present {
        println!("cargo:warning=adding the Rust target wasm32-unknown-unknown (rustup target add) for the page's engine");
        let _ = Command::new("rustup").args(["target", "add", "wasm32-unknown-unknown"]).status();
    }
}

fn build(root: &std::path::Path, out: &std::path::Path) -> Result<(), String> {
    ensure_target();
    // A relative CARGO_TARGET_DIR is the workspace root's (where cargo was run from, normally).
    let target_dir = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .map(|d| if d.is_absolute() { d } else { root.join(d) })
        .unwrap_or_else(|| root.join("target"))
        .join("engine");
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut cmd = Command::new(cargo);
    cmd.current_dir(root)
        .args(["build", "--release", "--quiet", "-p", "ncsight-wasm", "--target", "wasm32-unknown-unknown", "--target-dir"])
        .arg(&target_dir)
        .env("CARGO_PROFILE_RELEASE_DEBUG", "0")
        .env("CARGO_PROFILE_RELEASE_STRIP", "true")
        // The page runs a million-line programme in the engine: whole-programme optimisation.
        .env("CARGO_PROFILE_RELEASE_LTO", "fat")
        .env("CARGO_PROFILE_RELEASE_CODEGEN_UNITS", "1");
    // What the outer build set for its own target must not reach this one (a fuzzing build's
    // sanitizer flags, clippy's wrapper, the host's target).
    for var in [
        "RUSTFLAGS",
        "CARGO_ENCODED_RUSTFLAGS",
        "RUSTC_WRAPPER",
        "RUSTC_WORKSPACE_WRAPPER",
        "CARGO_BUILD_TARGET",
        "CARGO_TARGET_DIR",
        "CARGO_BUILD_RUSTFLAGS",
        "CARGO_BUILD_RUSTC_WRAPPER",
        "CARGO_BUILD_RUSTC_WORKSPACE_WRAPPER",
    ] {
        cmd.env_remove(var);
    }
    let status = cmd.status().map_err(|e| format!("cannot run cargo: {e}"))?;
    if !status.success() {
        return Err(
            "cargo build -p ncsight-wasm --target wasm32-unknown-unknown failed; is the target installed (rustup target add wasm32-unknown-unknown)?".into()
        );
    }
    let wasm = target_dir.join("wasm32-unknown-unknown/release/ncsight_wasm.wasm");
    std::fs::copy(&wasm, out).map(|_| ()).map_err(|e| format!("{}: {e}", wasm.display()))
}
