#!/usr/bin/env bash
# Installs what luxbox needs on a fresh Debian machine with Node 20 + npm,
# skipping whatever is already present. Safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."

need_pkgs=()
command -v chromium >/dev/null 2>&1 || need_pkgs+=(chromium)
command -v xvfb-run >/dev/null 2>&1 || need_pkgs+=(xvfb xauth)
# The cross-engine suite (e2e-engines/, docs/browsers.md): Firefox ESR driven over WebDriver BiDi,
# and WebKitGTK's WebDriver (it pulls in libwebkit2gtk-4.1-0, whose MiniBrowser it drives).
command -v firefox-esr >/dev/null 2>&1 || need_pkgs+=(firefox-esr)
command -v WebKitWebDriver >/dev/null 2>&1 || need_pkgs+=(webkit2gtk-driver)
# headless-gl's native binding is compiled with node-gyp against these; the fonts are
# listed so screenshot goldens see the same glyphs on every machine. libvulkan1 +
# mesa-vulkan-drivers give ANGLE's Vulkan back end (no X display; docs/gpu-server.md).
for p in build-essential python3 python3-venv pkg-config libxi-dev libglu1-mesa-dev libglew-dev libgl1-mesa-dri libvulkan1 mesa-vulkan-drivers fonts-dejavu-core fonts-dejavu-extra fonts-liberation; do
  dpkg -s "$p" >/dev/null 2>&1 || need_pkgs+=("$p")
done
if [ ${#need_pkgs[@]} -gt 0 ]; then
  echo "setup: installing ${need_pkgs[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y "${need_pkgs[@]}"
fi

# npm ci only when the installed tree does not match the lock file.
if [ ! -f node_modules/.package-lock.json ] || ! cmp -s package-lock.json node_modules/.luxbox-lock-stamp; then
  npm ci
  cp package-lock.json node_modules/.luxbox-lock-stamp
fi
# headless-gl must have its native binding (npm >= 11 only runs approved install scripts).
if [ ! -f node_modules/gl/build/Release/webgl.node ]; then
  npm rebuild gl
fi
# Radiance (the PyPI package pyradiance ships its binaries) in a project-local virtual
# environment: the Radiance export test renders through it (docs/radiance.md). Optional: a
# machine without it skips that test and says so.
if [ ! -x .venv/bin/python ] || ! .venv/bin/python -c 'import pyradiance' >/dev/null 2>&1; then
  (python3 -m venv .venv && .venv/bin/pip install --quiet --disable-pip-version-check pyradiance==1.3.1) \
    || echo "setup: pyradiance could not be installed; the Radiance cross-check will be skipped"
fi
# ANGLE loads libvulkan.so.1 from its own folder: link the system loader there
# (npm ci's postinstall does the same; this covers an existing node_modules).
node scripts/linkVulkanLoader.mjs
