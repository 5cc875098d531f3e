#!/usr/bin/env bash
# Installs the system packages three-capture-lighting needs for its GPU tests, demo tests and
# benchmarks: Xvfb + Mesa for headless-gl (and the headers `gl` builds against), Debian's
# Chromium for puppeteer-core, and CGAL for the optional tetrahedralization peer benchmark.
# Idempotent: packages already present are not reinstalled, and nothing is downloaded when all are.
set -euo pipefail

PACKAGES=(
  xvfb xauth
  libgl1-mesa-dri libglapi-mesa libosmesa6
  libxi-dev libglu1-mesa-dev libglew-dev pkg-config
  build-essential python3
  chromium
  libcgal-dev
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all system packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
