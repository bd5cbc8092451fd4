# shellcheck shell=bash
# Hang guards that scale with the machine instead of fixed wall-clock limits. Sourced by
# tests/c/check.sh and tests/fuzz/run.sh; tests/timeouts.py does the same for pytest.
#
#   lgf_load_factor
#       max(1, load / CPUs), the load being the larger of the 1-minute load average and the
#       tasks runnable right now less this one (the average lags a load that just began):
#       roughly how much slower than on an idle machine a CPU-bound run is now (1 where
#       /proc/loadavg is missing).
#   lgf_hang_guard FLOOR [FACTOR MEASURED MEASURED_LOAD]
#       Whole seconds: the larger of FLOOR × load factor now and FACTOR × MEASURED (a duration
#       measured on this run, under load factor MEASURED_LOAD) × how much the load rose since,
#       times LGF_TIMEOUT_SCALE (default 1); 0, i.e. no guard, when LGF_TIMEOUT_SCALE=0.
#   lgf_check_timeout_env
#       Fails (status 2) when LGF_TIMEOUT_SCALE or LGF_HARNESS_TIMEOUT is not a number.

lgf_load_factor() {
    local cpus
    cpus=$(nproc 2>/dev/null || echo 1)
    awk -v cpus="$cpus" '{
        split($4, tasks, "/"); load = (tasks[1] - 1 > $1) ? tasks[1] - 1 : $1
        f = load / cpus; printf "%.2f\n", (f > 1 ? f : 1); exit
    }' /proc/loadavg 2>/dev/null || echo 1
}

lgf_hang_guard() {
    awk -v floor="$1" -v factor="${2:-0}" -v measured="${3:-0}" -v then="${4:-1}" \
        -v now="$(lgf_load_factor)" -v scale="${LGF_TIMEOUT_SCALE:-1}" 'BEGIN {
        guard = floor * now
        rise = (then > 0 && now > then) ? now / then : 1
        if (factor * measured * rise > guard) guard = factor * measured * rise
        guard *= scale
        printf "%d\n", (guard == int(guard)) ? guard : int(guard) + 1
    }'
}

lgf_check_timeout_env() {
    if ! [[ ${LGF_TIMEOUT_SCALE:-1} =~ ^[0-9]+([.][0-9]+)?$ ]]; then
        echo "LGF_TIMEOUT_SCALE must be a number (a factor on every hang guard; 0: none), not '$LGF_TIMEOUT_SCALE'" >&2
        return 2
    fi
    if ! [[ ${LGF_HARNESS_TIMEOUT:-0} =~ ^[0-9]+$ ]]; then
        echo "LGF_HARNESS_TIMEOUT must be whole seconds (0: no guard), not '$LGF_HARNESS_TIMEOUT'" >&2
        return 2
    fi
}
