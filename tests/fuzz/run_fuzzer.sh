#!/usr/bin/env bash
# Runs the scene fuzzer for a bounded time from the committed seed corpus (copied, so the run adds
# nothing to the repository). A crash, hang or escaped exception fails the run and leaves the
# input in ARTIFACTS; commit it to tests/fuzz/regressions/ once fixed.
#   usage: bash tests/fuzz/run_fuzzer.sh FUZZ_BINARY SECONDS [ARTIFACTS]
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: bash tests/fuzz/run_fuzzer.sh FUZZ_BINARY SECONDS [ARTIFACTS]" >&2; exit 2; }
binary=$1 seconds=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
artifacts=${3:-$(dirname "$binary")/fuzz-artifacts}
mkdir -p "$artifacts"
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
cp "$here"/corpus/* "$here"/regressions/*.toml "$corpus"/ 2>/dev/null || true
echo "fuzz: $binary for ${seconds} s from $(ls "$corpus" | wc -l) seeds" >&2
if ! ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0} "$binary" "$corpus" -max_total_time="$seconds" -timeout=10 \
     -rss_limit_mb=4096 -artifact_prefix="$artifacts/" -print_final_stats=1 2> "$artifacts/fuzz.log"; then
  tail -40 "$artifacts/fuzz.log" >&2
  echo "fuzz: FAILED; the input is in $artifacts/ (crash-*, timeout-* or oom-*)" >&2
  exit 1
fi
grep -E "stat::(number_of_executed_units|new_units_added)" "$artifacts/fuzz.log" >&2 || true
echo "fuzz: no crash in ${seconds} s" >&2
