#!/usr/bin/env bash
# Installs what is missing, builds Taiwa (packaging/build.sh, the build
# test.sh uses too), exports the bundled sample job and opens the station
# window on it (README, first command).
set -euo pipefail
cd "$(dirname "$0")/.."
bash packaging/install-deps.sh
bash packaging/build.sh
sample=resources/samples/plate.taiwa
./build/app/taiwa export "$sample" --out out/plate
if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
  exec ./build/app/taiwa "$sample"
else
  echo "run.sh: no display; open the station with: xvfb-run -a ./build/app/taiwa $sample (or on a desktop: ./build/app/taiwa $sample)"
fi
