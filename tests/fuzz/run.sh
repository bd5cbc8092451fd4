#!/usr/bin/env bash
# Fuzzes every LGF FMU with libFuzzer (tests/fuzz/fuzz_fmu.c), SECONDS seconds per block:
#   tests/fuzz/run.sh [SECONDS]          (default 60; `make fuzz-smoke` shares 120 s among the
#                                         blocks, at least 4 s each; `make fuzz` runs 3600)
# 1. installs clang and the libFuzzer/sanitizer runtime where it may (tools/ensure-packages.sh);
#    without them it prints "SKIPPED: fuzzing (...)" and exits 0;
# 2. builds build-fuzz (CC=clang, -DLGF_FUZZ=ON; its FMUs go to build-fuzz/fmus, not fmus/);
# 3. replays the committed inputs: tests/fuzz/regressions/*/ (inputs that once found a bug,
#    on every block) and the seeds of tests/fuzz/corpus/<block>/;
# 4. fuzzes each block for SECONDS seconds from a fresh temporary corpus seeded with them, JOBS
#    blocks at a time (default 2, one a core); when a loaded machine managed fewer than
#    FUZZ_MIN_RUNS executions (default 10000; idle, two cores do 80,000-400,000 per block in
#    60 s), the block goes on for the missing executions, so a slow machine takes longer
#    instead of fuzzing less than that.
# Exits non-zero when a replay or the fuzzer finds a crash, a sanitizer report, a violated
# invariant, a leak or a hang; the input is kept under build-fuzz/artifacts/<block>/, to be
# committed to tests/fuzz/regressions/<block>/ together with the fix.
# A hang is one input running longer than 25 s × load factor (tools/hang-guard.sh; the
# slowest input measured takes under 1 s), × LGF_TIMEOUT_SCALE (0: no limit).
set -u
cd "$(dirname "$0")/../.."
root=$PWD
seconds=${1:-60}
case $seconds in '' | *[!0-9]* | 0) echo "usage: tests/fuzz/run.sh [SECONDS > 0]" >&2; exit 2 ;; esac
min_runs=${FUZZ_MIN_RUNS:-10000}
case $min_runs in '' | *[!0-9]*) echo "FUZZ_MIN_RUNS must be a number" >&2; exit 2 ;; esac
# shellcheck source=../../tools/hang-guard.sh
. tools/hang-guard.sh
lgf_check_timeout_env || exit 2
# The blocks: the folders of src/blocks with an interface.toml (as CMakeLists.txt finds them).
blocks=$(for interface in src/blocks/*/interface.toml; do basename "$(dirname "$interface")"; done)
build=build-fuzz

describe_limit() { if [ "$1" = 0 ]; then echo "no limit"; else echo "$1 s"; fi; }

skip() {
    echo "SKIPPED: fuzzing ($*)"
    exit 0
}

# clang, and Debian 12's libclang-rt-14-dev for libclang_rt.fuzzer, asan and ubsan (clang
# installed without recommends does not bring it). The runtime has no command of its own: the
# name before the colon is only there so that the package itself is looked up.
tools/ensure-packages.sh clang:clang libclang-rt-14-dev:libclang-rt-14-dev
command -v clang >/dev/null 2>&1 || skip "clang is not installed"
probe=$(mktemp -d)
trap 'rm -rf "$probe"' EXIT
printf '%s\n' '#include <stddef.h>' '#include <stdint.h>' \
    'int LLVMFuzzerTestOneInput(const uint8_t *d, size_t n) { (void)d; (void)n; return 0; }' \
    >"$probe/probe.c"
if ! clang -fsanitize=fuzzer,address,undefined "$probe/probe.c" -o "$probe/probe" 2>"$probe/err"; then
    skip "clang cannot build -fsanitize=fuzzer,address,undefined, the libFuzzer runtime is missing: $(grep -m1 -i error "$probe/err")"
fi

export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
python=python3
[ -x .venv/bin/python ] && python=$root/.venv/bin/python
started=$(date +%s)
echo "== fuzz: building $build"
if ! CC=clang cmake -S . -B "$build" -DLGF_FUZZ=ON -DLGF_DOCUMENTATION=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DFMU_OUTPUT_DIR="$root/$build/fmus" -DPython3_EXECUTABLE="$python" >"$probe/configure.log" 2>&1; then
    cat "$probe/configure.log"
    echo "fuzz: configuring $build failed (FMPy provides the FMI headers: make venv)"
    exit 1
fi
targets=$(for b in $blocks; do printf 'fuzz_%s ' "$b"; done)
# shellcheck disable=SC2086
if ! cmake --build "$build" --parallel "${JOBS:-2}" --target $targets >"$probe/build.log" 2>&1; then
    cat "$probe/build.log"
    echo "fuzz: building the fuzz targets failed"
    exit 1
fi
echo "   built in $(($(date +%s) - started)) s"

# One block: replay, then fuzz; its result goes to $lanes/<block>.result as
# "<ok|failed> <executions> <summary line>".
report() { echo "$1 $2 $3" >"$lanes/$block.result"; }
fuzz_block() {
    local block=$1
    # libFuzzer's -timeout: one input running longer is reported as a hang (0: never).
    input_timeout=$(lgf_hang_guard 25)
    fuzzer=$root/$build/tests/fuzz/fuzz_$block
    artifacts=$root/$build/artifacts/$block
    mkdir -p "$artifacts"
    log=$root/$build/fuzz-$block.log
    echo "== fuzz $block"

    # Replay the committed inputs, each once: the regressions of every block (most found bugs
    # of the shared layer) and this block's seeds.
    committed=()
    for dir in tests/fuzz/regressions tests/fuzz/corpus/$block; do
        [ -d "$dir" ] || continue
        while IFS= read -r -d '' file; do committed+=("$file"); done \
            < <(find "$dir" -type f ! -name '.*' ! -name '*.md' -print0 | sort -z)
    done
    if [ ${#committed[@]} -gt 0 ]; then
        if ! "$fuzzer" -rss_limit_mb=2048 -timeout="$input_timeout" "${committed[@]}" >"$log.replay" 2>&1; then
            grep -E -m8 'Running:|INVARIANT|ERROR|runtime error|SUMMARY' "$log.replay"
            echo "   a committed input FAILS (full log: $log.replay)"
            report failed 0 "$block: replay of ${#committed[@]} committed inputs FAILED"
            return
        fi
    fi

    # Inputs of bugs that were found but are not fixed yet (see tests/fuzz/README.md, "Open
    # findings"), in tests/fuzz/known/<block>/, a folder that exists only while there are any:
    # reported, not failed; once one passes it belongs in regressions/.
    # (Always with every invariant on: LGF_FUZZ_SKIP_KNOWN only lets the fuzzing go past them.)
    for file in tests/fuzz/known/$block/*; do
        [ -f "$file" ] || continue
        if LGF_FUZZ_SKIP_KNOWN= "$fuzzer" -rss_limit_mb=2048 -timeout="$input_timeout" "$file" >"$log.known" 2>&1; then
            echo "   NOTE: $file passes now: move it to tests/fuzz/regressions/$block/"
        else
            echo "   KNOWN, not fixed yet: $file: $(grep -m1 -E 'runtime error|INVARIANT|ERROR' "$log.known")"
        fi
    done

    # Fuzz from a fresh corpus seeded with the committed inputs.
    corpus=$(mktemp -d)
    i=0
    for file in "${committed[@]}"; do cp "$file" "$corpus/$((i += 1))-${file##*/}"; done
    echo "   ${#committed[@]} committed inputs replayed; fuzzing for $seconds s" \
         "(at least $min_runs executions; hang: one input > $(describe_limit "$input_timeout"))"
    block_started=$(date +%s)
    fuzz=("$fuzzer" "$corpus" -rss_limit_mb=2048 -timeout="$input_timeout" -max_len=4096
          -print_final_stats=1 -artifact_prefix="$artifacts/")
    "${fuzz[@]}" -max_total_time="$seconds" >"$log" 2>&1
    status=$?
    executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    executions=${executions:-0}
    extended=
    if [ "$status" -eq 0 ] && [ "$executions" -lt "$min_runs" ]; then
        # A loaded machine: go on from the corpus grown so far for the missing executions.
        echo "   only $executions executions in $seconds s (load factor $(lgf_load_factor)):" \
             "going on for $((min_runs - executions)) more"
        extended=" (only $executions in the first $seconds s)"
        "${fuzz[@]}" -runs=$((min_runs - executions)) >"$log.more" 2>&1
        status=$?
        more=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log.more" | tail -1)
        executions=$((executions + ${more:-0}))
        cat "$log.more" >>"$log"
    fi
    coverage=$(grep -E -o 'cov: [0-9]+ ft: [0-9]+' "$log" | tail -1)
    took=$(($(date +%s) - block_started))
    rm -rf "$corpus"
    if [ "$status" -eq 0 ]; then
        report ok "$executions" "$block: $executions executions in $took s$extended, ${coverage:-no coverage line}, nothing found"
    else
        artifact=$(grep -E -o "$artifacts/[^ ]+" "$log" | tail -1)
        grep -E -m8 'INVARIANT|ERROR|runtime error|SUMMARY' "$log"
        report failed "$executions" "$block: $executions executions, FOUND a problem (exit $status): ${artifact:-see $log}"
    fi
}

# JOBS blocks at a time (default 2, the machine's cores), each block's lines printed together
# when it ends; the summary in the blocks' order.
lanes=$(mktemp -d)
trap 'rm -rf "$probe" "$lanes"' EXIT
running=0
for block in $blocks; do
    { fuzz_block "$block" >"$lanes/$block.out" 2>&1; cat "$lanes/$block.out"; } &
    running=$((running + 1))
    if [ "$running" -ge "${JOBS:-2}" ]; then
        wait -n
        running=$((running - 1))
    fi
done
wait

failed=0
results=()
total_executions=0
for block in $blocks; do
    outcome=failed executions=0 line=
    [ -f "$lanes/$block.result" ] && read -r outcome executions line <"$lanes/$block.result"
    [ "$outcome" = ok ] || failed=1
    total_executions=$((total_executions + executions))
    results+=("${line:-$block: no result (its job died)}")
done

echo "== fuzz summary ($seconds s per block, $(($(date +%s) - started)) s in all)"
for line in "${results[@]}"; do echo "   $line"; done
if [ "$failed" -ne 0 ]; then
    echo "fuzz: FAILED. Replay an input with LGF_FUZZ_TRACE=1 $build/tests/fuzz/fuzz_<block> <file>;"
    echo "      commit it to tests/fuzz/regressions/<block>/ with the fix."
    exit 1
fi
echo "fuzz: passed ($total_executions executions)"
