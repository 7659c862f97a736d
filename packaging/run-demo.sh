#!/usr/bin/env bash
# Installs what is needed, builds Photoflight and opens the bundled demo mission: in the GUI when a
# display is available, otherwise with the headless planner, printing a summary of the plan.
set -euo pipefail
cd "$(dirname "$0")/.."
bash packaging/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build -j"$jobs" --target photoflight-cli $( [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && echo photoflight )
demo=resources/demo/demo_mission.json
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec ./build/app/photoflight "$demo"
fi
echo "No display found: planning the demo mission with photoflight-cli."
./build/app/photoflight-cli validate "$demo"
./build/app/photoflight-cli plan "$demo" --out out/demo
echo "Plan written to out/demo/ (plan.geojson, metrics.json)."
