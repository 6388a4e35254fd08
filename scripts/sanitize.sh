#!/usr/bin/env bash
# Builds kiln with clang, AddressSanitizer and UndefinedBehaviorSanitizer (any report fails; the
# test executables are not instrumented themselves, cmake/KilnCompilerOptions.cmake) in
# build-sanitize/, fuzzes each libFuzzer target of test/fuzz for SECONDS from its committed
# seed corpus (test/fuzz/corpus/TARGET, plus the repository's scenes and meshes), one fuzzer per
# core at a time, then runs the test suite in that build except the Monte Carlo checks labelled
# `statistical` (the release stage, scripts/test.sh, runs those). A crashing input is kept in
# build-sanitize/fuzz/TARGET/; add it to test/fuzz/corpus/TARGET once fixed, so it stays a
# regression input.
#   scripts/sanitize.sh [SECONDS]    (default 6 per target; 0 skips fuzzing)
# Fuzzing for hours: build-sanitize/fuzz_parser -max_total_time=3600 DIR test/fuzz/corpus/parser
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${KILN_SANITIZE_BUILD_DIR:-$root/build-sanitize}"
seconds="${1:-6}"

# clang and its runtimes (libFuzzer, sanitizers) come from Debian's packages
source "$root/scripts/packages.sh"
kiln_install_missing clang libclang-rt-14-dev

jobs="$(nproc 2>/dev/null || echo 2)"
# The release build's RGB-to-spectrum tables (scripts/test.sh builds it first) are copied rather
# than fitted again (about 30 s of one core)
tables="${KILN_BUILD_DIR:-$root/build}/generated/rgb2spec"
from=()
[ -f "$tables/rgb2spec_tables.cpp" ] && from=(-DKILN_RGB2SPEC_FROM="$tables")
if [ ! -f "$build/CMakeCache.txt" ]; then
    CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
        -DKILN_SANITIZE=ON -DKILN_FUZZ=ON -DKILN_BENCH=OFF "${from[@]}" >/dev/null
fi
cmake --build "$build" -j "$jobs"
echo "kiln: sanitizer build: ${SECONDS} s" >&2

export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

# One fuzzer per core at a time; each in its own folder, its log printed if it fails
fuzz_one() {
    local fuzzer="$1" target work
    target="$(basename "$fuzzer")"
    target="${target#fuzz_}"
    work="$build/fuzz/$target"
    mkdir -p "$work/corpus"
    local seeds=("$root/test/fuzz/corpus/$target")
    case "$target" in
    parser | scene) seeds+=("$root/scenes/wilkie2011" "$root/scenes/thermal") ;;
    ply) seeds+=("$root/scenes/textured-meshes") ;;
    esac
    echo "kiln: fuzzing $target for ${seconds}s" >&2
    # A fixed seed (KILN_FUZZ_SEED, default 1): runs draw the same inputs, as far as their
    # time allows, so a failure in CI recurs in a local run of the same length
    if ! (cd "$work" && "$fuzzer" -seed="${KILN_FUZZ_SEED:-1}" -max_total_time="$seconds" \
        -timeout=20 -rss_limit_mb=4096 \
        -max_len=65536 -print_final_stats=1 -artifact_prefix="$work/" \
        corpus "${seeds[@]}" 2>"$work/log.txt"); then
        tail -n 60 "$work/log.txt" >&2
        echo "kiln: fuzzer $target failed; inputs in $work" >&2
        return 1
    fi
    echo "kiln: $target: $(grep -E "stat::number_of_executed_units" "$work/log.txt" || true)" >&2
}

if [ "$seconds" -gt 0 ]; then
    pids=()
    failed=0
    for fuzzer in "$build"/fuzz_*; do
        if [ "${#pids[@]}" -ge "$jobs" ]; then
            wait "${pids[0]}" || failed=1
            pids=("${pids[@]:1}")
        fi
        fuzz_one "$fuzzer" &
        pids+=("$!")
    done
    for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
    [ "$failed" = 0 ] || exit 1
fi
echo "kiln: sanitizer build and fuzzing: ${SECONDS} s" >&2

cd "$build"
# Every test but the Monte Carlo checks labelled `statistical`, the installation tests labelled
# `packaging` and the documentation's commands labelled `releaseonly` (CMakeLists.txt), which
# the release stage runs
ctest --output-on-failure -j "$jobs" --timeout 1800 -LE "statistical|packaging|releaseonly"
echo "kiln: sanitizer stage: ${SECONDS} s" >&2
