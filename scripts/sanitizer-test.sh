#!/usr/bin/env bash
# CI's sanitizer stage: the library, the CPU tests and the fuzz harnesses built with clang under
# AddressSanitizer + UndefinedBehaviorSanitizer (and LeakSanitizer) in build-asan/, then every
# CPU test there: the unit and CLI tests, and each harness replaying its committed corpus and
# saved regressions (fuzz/corpus, fuzz/regressions). The first report fails the test.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
    -DCLOUDSCAPE_SANITIZE=ON -DCLOUDSCAPE_BUILD_FUZZERS=ON -DCLOUDSCAPE_BUILD_BENCH=OFF \
    -DCLOUDSCAPE_BUILD_GPU_TESTS=OFF >/dev/null
cmake --build build-asan
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
ctest --test-dir build-asan -L cpu --output-on-failure -j"$(nproc)"
