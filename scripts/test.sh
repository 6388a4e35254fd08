#!/usr/bin/env bash
# Builds kiln and its tests (installing missing packages first) and runs them in two stages,
# each test once: here the tests only a release build runs (the Monte Carlo checks labelled
# `statistical`, the installation tests labelled `packaging`, the documentation's commands
# labelled `releaseonly`: CMakeLists.txt), then the sanitizer stage (scripts/sanitize.sh: a
# clang build with AddressSanitizer and UndefinedBehaviorSanitizer, each libFuzzer target fuzzed
# for KILN_FUZZ_SECONDS, default 6, and every other test under the sanitizers). KILN_QUICK=1
# skips the sanitizer stage and runs the whole suite here.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# Each stage prints how long it took (seconds), so that a CI log tells where its time went
# With the sanitizer stage to follow, the release build makes only what its stage runs
# (CMakeLists.txt: kiln_release_stage); the sanitizer build makes every test
if [ "${KILN_QUICK:-0}" = 1 ]; then
    "$root/scripts/bootstrap.sh"
else
    "$root/scripts/bootstrap.sh" --target kiln_release_stage
fi
echo "kiln: set-up and release build: ${SECONDS} s" >&2
start=$SECONDS
only=()
[ "${KILN_QUICK:-0}" = 1 ] || only=(-L "statistical|packaging|releaseonly")
(cd "${KILN_BUILD_DIR:-$root/build}" &&
    ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" --timeout 900 "${only[@]}")
echo "kiln: release tests: $((SECONDS - start)) s" >&2
if [ "${KILN_QUICK:-0}" != 1 ]; then
    "$root/scripts/sanitize.sh" "${KILN_FUZZ_SECONDS:-6}"
fi
