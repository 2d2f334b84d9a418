#!/usr/bin/env bash
# Installs what is missing, builds (packaging/build.sh: warnings as errors,
# the build run.sh makes, so after it nothing is compiled again) and runs
# every test through CTest under a virtual X display (README, second
# command; .ci/run). Ends with the build's and the tests' wall times.
set -euo pipefail
cd "$(dirname "$0")/.."
bash packaging/install-deps.sh
start=$SECONDS
bash packaging/build.sh
build=$((SECONDS - start))
# Rendering tests need an X display (Mesa); GUI tests set the offscreen platform themselves.
start=$SECONDS
status=0
xvfb-run -a -s "-screen 0 1600x1000x24" ctest --preset default -j2 || status=$?
tests=$((SECONDS - start))
printf 'test.sh: build %dm%02ds, tests %dm%02ds (wall time)\n' $((build / 60)) $((build % 60)) $((tests / 60)) $((tests % 60))
exit "$status"
