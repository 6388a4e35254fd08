#!/usr/bin/env bash
# kiln benchmarks in one command (bench/README.md): builds kiln, kiln_microbench and
# kiln_benchtool in Release (installing packages first if needed, via scripts/bootstrap.sh),
# runs the microbenchmarks, then the convergence benchmark.
#   bench/run.sh [--micro-only | --convergence-only] [convergence.py options...]
# Results go to bench/results/; cached references and renders to bench/out/.
# KILN_BUILD_DIR picks the build directory (default: build/).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${KILN_BUILD_DIR:-$root/build}"
export KILN_BUILD_DIR="$build"

micro=1 convergence=1
case "${1:-}" in
    --micro-only) micro=1 convergence=0; shift ;;
    --convergence-only) micro=0 convergence=1; shift ;;
esac

"$root/scripts/bootstrap.sh" --target kiln kiln_microbench kiln_benchtool
mkdir -p "$root/bench/results" "$root/bench/out"

if [ "$micro" = 1 ]; then
    echo "bench: microbenchmarks -> bench/results/microbench.{txt,json}" >&2
    "$build/bench/kiln_microbench" --benchmark_out="$root/bench/results/microbench.json" \
        --benchmark_out_format=json --benchmark_counters_tabular=true \
        | tee "$root/bench/results/microbench.txt"
fi
if [ "$convergence" = 1 ]; then
    echo "bench: convergence -> bench/results/convergence.{csv,png}" >&2
    python3 "$root/bench/convergence.py" "$@"
fi
