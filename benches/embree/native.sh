#!/usr/bin/env bash
# raytree's closest hit against native Embree 4 (issue 30's measurements), on
# one thread, the same rays on both sides.
#
# Embree's side is benches/embree_native.rs: Embree 4's C API called directly
# (the shared library inside the embreex wheel, which this script installs into
# a virtual environment under target/ as compare.sh does), device "threads=1",
# scenes flagged RTC_SCENE_FLAG_ROBUST, default build quality. raytree's side is
# benches/closest_hit.rs, through raytree's public API as the renderer runs it.
#
# Rows:
# - the Gaspra mesh's 32,040 triangles in world space, with raytree's primary
#   rays of scenes/gaspra.json at WxH (coherent), N random rays from a sphere
#   around the mesh into its box, and N random rays starting inside its box
#   (random directions). raytree: the mesh's own hierarchy and watertight test;
#   Embree: a triangle geometry.
# - the spheres of `raytree generate spheres 1000` and `... 1000000` (seed 1,
#   floor left out), with that scene's primary rays at 320x240 (as
#   benches/scenes.rs). raytree: Tracer::closest_hit over a scene of those
#   spheres under its hierarchy; Embree: one user geometry whose callbacks are
#   raytree's sphere test in f64.
#
# First both sides cast each set once and must find the same hits (counts, and
# the sum of t over hits): Embree's rays are single precision, so a few rays
# on triangle edges or sphere rims may differ; more than 1 in 10,000 fails the
# script. Then runs alternate, raytree then Embree, each run a process of its
# own timing the fastest of 3 passes; the table gives the medians, the ratio
# raytree ÷ Embree (issue 30's targets: ≤ 1.5 on the mesh, ≤ 1.3 at a million
# spheres) and the time per ray.
#
# Usage: benches/embree/native.sh [RUNS] [WxH] [N]   (defaults: 5 640x480 300000)
# IDLE_WAIT=0 skips waiting for an idle machine (figures then marked busy);
# SPHERES="1000" times fewer sphere counts (default "1000 1000000");
# BEFORE=path/to/an/older/closest_hit (built from an older commit with this
# commit's benches/) times that build too, in the same alternation, for a
# before/after in one session (docs/performance.md). A quick
# check that everything runs: IDLE_WAIT=0 SPHERES=1000 native.sh 1 64x48 2000
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
lib=$(ls "$venv"/lib/python3*/site-packages/embreex.libs/libembree4-*.so.4 2>/dev/null | head -n 1)
[[ -n $lib ]] || { echo "no libembree4 in $venv's embreex" >&2; exit 1; }

cargo build --release --quiet --manifest-path "$root/Cargo.toml" -p raytree-benches \
    --example closest_hit --example embree_native
bin="${CARGO_TARGET_DIR:-$root/target}/release/examples"
closest_hit="$bin/closest_hit"
embree="$bin/embree_native"
field() { sed -n "s/.*\\b$1=\\([^ ]*\\).*/\\1/p"; }
version=$("$embree" "$lib" check | field embree)

data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT
"$closest_hit" export "$data" --width "${size%x*}" --height "${size#*x}" --random "$random" 2>/dev/null
read -r -a sphere_counts <<<"${SPHERES:-1000 1000000}"
for n in "${sphere_counts[@]}"; do
    "$closest_hit" spheres export "$data" "$n" 2>/dev/null
done

# The command line of each side for a row: "mesh SET" or "spheres N".
ours() {
    case $1 in
    mesh) "$closest_hit" time "$data" --set "$2" "${@:3}" ;;
    spheres) "$closest_hit" spheres time "$data" "$2" "${@:3}" ;;
    esac
}
theirs() { "$embree" "$lib" "$1" "$data" "$2" "${@:3}"; }
before() {
    case $1 in
    mesh) "$BEFORE" time "$data" --set "$2" "${@:3}" ;;
    spheres) "$BEFORE" spheres time "$data" "$2" "${@:3}" ;;
    esac
}

rows=("mesh primary" "mesh random" "mesh inside")
for n in "${sphere_counts[@]}"; do rows+=("spheres $n"); done

echo "checking that both sides find the same hits"
for row in "${rows[@]}"; do
    read -r kind set <<<"$row"
    a=$(ours "$kind" "$set" --passes 1)
    b=$(theirs "$kind" "$set" --passes 1)
    verdict=$(awk -v rays="$(field rays <<<"$a")" \
        -v ha="$(field hits <<<"$a")" -v hb="$(field hits <<<"$b")" \
        -v ta="$(field t_sum <<<"$a")" -v tb="$(field t_sum <<<"$b")" 'BEGIN {
            dh = ha - hb; if (dh < 0) dh = -dh
            dt = ta - tb; if (dt < 0) dt = -dt
            rel = (ta == 0 && tb == 0) ? 0 : dt / (ta > tb ? ta : tb)
            printf "%d hits against %d, sums of t %.6f and %.6f (relative difference %.1e)", ha, hb, ta, tb, rel
            if (dh > rays / 10000 || rel > 1e-4) { print " MISMATCH"; exit 1 }
        }') || { echo "  $kind $set: raytree and Embree: $verdict" >&2; exit 1; }
    echo "  $kind $set: raytree and Embree: $verdict"
done

wait_for_idle
echo "raytree closest hit vs native Embree $version (robust, threads=1), one thread," \
    "median of $runs alternating runs (each the fastest of 3 passes)$busy"
printf '%-18s %9s %12s %12s %8s %14s %14s' set rays "raytree ms" "Embree ms" ratio "raytree ns/ray" "Embree ns/ray"
[[ -n ${BEFORE:-} ]] && printf ' %12s %8s' "before ms" "ratio"
echo
for row in "${rows[@]}"; do
    read -r kind set <<<"$row"
    r=() e=() b=()
    for ((i = 0; i < runs; i++)); do
        if [[ -n ${BEFORE:-} ]]; then
            line=$(before "$kind" "$set")
            b+=("$(field seconds <<<"$line")")
        fi
        line=$(ours "$kind" "$set")
        r+=("$(field seconds <<<"$line")")
        line=$(theirs "$kind" "$set")
        e+=("$(field seconds <<<"$line")")
    done
    count=$(field rays <<<"$line")
    t_r=$(printf '%s\n' "${r[@]}" | median)
    t_e=$(printf '%s\n' "${e[@]}" | median)
    label=$([[ $kind == mesh ]] && echo "gaspra $set" || echo "spheres $set")
    t_b=""
    [[ -z ${BEFORE:-} ]] || t_b=$(printf '%s\n' "${b[@]}" | median)
    awk -v label="$label" -v n="$count" -v a="$t_r" -v b="$t_e" -v before="$t_b" 'BEGIN {
        printf "%-18s %9d %12.2f %12.2f %7.2fx %14.0f %14.0f", label, n, 1e3 * a, 1e3 * b, a / b, 1e9 * a / n, 1e9 * b / n
        if (before != "") printf " %12.2f %7.2fx", 1e3 * before, before / b
        printf "\n"
    }'
done
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
