#!/usr/bin/env bash
# The whole test suite, as CI runs it: formatting, lints, every test, and the generated
# completions and man pages checked against the clap definition.
set -euo pipefail
cd "$(dirname "$0")/.."

cargo fmt --all -- --check
cargo clippy --all-targets --quiet -- -D warnings
cargo test --all-targets
