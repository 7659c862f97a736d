#!/usr/bin/env bash
# Installs the Debian 12 packages Photoflight needs to build, test and run. Idempotent: when every
# package is already installed it does not touch apt at all.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  qtbase5-dev qtpositioning5-dev libqt5svg5-dev libqt5serialport5-dev
  libgdal-dev gdal-bin libproj-dev libgeos-dev libeigen3-dev
  # The .kmz (DJI WPML) writer.
  libminizip-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth
  # The user guide is rendered from docs/*.md at build time.
  pandoc
  # Release checks: fuzzers (clang's libFuzzer and sanitizer runtimes), desktop-file and AppStream
  # validators, dpkg-shlibdeps for the package's dependencies, and the X tools the kill-recovery
  # test uses to see and answer the application's recovery question on a virtual screen.
  clang libclang-rt-14-dev desktop-file-utils appstream dpkg-dev xdotool x11-utils
  # The manual pages come from the programs' --help (help2man); lintian checks the package.
  help2man lintian
  # The simulated MAVLink vehicle of the upload tests (tests/peers/, node-mavlink from npm).
  nodejs
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

# npm comes as its own Debian package, or inside a nodejs build that already bundles it.
if ! command -v npm >/dev/null 2>&1; then
  missing+=(npm)
fi

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
$SUDO apt-get update
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
