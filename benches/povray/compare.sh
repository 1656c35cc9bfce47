#!/usr/bin/env bash
# raytree side by side with POV-Ray 3.7 on the same scenes.
#
# Renders scenes/whitted.json and scenes/spheres.json with raytree and their
# hand-written POV-Ray twins (whitted.pov, spheres.pov beside this script) at
# 640×480 and 1280×960, 1 sample per pixel (antialiasing off), max depth 8, on
# all cores, alternating the two renderers run after run so a busy machine slows
# both alike. Prints, as medians:
#   - each side's wall time for the whole command (start-up, parsing, building,
#     rendering, writing the PNG) and their ratio, and
#   - each side's own report of its rendering time (POV-Ray's "Trace Time",
#     raytree's "… s building and tracing", both without start-up, parsing and
#     writing the file)
#     and their ratio: POV-Ray's fixed start-up (about 0.7 s) flatters small
#     images in the first ratio, not in this one,
# and how far the images differ in 8-bit.
#
# BEFORE=path/to/an/older/raytree renders with that binary too, in the same
# alternation, and adds its own render time and POV-Ray's ratio to it: a
# before/after in one session (docs/performance.md).
#
# Usage: benches/povray/compare.sh [RUNS] [SIZES]
#   RUNS defaults to 5; SIZES to "640x480 1280x960" (e.g. "160x120" for a quick check).
# Installs POV-Ray from the system's package manager (apt-get) if it is missing,
# and waits (see ../idle.sh) until the machine is idle enough to time.
set -euo pipefail

runs=${1:-5}
sizes=${2:-640x480 1280x960}
[[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "usage: $0 [RUNS] [SIZES]" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
source "$here/../idle.sh"
cores=$(nproc)

source "$here/setup.sh"

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# Runs a command; prints its wall time in seconds, keeps its stderr in $out/stderr.
wall() {
    local start end
    start=$(date +%s.%N)
    "$@" >/dev/null 2>"$out/stderr" || { cat "$out/stderr" >&2; exit 1; }
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" 'BEGIN { printf "%.6f\n", b - a }'
}

# raytree's own time from its "wrote" line: "…, 0.31 s building and tracing on
# 2 threads", or "in 0.31 s on" from a build older than 2026-11-26 (BEFORE).
own_time() {
    sed -n -e 's/.*, \([0-9.]*\) s building and tracing on .*/\1/p' \
        -e 's/.* in \([0-9.]*\) s on .*/\1/p' "$1"
}

ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2fx", a / b }'; }

wait_for_idle
echo "raytree $("$raytree" --version | cut -d' ' -f2) vs $povray_version, $cores cores, median of $runs alternating runs$busy"
printf '%-8s %-9s | %9s %9s %7s | %9s %9s %7s | %s\n' scene size \
    "raytree" "POV-Ray" "ratio" "raytree" "POV-Ray" "ratio" "image difference (8-bit)"
printf '%-8s %-9s | %-27s | %-27s |\n' "" "" "wall time, whole command" "own render / trace time"
for scene in whitted spheres; do
    for size in $sizes; do
        w=${size%x*}
        h=${size#*x}
        ours=() theirs=() ours_own=() theirs_own=() before_own=()
        for ((i = 0; i < runs; i++)); do
            if [[ -n ${BEFORE:-} ]]; then
                wall "$BEFORE" render "$root/scenes/$scene.json" --width "$w" --height "$h" \
                    --spp 1 --max-depth 8 --threads "$cores" -o "$out/before.png" >/dev/null
                before_own+=("$(own_time "$out/stderr")")
            fi
            ours+=("$(wall "$raytree" render "$root/scenes/$scene.json" --width "$w" --height "$h" \
                --spp 1 --max-depth 8 --threads "$cores" -o "$out/raytree.png")")
            ours_own+=("$(own_time "$out/stderr")")
            # POV-Ray finds spheres.inc in the working folder; +GS prints its statistics (the trace time).
            theirs+=("$(cd "$here" && wall povray "+I$scene.pov" "+O$out/povray.png" "+W$w" "+H$h" \
                -D -A +FN8 File_Gamma=sRGB "+WT$cores" -V +GS)")
            theirs_own+=("$(sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "$out/stderr")")
        done
        t_ours=$(printf '%s\n' "${ours[@]}" | median)
        t_theirs=$(printf '%s\n' "${theirs[@]}" | median)
        o_ours=$(printf '%s\n' "${ours_own[@]}" | median)
        o_theirs=$(printf '%s\n' "${theirs_own[@]}" | median)
        # Exit status 1 says the images differ: expected, the figure is what counts.
        diff=$("$raytree" diff "$out/raytree.png" "$out/povray.png" || true)
        printf '%-8s %-9s | %7.3f s %7.3f s %7s | %7.3f s %7.3f s %7s | %s\n' "$scene" "$size" \
            "$t_ours" "$t_theirs" "$(ratio "$t_theirs" "$t_ours")" \
            "$o_ours" "$o_theirs" "$(ratio "$o_theirs" "$o_ours")" "$diff"
        if [[ -n ${BEFORE:-} ]]; then
            o_before=$(printf '%s\n' "${before_own[@]}" | median)
            printf '%-8s %-9s   before: own render time %.3f s, POV-Ray ÷ before %s\n' "" "" \
                "$o_before" "$(ratio "$o_theirs" "$o_before")"
        fi
    done
done
