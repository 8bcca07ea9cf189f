//! Links libgcc's unwinder into mbtool on Linux with glibc, as `gcc -static-libgcc` does.
//!
//! Rust's standard library takes its unwinder from the shared `libgcc_s`, and loading it
//! costs every process a library to find, map and bind, and a constructor that probes the
//! CPU (`__cpu_indicator_init`). A one-shot command is mostly start-up, and that load was
//! about a fifth of its CPU time (bench/oneshot.py). Named here, `libgcc_eh.a` comes
//! before `libgcc_s` on the link line, so the unwinder's symbols are found in it and the
//! linker (`--as-needed`) leaves `libgcc_s` out. A static build links `libgcc_eh` itself.

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let var = |name: &str| std::env::var(name).unwrap_or_default();
    let static_crt = var("CARGO_CFG_TARGET_FEATURE")
        .split(',')
        .any(|feature| feature == "crt-static");
    if var("CARGO_CFG_TARGET_OS") == "linux" && var("CARGO_CFG_TARGET_ENV") == "gnu" && !static_crt
    {
        // Not bundled into the library's rlib: named once, at the final link.
        println!("cargo:rustc-link-lib=static:-bundle=gcc_eh");
    }
}
