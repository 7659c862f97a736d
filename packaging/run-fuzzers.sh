#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, AddressSanitizer + UBSan, in build-fuzz/) and runs each one for
# a bounded time on its seed corpus in tests/data/fuzz/<target>/. Exits non-zero if any harness finds a
# crash, a leak or undefined behaviour; the input that did it is kept in build-fuzz/crashes/<target>/.
#
#   packaging/run-fuzzers.sh            # 20 s per harness (what CI runs)
#   PF_FUZZ_SECONDS=600 packaging/run-fuzzers.sh mission gpx   # longer, selected harnesses
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${PF_FUZZ_SECONDS:-20}"
build="${PF_FUZZ_BUILD_DIR:-build-fuzz}"
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=(mission catalog area_import qgc_plan qgc_wpl gpx waypoint_geojson litchi_csv mavlink wpml_kmz)
fi

CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPF_BUILD_FUZZERS=ON -DPF_BUILD_UI=OFF -DPF_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j"$(nproc 2>/dev/null || echo 2)" --target pf_fuzzers

failed=()
for t in "${targets[@]}"; do
  seeds="tests/data/fuzz/$t"
  work="$build/corpus/$t"     # new inputs found go here, never into the repository's seeds
  crashes="$build/crashes/$t"
  mkdir -p "$work" "$crashes"
  echo "== fuzz_$t: ${seconds}s on $seeds"
  # GDAL keeps per-process caches that are not leaks of ours; leak checking still covers each input.
  if ! ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}" UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
       "$build/tests/fuzz/fuzz_$t" "$work" "$seeds" -max_total_time="$seconds" -timeout=20 \
       -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$crashes/" 2>"$build/fuzz_$t.log"; then
    echo "!! fuzz_$t failed; last lines of $build/fuzz_$t.log:"
    tail -n 40 "$build/fuzz_$t.log"
    failed+=("$t")
  else
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$build/fuzz_$t.log" | tr '\n' ' '
    echo
  fi
done

if [ ${#failed[@]} -ne 0 ]; then
  echo "run-fuzzers: crashes in: ${failed[*]} (inputs in $build/crashes/)"
  exit 1
fi
echo "run-fuzzers: ${#targets[@]} harnesses ran ${seconds}s each without a crash"
