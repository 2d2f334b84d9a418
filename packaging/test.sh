#!/usr/bin/env bash
# Installs what is missing, builds with warnings as errors and runs every test
# through CTest under a virtual X display (README, second command; .ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
bash packaging/install-deps.sh
export CCACHE_BASEDIR="$PWD"
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}"
# A clone in another folder (CI's) hits what a build here cached: paths
# relative to the checkout, and the build folder not hashed (it is in the
# debug info only).
export CCACHE_NOHASHDIR=true
cmake --preset ci >/dev/null
cmake --build --preset ci
# Rendering tests need an X display (Mesa); GUI tests set the offscreen platform themselves.
xvfb-run -a -s "-screen 0 1600x1000x24" ctest --preset ci -j2
