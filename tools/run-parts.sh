#!/usr/bin/env bash
# Runs the parts of a suite one after another, each to its end even when an earlier one failed,
# then prints one table (part, result, duration, the part's closing result line) and a last
# line "parts: N passed, M failed", and exits non-zero if any part failed. `make test` runs its
# parts through it.
#   tools/run-parts.sh <name> <command> [<name> <command> ...]
# Each command is run by bash -c, with its output shown as it comes. An interrupt (Ctrl-C)
# stops the whole run: the table then shows the parts so far, the current one as interrupted.
set -u
if [ $# -eq 0 ] || [ $(($# % 2)) -ne 0 ]; then
    echo "usage: tools/run-parts.sh <name> <command> [<name> <command> ...]" >&2
    exit 2
fi

names=() results=() durations=() details=()
logs=$(mktemp -d)
current=
suite_started=$(date +%s.%N)

seconds_since() { awk -v a="$1" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }'; }
load() { cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo "?"; }

# The last line of a part's output that states a result (pytest's "N passed ...", the C
# harness's "N passed, M failed", "fuzz: passed ...", "SKIPPED: ..."), else make's last
# error, else its last line.
closing_line() {
    local line
    line=$(grep -E '[0-9]+ (passed|failed)|^fuzz: |SKIPPED' "$1" | tail -n 1)
    [ -n "$line" ] || line=$(grep -E '^make(\[[0-9]+\])?: \*\*\*' "$1" | tail -n 1)
    [ -n "$line" ] || line=$(grep -v '^[[:space:]]*$' "$1" | tail -n 1)
    line=$(echo "$line" | sed -E 's/^[= ]+//; s/[= ]+$//')
    [ ${#line} -le 90 ] || line="${line:0:87}..."
    echo "$line"
}

summary() {
    local i failed=() width=4
    for i in "${!names[@]}"; do [ "${#names[$i]}" -le "$width" ] || width=${#names[$i]}; done
    echo
    echo "==== summary: $(seconds_since "$suite_started") s in all; load average now $(load) on $(nproc) CPUs ===="
    printf "  %-${width}s  %-11s %9s  %s\n" part result duration "closing line"
    for i in "${!names[@]}"; do
        printf "  %-${width}s  %-11s %7s s  %s\n" "${names[$i]}" "${results[$i]}" "${durations[$i]}" "${details[$i]}"
        [ "${results[$i]}" = passed ] || failed+=("${names[$i]}")
    done
    [ ${#failed[@]} -eq 0 ] || echo "  FAILED: ${failed[*]}"
    echo "parts: $((${#names[@]} - ${#failed[@]})) passed, ${#failed[@]} failed"
    rm -rf "$logs"
    [ ${#failed[@]} -eq 0 ]
}

interrupted() {
    if [ -n "$current" ]; then
        names+=("$current") results+=("interrupted") durations+=("$(seconds_since "$part_started")")
        details+=("")
    fi
    summary
    exit 130
}
trap interrupted INT TERM

number=0
total=$(($# / 2))
while [ $# -gt 0 ]; do
    name=$1 command=$2
    shift 2
    number=$((number + 1))
    log=$logs/$number.log
    echo "==== part $number/$total: $name ($command); load average $(load) ===="
    current=$name
    part_started=$(date +%s.%N)
    # Unbuffered Python, so that the output through tee comes as it is written.
    PYTHONUNBUFFERED=1 bash -c "$command" 2>&1 | tee "$log"
    status=${PIPESTATUS[0]}
    current=
    names+=("$name")
    durations+=("$(seconds_since "$part_started")")
    details+=("$(closing_line "$log")")
    if [ "$status" -eq 0 ]; then
        results+=("passed")
    else
        results+=("FAILED ($status)")
    fi
    echo "==== part $number/$total: $name ${results[-1]} in ${durations[-1]} s ===="
done
summary
