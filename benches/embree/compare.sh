#!/usr/bin/env bash
# raytree's closest-hit loop against Embree's, on the same rays and the same mesh.
#
# Embree (through embreex, its Python binding from PyPI, installed into a
# virtual environment under target/ by this script) and raytree
# (benches/closest_hit.rs) each build their hierarchy over the Gaspra mesh's
# 32,040 triangles in world space, then cast, on one thread, the same two ray
# sets: exactly raytree's primary rays of scenes/gaspra.json at WxH (coherent),
# and N random rays from a sphere around the mesh into its box (incoherent).
# Only the casting is timed (the fastest of 3 passes within each run); runs
# alternate between the two, and the script prints the medians and the ratio
# raytree ÷ Embree (how many times slower raytree is; the target is ≤ 2).
# Embree's time is as measured, the Python binding's per-call cost included:
# the time of the same call on a scene no ray hits is mostly Embree's own
# per-call cost, not the binding's, so subtracting it would take away
# Embree's own work too (docs/performance.md).
# The hit counts and the sum of t over hits are compared first: both sides
# must find the same hits (up to a few rays on triangle edges: Embree tests
# in single precision, raytree in double).
#
# Usage: benches/embree/compare.sh [RUNS] [WxH] [N]   (defaults: 5 640x480 300000)
set -euo pipefail

runs=${1:-5}
size=${2:-640x480}
random=${3:-300000}
[[ $runs =~ ^[1-9][0-9]*$ && $size =~ ^[1-9][0-9]*x[1-9][0-9]*$ && $random =~ ^[1-9][0-9]*$ ]] ||
    { echo "usage: $0 [RUNS] [WxH] [N]" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
source "$here/../idle.sh"

source "$here/venv.sh"
embree_version=$("$venv/bin/pip" show embreex 2>/dev/null | sed -n 's/^Version: //p')

cargo build --release --quiet --manifest-path "$root/Cargo.toml" -p raytree-benches --example closest_hit
closest_hit="${CARGO_TARGET_DIR:-$root/target}/release/examples/closest_hit"

data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT
"$closest_hit" export "$data" --width "${size%x*}" --height "${size#*x}" --random "$random" 2>/dev/null

field() { sed -n "s/.*\\b$1=\\([^ ]*\\).*/\\1/p"; }

wait_for_idle
echo "raytree closest hit vs Embree (embreex $embree_version), Gaspra mesh, one thread, median of $runs alternating runs$busy"
printf '%-22s %10s %12s %10s\n' "rays" raytree "Embree" "ratio"
for set in primary random; do
    ours=$("$closest_hit" time "$data" --set "$set" --passes 1)
    theirs=$("$venv/bin/python" "$here/embree_rays.py" "$data" "$set" --check)
    if [[ $(field hits <<<"$ours") != $(field hits <<<"$theirs") ]]; then
        echo "note: $set rays: raytree finds $(field hits <<<"$ours") hits, Embree $(field hits <<<"$theirs")" \
            "(t sums $(field t_sum <<<"$ours") and $(field t_sum <<<"$theirs"))"
    fi
    r=() e=()
    for ((i = 0; i < runs; i++)); do
        line=$("$closest_hit" time "$data" --set "$set")
        r+=("$(field seconds <<<"$line")")
        line=$("$venv/bin/python" "$here/embree_rays.py" "$data" "$set")
        e+=("$(field seconds <<<"$line")")
    done
    count=$(field rays <<<"$line")
    t_r=$(printf '%s\n' "${r[@]}" | median)
    t_e=$(printf '%s\n' "${e[@]}" | median)
    printf '%-22s %8.1f ms %9.1f ms %9.2fx\n' "$set ($count)" \
        "$(awk -v t="$t_r" 'BEGIN { print 1e3 * t }')" "$(awk -v t="$t_e" 'BEGIN { print 1e3 * t }')" \
        "$(awk -v a="$t_r" -v b="$t_e" 'BEGIN { print a / b }')"
done
