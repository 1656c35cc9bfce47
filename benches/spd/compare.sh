#!/usr/bin/env bash
# raytree side by side with POV-Ray 3.7 on Eric Haines's Standard Procedural
# Databases (SPD): the seven scenes balls, gears, mount, rings, teapot, tetra
# and tree.
#
# raytree reads each scene's NFF file and renders it under the SPD protocol
# (`--protocol spd --stats`: 512×512, rays through the 513×513 pixel corners,
# max depth 5, no cutoff); POV-Ray renders the generator's own POV-Ray export
# of the same scene (povray/NAME.pov) at 512×512 with antialiasing off, one
# ray through each pixel's center: 262,144 eye rays against raytree's 263,169
# (0.4 % more). Both use all cores; the two renderers alternate run after run,
# so a busy machine slows both alike. Prints, as medians:
#   - raytree's preprocessing (reading the NFF file, building the hierarchy)
#     and tracing time, from its --stats;
#   - POV-Ray's preprocessing (its parse and bounding times) and trace time,
#     from its own statistics (+GS);
#   - the ratio of the trace times (POV-Ray's over raytree's);
#   - the rays each side cast (raytree's --stats total; POV-Ray's "Rays" and
#     "Shadow Ray Tests"), and the ratio of the time per ray: where POV-Ray
#     traces fewer rays (it reads the POV-Ray 3.1 finishes its own way, and
#     its default adc_bailout stops faint rays the protocol traces), the trace
#     time ratio understates raytree; and
#   - how far the two images differ in 8-bit levels. They are not expected to
#     match: lights, finishes and the camera follow each side's model (see
#     docs/spd.md).
#
# Usage: benches/spd/compare.sh [RUNS] [SCENES]
#   RUNS defaults to 3; SCENES to all seven (e.g. "tetra balls").
#   SPD=DIR points at the SPD folder (default: ../shared/spd beside the repository).
# Installs POV-Ray from the system's package manager (apt-get) if it is missing,
# and waits (see ../idle.sh) until the machine is idle enough to time.
set -euo pipefail

runs=${1:-3}
scenes=${2:-balls gears mount rings teapot tetra tree}
[[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "usage: $0 [RUNS] [SCENES]" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
spd=${SPD:-$root/../shared/spd}
[[ -d $spd/povray ]] || { echo "no SPD scenes in $spd (set SPD=DIR)" >&2; exit 2; }
source "$here/../idle.sh"
cores=$(nproc)

source "$here/../povray/setup.sh"

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2fx", a / b }'; }
# POV-Ray's "Parse Time: ... (0.123 seconds)" line for KIND, in seconds (0 if absent).
pov_time() { sed -n "s/.*$1 Time:.*(\([0-9.]*\) seconds).*/\1/p" "$out/stderr" | head -1 | grep . || echo 0; }

wait_for_idle
echo "$(date -u +%Y-%m-%d), raytree $("$raytree" --version | cut -d' ' -f2) vs $povray_version, $cores cores, load average $(cut -d' ' -f1-3 /proc/loadavg), median of $runs alternating runs$busy"
printf '%-7s | %9s %9s | %9s %9s | %7s | %10s %10s | %7s | %s\n' scene \
    "rt prep" "rt trace" "pov prep" "pov trace" "trace ×" "rt rays" "pov rays" "/ray ×" "image difference (8-bit)"
for scene in $scenes; do
    prep=() trace=() parse=() povtrace=()
    for ((i = 0; i < runs; i++)); do
        "$raytree" render "$spd/$scene.nff" --protocol spd --stats --threads "$cores" \
            -o "$out/raytree.png" >"$out/stats" 2>"$out/stderr" || { cat "$out/stderr" >&2; exit 1; }
        prep+=("$(sed -n 's/^time: \([0-9.]*\) s preprocessing.*/\1/p' "$out/stats")")
        trace+=("$(sed -n 's/.*, \([0-9.]*\) s tracing$/\1/p' "$out/stats")")
        rt_rays=$(sed -n '1s/^\([0-9,]*\) rays:.*/\1/p' "$out/stats" | tr -d ,)
        (cd "$spd/povray" && povray "+I$scene.pov" "+O$out/povray.png" +W512 +H512 \
            -D -A +FN8 File_Gamma=sRGB "+WT$cores" -V +GS) >/dev/null 2>"$out/stderr" \
            || { cat "$out/stderr" >&2; exit 1; }
        pov_rays=$(awk '/^Rays:/ { r = $2 } /^Shadow Ray Tests:/ { s = $4 } END { print r + s }' "$out/stderr")
        parse+=("$(awk -v a="$(pov_time Parse)" -v b="$(pov_time Bounding)" 'BEGIN { print a + b }')")
        povtrace+=("$(pov_time Trace)")
    done
    m_prep=$(printf '%s\n' "${prep[@]}" | median)
    m_trace=$(printf '%s\n' "${trace[@]}" | median)
    m_parse=$(printf '%s\n' "${parse[@]}" | median)
    m_povtrace=$(printf '%s\n' "${povtrace[@]}" | median)
    diff=$("$raytree" diff "$out/raytree.png" "$out/povray.png" || true)
    per_ray=$(awk -v pt="$m_povtrace" -v pr="$pov_rays" -v rt="$m_trace" -v rr="$rt_rays" 'BEGIN { printf "%.2fx", (pt / pr) / (rt / rr) }')
    printf '%-7s | %7.3f s %7.3f s | %7.3f s %7.3f s | %7s | %10s %10s | %7s | %s\n' "$scene" \
        "$m_prep" "$m_trace" "$m_parse" "$m_povtrace" "$(ratio "$m_povtrace" "$m_trace")" \
        "$rt_rays" "$pov_rays" "$per_ray" "${diff%%,*}"
done
