#!/usr/bin/env bash
# Builds the Debian package and checks it the way a user would meet it: installs it with apt (which
# pulls its dependencies), runs the INSTALLED programs on the INSTALLED demo mission, then removes the
# package again so the machine stays as it was. Needs root (or sudo) for apt. Not part of CI (it
# installs into /usr); run it by hand before a release:
#
#   packaging/check-deb.sh [BUILD_DIR]        # default build-deb
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build-deb}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

if dpkg-query -W -f='${Status}' photoflight 2>/dev/null | grep -q "install ok installed"; then
  echo "check-deb: photoflight is already installed; remove it first (apt-get remove photoflight)" >&2
  exit 2
fi

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_INSTALL_PREFIX=/usr
cmake --build "$build" -j"$(nproc 2>/dev/null || echo 2)" --target photoflight photoflight-cli pf_demo_map pf_demo_dem pf_icons pf_man_pages pf_changelog
(cd "$build" && rm -f photoflight_*.deb && cpack -G DEB)
deb=$(ls "$build"/photoflight_*.deb | head -n 1)
echo "check-deb: built $deb"
dpkg-deb --info "$deb" | sed -n '/Package:/,$p'
dpkg-deb --contents "$deb" | awk '{print $6}'
# Debian's own package checker: no error and no warning (the information tags are listed, not fatal).
if command -v lintian >/dev/null; then
  lintian --fail-on error,warning --info "$deb" || { echo "check-deb: FAILED: lintian" >&2; exit 1; }
  echo "check-deb: lintian reports no error and no warning"
else
  echo "check-deb: FAILED: lintian is not installed (packaging/install-deps.sh installs it)" >&2
  exit 1
fi

cleanup() { DEBIAN_FRONTEND=noninteractive $SUDO apt-get remove -y photoflight >/dev/null || true; }
trap cleanup EXIT
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y "$(realpath "$deb")" # apt needs a path, absolute or ./

out=$(mktemp -d)
fail() { echo "check-deb: FAILED: $*" >&2; exit 1; }
dpkg-deb -f "$deb" Depends | grep -q libminizip1 || fail "the package does not depend on libminizip1 (the .kmz writer)"
cd /   # nothing may come from the source tree
for f in /usr/bin/photoflight /usr/bin/photoflight-cli \
         /usr/share/photoflight/catalog.json /usr/share/photoflight/demo/demo_mission.json \
         /usr/share/photoflight/maps/demo_map.tif \
         /usr/share/applications/io.photoflight.Photoflight.desktop \
         /usr/share/metainfo/io.photoflight.Photoflight.metainfo.xml \
         /usr/share/icons/hicolor/scalable/apps/io.photoflight.Photoflight.svg \
         /usr/share/icons/hicolor/256x256/apps/io.photoflight.Photoflight.png \
         /usr/share/icons/hicolor/16x16/apps/io.photoflight.Photoflight.png \
         /usr/share/man/man1/photoflight.1.gz /usr/share/man/man1/photoflight-cli.1.gz \
         /usr/share/doc/photoflight/copyright /usr/share/doc/photoflight/changelog.gz; do
  [ -e "$f" ] || fail "$f is not installed"
done
version=$(sed -n 's/^project(Photoflight VERSION \([0-9.]*\).*/\1/p' "$OLDPWD/CMakeLists.txt")
photoflight-cli --version | grep -q "$version" || fail "photoflight-cli --version does not say $version"
photoflight --version | grep -q "$version" || fail "photoflight --version does not say $version"
man -w photoflight-cli >/dev/null 2>&1 || fail "man photoflight-cli finds no page"
photoflight-cli catalog >/dev/null || fail "photoflight-cli catalog cannot read the installed catalog"
photoflight-cli validate /usr/share/photoflight/demo/demo_mission.json >/dev/null || fail "validate"
photoflight-cli plan /usr/share/photoflight/demo/demo_mission.json --out "$out" || fail "plan"
[ -s "$out/plan.geojson" ] && [ -s "$out/metrics.json" ] || fail "plan wrote no plan.geojson/metrics.json"
if command -v desktop-file-validate >/dev/null; then
  desktop-file-validate /usr/share/applications/io.photoflight.Photoflight.desktop || fail "desktop file"
fi
if command -v appstreamcli >/dev/null; then
  appstreamcli validate --no-net /usr/share/metainfo/io.photoflight.Photoflight.metainfo.xml || fail "metainfo"
fi
QT_QPA_PLATFORM=offscreen photoflight --screenshot "$out/screenshot.png" >/dev/null \
  || fail "photoflight --screenshot on the installed demo mission"
rm -rf "$out"
echo "check-deb: OK: $deb installs, and the installed photoflight-cli plans the installed demo mission"
