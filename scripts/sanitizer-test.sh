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
# Mesa's lavapipe keeps an allocation in its globals that LeakSanitizer reports as a leak (128
# bytes from an "<unknown module>") once the Vulkan loader has unloaded the driver at exit, as
# the cpu tests that list devices or fall back from Vulkan do. Preloaded, the driver stays
# mapped and what it holds stays reachable; the leak check still covers all of our code.
lavapipe=$(ls /usr/lib/*/libvulkan_lvp.so 2>/dev/null | head -1 || true)
[ -z "$lavapipe" ] || export LD_PRELOAD="$lavapipe${LD_PRELOAD:+:$LD_PRELOAD}"
ctest --test-dir build-asan -L cpu --output-on-failure -j"$(nproc)"
unset LD_PRELOAD

# gcc and clang must draw the same images (the path tracer draws its random numbers in one fixed
# order; the real-time model has no order to lose): with the gcc build of build/ beside this
# one (as in scripts/setup-and-test.sh), a small path trace and a CPU still from each compare
# byte for byte.
if [ -x build/cloudscape ]; then
    images=$(mktemp -d)
    trap 'rm -rf "$images"' EXIT
    for compiler in build build-asan; do
        "$compiler/cloudscape" pathtrace --width 48 --height 27 --spp 8 \
            -o "$images/$compiler-pathtrace.exr" >/dev/null
        "$compiler/cloudscape" render --backend cpu --width 96 --height 54 \
            -o "$images/$compiler-still.exr" >/dev/null
    done
    for image in pathtrace still; do
        cmp "$images/build-$image.exr" "$images/build-asan-$image.exr" ||
            { echo "sanitizer-test: gcc and clang render different $image images" >&2; exit 1; }
    done
    echo "sanitizer-test: gcc (build/) and clang (build-asan/) render the same images"
fi
