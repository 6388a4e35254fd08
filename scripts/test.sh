#!/usr/bin/env bash
# Builds kiln and its tests (installing missing packages first) and runs the whole suite; then
# the sanitizer stage (scripts/sanitize.sh: a clang build with AddressSanitizer and
# UndefinedBehaviorSanitizer, each libFuzzer target fuzzed for KILN_FUZZ_SECONDS, default 6,
# and the suite again under the sanitizers but for the Monte Carlo checks labelled
# `statistical`). KILN_QUICK=1 skips that stage.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# Each stage prints how long it took (seconds), so that a CI log tells where its time went
"$root/scripts/bootstrap.sh"
echo "kiln: set-up and release build: ${SECONDS} s" >&2
start=$SECONDS
(cd "${KILN_BUILD_DIR:-$root/build}" &&
    ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" --timeout 900)
echo "kiln: release tests: $((SECONDS - start)) s" >&2
if [ "${KILN_QUICK:-0}" != 1 ]; then
    "$root/scripts/sanitize.sh" "${KILN_FUZZ_SECONDS:-6}"
fi
