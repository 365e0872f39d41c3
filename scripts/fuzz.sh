#!/usr/bin/env bash
# Builds the libFuzzer harnesses of fuzz/ with clang under ASan + UBSan (build-fuzz/) and runs
# each for SECONDS seconds, one after the other, at the lowest CPU priority (FUZZ_NICE=0 gives
# the fuzzer a fair share beside other work: libFuzzer's time limit is wall-clock time).
#   scripts/fuzz.sh [SECONDS] [HARNESS ...]    default: 600 s each, every harness
#   harnesses: scene_json scene_set camera_path weather_png depth_exr checkpoint cli keyframes
#              sequence_checkpoint
# The committed seeds (fuzz/corpus/H) are read, never written: what a run learns goes to
# build-fuzz/fuzz-work/H/corpus, crashes to build-fuzz/fuzz-work/H/artifacts, the log to
# build-fuzz/fuzz-work/H-<UTC start time>.log (one per run: earlier campaigns' logs are kept).
# Add the new coverage to the seeds with
#   build-fuzz/fuzz/fuzz_H -merge=1 fuzz/corpus/H build-fuzz/fuzz-work/H/corpus
# and replay a saved crash with build-fuzz/fuzz/fuzz_H CRASH_FILE. docs/RELIABILITY.md has more.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
seconds=${1:-600}
shift || true
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] ||
    harnesses=(scene_json scene_set camera_path weather_png depth_exr checkpoint cli keyframes
        sequence_checkpoint)
build=${FUZZ_BUILD_DIR:-build-fuzz}
niceness=${FUZZ_NICE:-19}

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
    -DCLOUDSCAPE_SANITIZE=ON -DCLOUDSCAPE_BUILD_FUZZERS=ON -DCLOUDSCAPE_LIBFUZZER=ON \
    -DCLOUDSCAPE_BUILD_TESTS=OFF -DCLOUDSCAPE_BUILD_BENCH=OFF >/dev/null
nice cmake --build "$build" --target "${harnesses[@]/#/fuzz_}"

# Text harnesses: a dictionary of keys and options, and room to grow past the longest seed (the
# 40 KB nesting regressions are cut to this length when loaded, still nested past the limit).
text_options() {
    case $1 in
    scene_json | scene_set | cli) echo "-dict=$root/fuzz/dict/$1.dict -max_len=4096" ;;
    keyframes) echo "-dict=$root/fuzz/dict/scene_json.dict -max_len=4096" ;; # scene keys in JSON
    esac
}

# The CLI prints a line for every refused input: its stderr is closed too (libFuzzer keeps its
# own and the sanitizers' reports); the other harnesses print only their own findings.
closed_fds() { if [ "$1" = cli ]; then echo 3; else echo 1; fi; }

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
status=0
for h in "${harnesses[@]}"; do
    work="$root/$build/fuzz-work/$h"
    mkdir -p "$work/corpus" "$work/artifacts"
    inputs=("$work/corpus" "$root/fuzz/corpus/$h")
    [ -d "$root/fuzz/regressions/$h" ] && inputs+=("$root/fuzz/regressions/$h")
    log="$work-$(date -u +%Y%m%dT%H%M%SZ).log"
    echo "fuzz: $h for ${seconds} s (log ${log#"$root/"})"
    # Absolute paths throughout: the CLI harness works in its own scratch directory.
    # shellcheck disable=SC2046
    if ! nice -n "$niceness" "$root/$build/fuzz/fuzz_$h" -max_total_time="$seconds" -timeout=30 \
        -rss_limit_mb=2048 -close_fd_mask="$(closed_fds "$h")" -print_final_stats=1 \
        -artifact_prefix="$work/artifacts/" $(text_options "$h") "${inputs[@]}" \
        >"$log" 2>&1; then
        echo "fuzz: $h FOUND A CRASH: $(ls -t "$work/artifacts" | head -1) (see $log)"
        status=1
    fi
    { grep -E "^#[0-9]+.*(DONE|pulse|NEW|REDUCE)" "$log" | tail -1 || true; } |
        sed "s/^/fuzz: $h: /"
    { grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$log" || true; } |
        sed "s/^/fuzz: $h: /"
done
exit $status
