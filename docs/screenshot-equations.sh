#!/bin/sh
# Screenshots the rustdoc page of a type that derives `Dynamics` (1000x1300, the top of the
# page down to the Coriolis matrix), to check by eye that its
# equations read right in a browser's monospace font (docs/equations-in-rustdoc.md). Needs
# headless Chromium; not run in CI.
#
#   docs/screenshot-equations.sh [OUT.png]     (default target/screenshot-equations/arm.png)
#
# The user's crate is a scratch crate outside the workspace (its own `[workspace]`), built
# offline into the workspace's `target/` with the workspace's lock file, so it depends on
# this checkout of `dynamics-runtime` exactly as a user's crate does.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
dir=$root/target/screenshot-equations
out=${1:-$dir/arm.png}
mkdir -p "$dir/src"
cp "$root/Cargo.lock" "$dir/Cargo.lock"
cat >"$dir/Cargo.toml" <<TOML
[package]
name = "screenshot-equations"
version = "0.0.0"
edition = "2021"
publish = false

[dependencies]
dynamics-runtime = { path = "$root/dynamics-runtime" }

[workspace]
TOML
cat >"$dir/src/lib.rs" <<'RUST'
//! A user's crate: one robot, derived.
use dynamics_runtime::Dynamics;

/// Niku's Example 6.4: a planar two-link arm of uniform rods in a vertical plane.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, -g, 0],
    dh = [[q, 0, l1, 0], [q, 0, l2, 0]],
    link(mass = m1, com = [-l1 / 2, 0, 0], inertia = [0, m1 * l1^2 / 12, m1 * l1^2 / 12, 0, 0, 0]),
    link(mass = m2, com = [-l2 / 2, 0, 0], inertia = [0, m2 * l2^2 / 12, m2 * l2^2 / 12, 0, 0, 0]),
)]
#[allow(missing_docs)]
pub struct Arm {
    pub l1: f64,
    pub l2: f64,
    pub m1: f64,
    pub m2: f64,
    pub g: f64,
}
RUST
# Warnings are errors: the user's docs, and the runtime's as a dependency, build clean.
(cd "$dir" && CARGO_TARGET_DIR=$root/target RUSTDOCFLAGS=-Dwarnings \
    cargo doc --offline --quiet -p screenshot-equations -p dynamics-runtime)
page=$root/target/doc/screenshot_equations/struct.Arm.html
chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1000,1300 \
    --screenshot="$out" "file://$page" 2>/dev/null
echo "$out ($page)"
