#!/usr/bin/env bash
# Does the renderer pay for the recorder hooks it does not use?
#
# Builds the tracer twice from the same source: as shipped (the renderer calls
# every hook on the no-op recorder), and with `--cfg raytree_no_hooks`, which
# removes every hook call from the source (the `record!` macro in
# src/trace/recorder.rs). Then compares, on the Whitted scene at 640×480:
#   - wall time: the divan benchmark `whitted_640x480` (median of 30 renders), and
#   - instructions executed, counted by callgrind on one single-threaded render
#     (exact and repeatable, unlike time on a shared machine), if valgrind is
#     installed.
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== wall time, hooks present (no-op recorder)"
cargo bench -p raytree-benches --bench render -- whitted_640x480 2>/dev/null | grep -A1 whitted
echo "== wall time, hooks compiled out"
RUSTFLAGS="--cfg raytree_no_hooks" CARGO_TARGET_DIR=target/no_hooks cargo bench -p raytree-benches --bench render -- whitted_640x480 2>/dev/null | grep -A1 whitted

if command -v valgrind >/dev/null; then
  cargo build --release --quiet
  RUSTFLAGS="--cfg raytree_no_hooks" CARGO_TARGET_DIR=target/no_hooks cargo build --release --quiet
  count() {
    valgrind --tool=callgrind --callgrind-out-file=/dev/null "$1" render --threads 1 --quiet -o "$(mktemp -d)/x.png" 2>&1 |
      sed -n 's/.*Collected : *\([0-9]*\).*/\1/p'
  }
  with=$(count target/release/raytree)
  without=$(count target/no_hooks/release/raytree)
  echo "== instructions for one render (callgrind, 1 thread)"
  echo "hooks present:      $with"
  echo "hooks compiled out: $without"
  awk -v a="$with" -v b="$without" 'BEGIN { printf "ratio: %.5f\n", a / b }'
else
  echo "(install valgrind for exact instruction counts)"
fi
