#!/usr/bin/env bash
# The one build of the README's commands (run.sh, test.sh, deb.sh): the
# default preset into build/, warnings as errors, through ccache when it is
# installed. All three configure and build the same way, so whichever runs
# second finds everything built and compiles nothing.
set -euo pipefail
cd "$(dirname "$0")/.."
export CCACHE_BASEDIR="$PWD"
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}"
# A clone in another folder (CI's) hits what a build here cached: paths
# relative to the checkout, and the build folder not hashed (it is in the
# debug info only).
export CCACHE_NOHASHDIR=true
cmake --preset default >/dev/null
cmake --build --preset default
