#!/usr/bin/env bash
# Builds penumbra and its test suite with AddressSanitizer + UndefinedBehaviorSanitizer in their own
# build directory and runs the whole suite (CONTRIBUTING.md). Any report fails a test: the GPU and
# loader tests abort in-process, the CLI tests see the child's report on stderr and its exit status.
#   scripts/sanitize.sh [ctest arguments, e.g. -R Gltf]
# Environment: BUILD (default build-asan), JOBS (default nproc).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD:-build-asan}
jobs=${JOBS:-$(nproc)}
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build "$build" -j"$jobs"
supp="$PWD/scripts/sanitize"
# lavapipe, LLVM, the Vulkan loader and the validation layer keep allocations for the process's
# lifetime (lsan.supp). The loader dlclose()s the driver and the layer before LeakSanitizer runs, which
# would leave their allocations in "<unknown module>" where no suppression can name them:
# keep_loaded.c, preloaded after the ASan runtime (which must come first), keeps them mapped. Child
# processes (the CLI tests) inherit all of it.
cc -shared -fPIC -O1 -o "$build/keep_loaded.so" scripts/sanitize/keep_loaded.c -ldl
export LD_PRELOAD="$(gcc -print-file-name=libasan.so):$PWD/$build/keep_loaded.so"
# embed_install builds examples/embed against the instrumented library, so with the same flags (cmake
# takes CXXFLAGS and LDFLAGS as a new project's defaults); it runs its tools without the preload.
export CXXFLAGS="$flags" LDFLAGS="-fsanitize=address,undefined"
# The view tests start their Xvfb without it (tests/view/x_server.cpp): it is not ours to check.
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:strict_string_checks=1:check_initialization_order=1"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="suppressions=$supp/ubsan.supp:print_stacktrace=1:halt_on_error=1"
ctest --test-dir "$build" --output-on-failure -j"$jobs" --timeout 600 "$@"
