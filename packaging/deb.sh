#!/usr/bin/env bash
# Installs what is missing, builds Taiwa (packaging/build.sh, the build of
# run.sh and test.sh) and makes the Debian package with CPack:
# build/taiwa_VERSION_ARCH.deb (README, third command).
set -euo pipefail
cd "$(dirname "$0")/.."
bash packaging/install-deps.sh
bash packaging/build.sh
cpack -G DEB --config build/CPackConfig.cmake -B build
ls build/taiwa_*.deb
