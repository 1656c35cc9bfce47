# Sourced by the comparison scripts: wait (up to IDLE_WAIT seconds, default 120)
# until the machine is idle enough to time anything, that is until the 1-minute
# load average is below IDLE_LOAD (default 0.5). Still busy after that, the run
# goes on, but every figure it prints is marked as taken on a busy machine.
# Prints the load it started at.
wait_for_idle() {
    local limit=${IDLE_LOAD:-0.5} wait=${IDLE_WAIT:-120} load waited=0
    while :; do
        load=$(cut -d' ' -f1 /proc/loadavg)
        if awk -v l="$load" -v m="$limit" 'BEGIN { exit !(l < m) }'; then
            echo "load average $load (below $limit): idle enough"
            busy=""
            return
        fi
        if ((waited >= wait)); then
            echo "WARNING: load average $load after ${waited} s (wanted below $limit): other work is running, these figures are NOT quotable"
            busy=" (busy machine)"
            return
        fi
        sleep 5
        waited=$((waited + 5))
    done
}

median() {
    sort -g | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
