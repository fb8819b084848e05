#!/usr/bin/env bash
# Builds the libFuzzer targets (preset `fuzz`, clang with ASan and UBSan) and runs each for a
# bounded time on a scratch copy of its seed corpus (fuzz/corpus/<name>; the committed corpus
# is never modified). Any crash, sanitizer report or escaped exception fails the run, and the
# crashing input is kept in build/fuzz/findings/<name>/ for a regression test.
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET]   (default 10: 60 s for the six targets)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-10}"
targets=(at2 cosmos csv spectrum_csv case cli_values)
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz --target "${targets[@]/#/fuzz_}" >/dev/null
status=0
failures=0
for name in "${targets[@]}"; do
  work="build/fuzz/work/${name}"
  findings="build/fuzz/findings/${name}"
  rm -rf "${work}"
  mkdir -p "${work}" "${findings}"
  cp -r "fuzz/corpus/${name}/." "${work}/"
  log="build/fuzz/${name}.log"
  if "build/fuzz/fuzz/fuzz_${name}" "${work}" -max_total_time="${seconds}" -max_len=16384 \
      -timeout=10 -rss_limit_mb=2048 -artifact_prefix="${findings}/" -print_final_stats=1 \
      >"${log}" 2>&1; then
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "${log}" | grep -o '[0-9]*$' || echo "?")
    echo "fuzz ${name}: ${runs} executions in ${seconds} s, no crash"
  else
    echo "fuzz ${name}: FAILED (see ${log}; input kept in ${findings}/)"
    tail -30 "${log}"
    status=1
    failures=$((failures + 1))
  fi
done
echo "fuzz: $(( ${#targets[@]} - failures )) passed, ${failures} failed"
exit "${status}"
