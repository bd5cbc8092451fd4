#!/usr/bin/env bash
# The C harness (tests/c/harness.c) against every block's FMU binaries, FMI 2.0 (<Block>.fmu)
# and FMI 3.0 (fmi3/<Block>.fmu, compared with the block's FMI 2.0 library), in three parts:
#   (a) plain                    the FMUs that ship: those of fmus/ (make build), unzipped into
#                                build-harness/unpacked/; each run loads binaries/<platform>/
#                                <Block>.so with the modelDescription.xml beside it; only the
#                                harness is built (build-harness/, Release)
#   (b) ASan + UBSan             build-asan/: the same sources built again, instrumented (FMUs
#                                and harness; -DSANITIZE=address,undefined,float-cast-overflow:
#                                GCC leaves float-cast-overflow out of "undefined"); its FMUs
#                                (build-asan/fmus/) unzipped the same way
#   (c) valgrind memcheck        the FMUs and the harness of (a), VALGRIND_CYCLES (default 5000,
#                                half of (a): memory errors show in the paths, not the count)
#                                cycles, 2 rounds of threads instead of
#                                10, and for FMI 3.0 VALGRIND_CYCLES3 (default 2000) cycles
# Each part prints the harness's lines per group and each run's duration; the script ends with
# the sum of all runs as "N passed, M failed" and exits non-zero if anything failed. A tool that
# is missing and cannot be installed is reported as "SKIPPED: ..." and the other parts go on.
#   tests/c/check.sh                (VALGRIND_CYCLES=N, VALGRIND_CYCLES3=N to change the cycles
#                                    under valgrind)
#
# Hang guard: every harness run gets --timeout (its SIGALRM: "harness timed out (a call
# hangs?)"), never a fixed one (tools/hang-guard.sh):
#   (a) plain                    300 s × load factor (max(1, load / CPUs))
#   (b), (c) every later run     the larger of that and 300 × the plain run of the same block
#                                (× VALGRIND_CYCLES / 10000 under valgrind), × the load's rise
#                                since; measured: valgrind takes 20-40× the plain run when
#                                idle, about 60× under a load of 12 on 2 cores
# LGF_TIMEOUT_SCALE=F multiplies every guard (0: none); LGF_HARNESS_TIMEOUT=S sets every run's
# guard to S seconds (0: none).
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
PY=${PYTHON_FOR_CMAKE:-$ROOT/.venv/bin/python}
# The blocks: the folders of src/blocks with an interface.toml (as CMakeLists.txt finds them).
BLOCKS=()
for interface in src/blocks/*/interface.toml; do BLOCKS+=("$(basename "$(dirname "$interface")")"); done
PLAIN_CYCLES=10000
VALGRIND_CYCLES=${VALGRIND_CYCLES:-5000}
VALGRIND_CYCLES3=${VALGRIND_CYCLES3:-2000}
JOBS=${JOBS:-2}
# The floor of every guard (× load factor) and the factor on the plain run's duration.
GUARD_FLOOR=300
GUARD_FACTOR=300
# shellcheck source=../../tools/hang-guard.sh
. tools/hang-guard.sh
lgf_check_timeout_env
case $VALGRIND_CYCLES in '' | *[!0-9]* | 0) echo "VALGRIND_CYCLES must be a positive number" >&2; exit 2 ;; esac
case $VALGRIND_CYCLES3 in '' | *[!0-9]* | 0) echo "VALGRIND_CYCLES3 must be a positive number" >&2; exit 2 ;; esac

tools/ensure-packages.sh valgrind:valgrind

total_passed=0
total_failed=0
failures=()
summary=()
# The plain run of each block and version (keys <block>, <block>-fmi3): its duration and the
# load factor it ran under.
declare -A plain_seconds plain_load
# Harness arguments of the FMI 3.0 runs only (after the part's own: the later one counts).
fmi3_args=()
# The unpacked FMUs of fmus/ once (a) has them (and its harness is built): (a) and (c) test them.
plain_fmus=

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'; }
# FMI 2.0's guid, FMI 3.0's instantiationToken
guid_of() { grep -o -E '(guid|instantiationToken)="[^"]*"' "$1" | head -n 1 | cut -d'"' -f2; }

# configure_and_build <dir> <target, or "" for all> <extra cmake args...>
configure_and_build() {
    local dir=$1 target=$2
    shift 2
    mkdir -p "$dir"
    # Without documentation: the harness needs the binaries only (and no matplotlib).
    cmake -S . -B "$dir" -DLGF_HARNESS=ON -DLGF_DOCUMENTATION=OFF -DFMU_OUTPUT_DIR="$ROOT/$dir/fmus" \
        -DPython3_EXECUTABLE="$PY" "$@" >"$dir/configure.log" 2>&1 ||
        { cat "$dir/configure.log"; return 1; }
    cmake --build "$dir" --parallel "$JOBS" ${target:+--target "$target"} >"$dir/build.log" 2>&1 ||
        { tail -n 60 "$dir/build.log"; return 1; }
}

# The platform folder of this machine's binaries in an FMU of FMI 2.0 and of FMI 3.0 (an FMI 3.0
# FMU also holds aarch64-linux, which the harness cannot load here).
NATIVE_PLATFORM_2=linux64
NATIVE_PLATFORM_3=x86_64-linux

# native_library <unpacked FMU folder> <version> <block>: the path of its native <Block>.so.
native_library() {
    local platform=NATIVE_PLATFORM_$2
    echo "$1/binaries/${!platform}/$3.so"
}

# unpack_fmus <fmu dir> <dest>: every block's <fmu dir>/<Block>.fmu and <fmu dir>/fmi3/<Block>.fmu
# unzipped into <dest>/fmi2/<Block>/ and <dest>/fmi3/<Block>/, each with its native <Block>.so.
unpack_fmus() {
    local from=$1 to=$2 block version fmu folder library
    rm -rf "$to"
    for block in "${BLOCKS[@]}"; do
        for version in 2 3; do
            fmu=$from/$block.fmu
            [ "$version" = 2 ] || fmu=$from/fmi3/$block.fmu
            if [ ! -f "$fmu" ]; then
                echo "$fmu is missing (make build writes fmus/)"
                return 1
            fi
            folder=$to/fmi$version/$block
            "$PY" -m zipfile -e "$fmu" "$folder" || { echo "cannot unzip $fmu"; return 1; }
            library=$(native_library "$folder" "$version" "$block")
            if [ ! -f "$library" ]; then
                echo "$fmu holds no ${library#"$folder"/}"
                return 1
            fi
        done
    done
}

# fmu_of <unpacked dir> <version> <block>: sets fmu to the harness's three arguments for that
# FMU: its library, its modelDescription.xml and the guid or instantiationToken in it.
fmu_of() {
    local folder=$1/fmi$2/$3
    local xml=$folder/modelDescription.xml
    fmu=("$(native_library "$folder" "$2" "$3")" "$xml" "$(guid_of "$xml")")
}

# Adds a harness run's closing "N passed, M failed" to the totals (a run that died before it
# counts as one failure).
count() {
    local output=$1 label=$2 status=$3 line
    line=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$output" | tail -n 1 || true)
    if [ -n "$line" ]; then
        total_passed=$((total_passed + $(echo "$line" | cut -d' ' -f1)))
        total_failed=$((total_failed + $(echo "$line" | cut -d' ' -f3)))
    else
        total_failed=$((total_failed + 1))
        line="no result (exit status $status)"
    fi
    if [ "$status" != 0 ]; then
        failures+=("$label: $line, exit status $status")
        # e.g. valgrind's error exit code after a harness run whose own checks all passed
        if echo "$line" | grep -q ' 0 failed'; then total_failed=$((total_failed + 1)); fi
    fi
}

# guard_for <label> <block> <factor>: the --timeout of one harness run (see the top).
guard_for() {
    local label=$1 block=$2 factor=$3
    if [ -n "${LGF_HARNESS_TIMEOUT:-}" ]; then
        echo "$LGF_HARNESS_TIMEOUT"
    elif [ "$label" != plain ] && [ -n "${plain_seconds[$block]:-}" ]; then
        lgf_hang_guard "$GUARD_FLOOR" "$factor" "${plain_seconds[$block]}" "${plain_load[$block]}"
    else
        lgf_hang_guard "$GUARD_FLOOR"
    fi
}

# run_one <output> <command...>: one harness run, its output into <output>, its exit status,
# duration and load factor at the start into <output>.status, .seconds and .load.
run_one() {
    local output=$1 started status=0
    shift
    lgf_load_factor >"$output.load"
    started=$(now)
    "$@" >"$output" 2>&1 || status=$?
    elapsed "$started" >"$output.seconds"
    echo "$status" >"$output.status"
}

# run_part <label> <build dir> <unpacked FMUs> <guard factor> <harness args...> -- <prefix...>
# (the harness is <build dir>/tests/c/harness, its logs go to <build dir>). The runs of the
# blocks, each FMI 2.0 and 3.0, go JOBS at a time (each run is one process; its guard scales with
# the load it starts under); their reports follow in the blocks' order once all have ended.
run_part() {
    local label=$1 dir=$2 fmus=$3 factor=$4
    shift 4
    local args=()
    while [ "$1" != "--" ]; do args+=("$1"); shift; done
    shift
    local prefix=("$@")
    local n=${#BLOCKS[@]} i block other version key status output guard load seconds
    local versioned mine2 mine3 other2 other3 fmu
    local -a keys=() outputs=() guards=() labels=()
    for ((i = 0; i < n; i++)); do
        block=${BLOCKS[$i]}
        other=${BLOCKS[$(((i + 1) % n))]}
        fmu_of "$fmus" 2 "$block"; mine2=("${fmu[@]}")
        fmu_of "$fmus" 3 "$block"; mine3=("${fmu[@]}")
        fmu_of "$fmus" 2 "$other"; other2=("${fmu[@]}")
        fmu_of "$fmus" 3 "$other"; other3=("${fmu[@]}")
        for version in 2 3; do
            if [ "$version" = 2 ]; then
                key=$block
            else
                key=$block-fmi3
            fi
            guard=$(guard_for "$label" "$key" "$factor")
            if [ "$version" = 2 ]; then
                versioned=("${args[@]}" --timeout "$guard" "${mine2[@]}" "${other2[@]}")
            else
                versioned=("${args[@]}" "${fmi3_args[@]+"${fmi3_args[@]}"}" --timeout "$guard"
                    --fmi2 "${mine2[@]:0:2}" "${mine3[@]}" "${other3[@]}")
            fi
            output="$dir/harness-$label-$key.log"
            rm -f "$output" "$output.status" "$output.seconds" "$output.load"
            while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n || true; done
            run_one "$output" "${prefix[@]}" "$dir/tests/c/harness" "${versioned[@]}" &
            keys+=("$key") outputs+=("$output") guards+=("$guard")
            labels+=("$label $block FMI $version.0")
        done
    done
    wait
    for ((i = 0; i < ${#keys[@]}; i++)); do
        key=${keys[$i]} output=${outputs[$i]} guard=${guards[$i]}
        status=$(cat "$output.status" 2>/dev/null || echo 1)
        seconds=$(cat "$output.seconds" 2>/dev/null || echo 0)
        load=$(cat "$output.load" 2>/dev/null || echo 1)
        sed 's/^/  /' "$output"
        echo "  (${labels[$i]}: $seconds s, hang guard $(describe_guard "$guard"), load factor $load)"
        if grep -q 'harness timed out' "$output"; then
            echo "  The run hit its hang guard of $(describe_guard "$guard"). If the machine is only slow, not"
            echo "  hanging: LGF_TIMEOUT_SCALE=F multiplies the guards, LGF_HARNESS_TIMEOUT=S sets them."
        fi
        if [ "$label" = plain ]; then
            plain_seconds[$key]=$seconds
            plain_load[$key]=$load
        fi
        count "$output" "${labels[$i]}" "$status"
    done
}

describe_guard() { if [ "$1" = 0 ]; then echo "none"; else echo "$1 s"; fi; }

# ---- (a) plain ----
echo "== (a) C harness, plain: the libraries inside fmus/*.fmu and fmus/fmi3/*.fmu =="
start=$(now)
if ! configure_and_build build-harness lgf_harness; then
    failures+=("(a) the build of the harness failed")
    total_failed=$((total_failed + 1))
elif ! unpack_fmus fmus build-harness/unpacked; then
    failures+=("(a) the FMUs of fmus/ could not be unpacked (see above)")
    total_failed=$((total_failed + 1))
else
    plain_fmus=build-harness/unpacked
    run_part plain build-harness "$plain_fmus" 0 --cycles "$PLAIN_CYCLES" --
    summary+=("(a) plain:    $(elapsed "$start") s")
fi

# ---- (b) AddressSanitizer + UndefinedBehaviorSanitizer ----
echo "== (b) C harness under ASan + UBSan (build-asan: the sources built again, instrumented) =="
start=$(now)
probe=$(mktemp -d)
echo 'int main(void) { return 0; }' >"$probe/probe.c"
if ! cc -fsanitize=address,undefined "$probe/probe.c" -o "$probe/probe" >/dev/null 2>&1; then
    echo "SKIPPED: ASan + UBSan (the C compiler cannot link -fsanitize=address,undefined;" \
         "install libasan and libubsan for it)"
    summary+=("(b) sanitizers: SKIPPED")
elif configure_and_build build-asan "" -DSANITIZE=address,undefined,float-cast-overflow \
        -DCMAKE_BUILD_TYPE=RelWithDebInfo && unpack_fmus build-asan/fmus build-asan/unpacked; then
    # The harness dlopens the instrumented libraries; the runtime comes with the executable.
    # LeakSanitizer needs ptrace, which some containers forbid: then leaks are left to the
    # harness's own allocation count and to valgrind, and the line below says so.
    leaks=1
    if ! ASAN_OPTIONS=detect_leaks=1 "$probe/probe" >/dev/null 2>&1; then
        leaks=0
        echo "  NOTE: LeakSanitizer cannot run here (ptrace not permitted); leak checks come from" \
             "the harness's allocation count and valgrind"
    fi
    export ASAN_OPTIONS="detect_leaks=$leaks:halt_on_error=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1:detect_invalid_pointer_pairs=1"
    export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
    run_part asan build-asan build-asan/unpacked "$GUARD_FACTOR" --cycles "$PLAIN_CYCLES" --
    unset ASAN_OPTIONS UBSAN_OPTIONS
    summary+=("(b) sanitizers: $(elapsed "$start") s")
else
    failures+=("(b) the sanitizer build failed")
    total_failed=$((total_failed + 1))
fi
rm -rf "$probe"

# ---- (c) valgrind memcheck on the FMUs of (a) ----
echo "== (c) C harness under valgrind memcheck (fmus/, $VALGRIND_CYCLES cycles," \
     "FMI 3.0 $VALGRIND_CYCLES3) =="
start=$(now)
if ! command -v valgrind >/dev/null 2>&1; then
    echo "SKIPPED: valgrind (not installed; sudo apt-get install valgrind)"
    summary+=("(c) valgrind:  SKIPPED")
elif [ -z "$plain_fmus" ]; then
    echo "SKIPPED: valgrind (the harness or the FMUs of (a) are missing)"
    summary+=("(c) valgrind:  SKIPPED")
else
    valgrind_factor=$(awk -v f="$GUARD_FACTOR" -v c="$VALGRIND_CYCLES" -v p="$PLAIN_CYCLES" \
        'BEGIN { print ((c > p) ? f * c / p : f) }')
    # The FMI 3.0 runs repeat what the FMI 2.0 runs did through the same core: fewer cycles.
    fmi3_args=(--cycles "$VALGRIND_CYCLES3")
    # --child-silent-after-fork: the harness runs the cases of known crashes in a child
    # (isolated() in harness.c), whose end is a failed check, not valgrind's report.
    run_part valgrind build-harness "$plain_fmus" "$valgrind_factor" \
        --cycles "$VALGRIND_CYCLES" --rounds 2 -- \
        valgrind --tool=memcheck --leak-check=full --errors-for-leak-kinds=definite,indirect \
        --error-exitcode=99 --quiet --child-silent-after-fork=yes
    fmi3_args=()
    summary+=("(c) valgrind:  $(elapsed "$start") s")
fi

echo "== C harness summary =="
for line in "${summary[@]}"; do echo "  $line"; done
for line in "${failures[@]+"${failures[@]}"}"; do echo "  FAILED: $line"; done
echo "$total_passed passed, $total_failed failed"
[ "$total_failed" -eq 0 ] && [ ${#failures[@]} -eq 0 ]
