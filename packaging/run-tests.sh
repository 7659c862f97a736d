#!/usr/bin/env bash
# Installs what is needed, builds Photoflight and runs the whole test suite (core, UI offscreen,
# benchmark smoke run), then the fuzzers for a bounded time. This is the README's test command and what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash packaging/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPF_WERROR=ON
cmake --build build -j"$jobs"
cd build
QT_QPA_PLATFORM=offscreen ctest --output-on-failure -j"$jobs" --timeout 600
cd ..
# Fuzzers after the tests: 20 s per reader on the seed corpus (PF_FUZZ_SECONDS=0 skips them).
if [ "${PF_FUZZ_SECONDS:-20}" != "0" ]; then
  bash packaging/run-fuzzers.sh
fi
