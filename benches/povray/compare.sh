#!/usr/bin/env bash
# raytree side by side with POV-Ray 3.7 on the same scenes.
#
# Renders scenes/whitted.json and scenes/spheres.json with raytree and their
# hand-written POV-Ray twins (whitted.pov, spheres.pov beside this script) at
# 640×480 and 1280×960, 1 sample per pixel (antialiasing off), max depth 8, on
# all cores, alternating the two renderers run after run so a busy machine slows
# both alike. Prints each side's median wall time (the whole command: start-up,
# parsing and rendering), the ratio, and how far the images differ in 8-bit.
#
# Usage: benches/povray/compare.sh [RUNS]     (RUNS defaults to 5)
# Installs POV-Ray from the system's package manager (apt-get) if it is missing.
set -euo pipefail

runs=${1:-5}
[[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "usage: $0 [RUNS]" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
cores=$(nproc)

if ! command -v povray >/dev/null; then
    echo "POV-Ray is missing: installing it with apt-get" >&2
    sudo=""
    [[ $(id -u) -eq 0 ]] || sudo=sudo
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq povray >/dev/null
fi
povray_version=$(povray --version 2>&1 | grep -m1 -o 'POV-Ray [0-9.]*[^ ]*' || true)

cargo build --release --quiet --manifest-path "$root/Cargo.toml"
raytree="$root/target/release/raytree"

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# Wall time of one command in seconds.
wall() {
    local start end
    start=$(date +%s.%N)
    "$@" >/dev/null 2>"$out/stderr" || { cat "$out/stderr" >&2; exit 1; }
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" 'BEGIN { printf "%.6f\n", b - a }'
}

median() {
    sort -g | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

echo "raytree $("$raytree" --version | cut -d' ' -f2) vs $povray_version, $cores cores, median of $runs alternating runs"
printf '%-8s %-9s %12s %12s %8s   %s\n' scene size raytree POV-Ray ratio "image difference (8-bit)"
for scene in whitted spheres; do
    for size in 640x480 1280x960; do
        w=${size%x*}
        h=${size#*x}
        ours=()
        theirs=()
        for ((i = 0; i < runs; i++)); do
            ours+=("$(wall "$raytree" render "$root/scenes/$scene.json" --width "$w" --height "$h" \
                --spp 1 --max-depth 8 --threads "$cores" -q -o "$out/raytree.png")")
            # POV-Ray finds spheres.inc in the working folder.
            theirs+=("$(cd "$here" && wall povray "+I$scene.pov" "+O$out/povray.png" "+W$w" "+H$h" \
                -D -A +FN8 File_Gamma=sRGB "+WT$cores" -V -GA)")
        done
        t_ours=$(printf '%s\n' "${ours[@]}" | median)
        t_theirs=$(printf '%s\n' "${theirs[@]}" | median)
        ratio=$(awk -v a="$t_theirs" -v b="$t_ours" 'BEGIN { printf "%.6f", a / b }')
        diff=$("$raytree" diff "$out/raytree.png" "$out/povray.png")
        printf '%-8s %-9s %10.3f s %10.3f s %7.2fx   %s\n' "$scene" "$size" "$t_ours" "$t_theirs" "$ratio" "$diff"
    done
done
