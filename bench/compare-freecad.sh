#!/usr/bin/env bash
# Issue 35 bench: FreeCAD CAM (Path workbench) beside Taiwa on the same pocket,
# bench/fine-pocket.taiwa (100 x 60 x 20, r 5.3, 10 mm flat end mill,
# step-over 2 %, step-down 0.2 mm), both timed in one run.
#   FreeCAD: bench/freecad_pocket.py under freecadcmd: a Pocket Shape
#            operation's path computation and its linuxcnc post, each timed
#            inside FreeCAD (time.perf_counter), plus freecadcmd's wall time.
#   Taiwa:   `taiwa export --no-cache` of the job, end to end (verification at
#            the default 0.05 mm, the tape, the sheet and its pictures), wall
#            clock.
# Run from anywhere:
#   bench/compare-freecad.sh [TAIWA_BINARY]     (or TAIWA=... bench/compare-freecad.sh)
# The binary defaults to build/app/taiwa under the project root. FreeCAD is a
# bench-only dependency: apt-get install freecad (Debian 12: 0.20.2).
# Exit: 0 done, 2 freecadcmd or the taiwa binary missing, 1 a run failed.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

taiwa=${1:-${TAIWA:-build/app/taiwa}}
job=bench/fine-pocket.taiwa

if ! command -v freecadcmd >/dev/null 2>&1; then
    echo "compare-freecad: freecadcmd not found; install it with: apt-get install freecad" >&2
    exit 2
fi
if [[ ! -x $taiwa ]]; then
    echo "compare-freecad: no taiwa binary at $taiwa (build it, or give its path as \$1 or TAIWA)" >&2
    exit 2
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

now() { date +%s.%N; }
calc() { awk "BEGIN { printf \"%.6f\", $1 }"; }

# FreeCAD: its banner and progress go to stdout too; keep only our line.
t0=$(now)
if ! freecadcmd bench/freecad_pocket.py >"$work/freecad.out" 2>"$work/freecad.err"; then
    echo "compare-freecad: freecadcmd failed:" >&2
    tail -20 "$work/freecad.err" "$work/freecad.out" >&2
    exit 1
fi
t1=$(now)
fc_line=$(grep -a '^freecad path_s=' "$work/freecad.out" || true)
if [[ -z $fc_line ]]; then
    echo "compare-freecad: the FreeCAD script printed no result:" >&2
    tail -20 "$work/freecad.err" "$work/freecad.out" >&2
    exit 1
fi
fc_wall=$(calc "$t1 - $t0")
field() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<<"$fc_line"; }
fc_path=$(field path_s)
fc_post=$(field post_s)
fc_moves=$(field moves)
fc_lines=$(field lines)
fc_arcs=$(field arcs)
fc_total=$(calc "$fc_path + $fc_post")
fc_info=$(grep -a '^freecad_pocket:' "$work/freecad.err" | tail -1 || true)

# Taiwa: the default export, verification included.
out="$work/taiwa"
mkdir "$out"
t0=$(now)
if ! env -u DISPLAY QT_QPA_PLATFORM=offscreen "$taiwa" export --no-cache "$job" \
        --out "$out" >"$work/taiwa.out" 2>"$work/taiwa.err"; then
    echo "compare-freecad: taiwa export failed:" >&2
    cat "$work/taiwa.err" >&2
    exit 1
fi
t1=$(now)
tw_s=$(calc "$t1 - $t0")
tw_lines=$(wc -l <"$out/fine-pocket.nc")
tw_moves=$(sed -n 's/.*"moves": *\([0-9]*\).*/\1/p' "$out/fine-pocket.steps.json" | head -1)

echo "$fc_line"
[[ -n $fc_info ]] && echo "  (${fc_info#freecad_pocket: })"
printf 'FreeCAD 0.20 Pocket Shape: path %.2f s + linuxcnc post %.2f s = %.2f s (freecadcmd wall %.2f s); %s moves, %s arcs, %s tape lines\n' \
    "$fc_path" "$fc_post" "$fc_total" "$fc_wall" "$fc_moves" "$fc_arcs" "$fc_lines"
printf 'Taiwa export (verification 0.05 mm, tape, sheet, pictures): %.2f s wall; %s moves, %s tape lines\n' \
    "$tw_s" "$tw_moves" "$tw_lines"
printf 'ratio: FreeCAD path+post / Taiwa export = %.2f (freecadcmd wall / Taiwa export = %.2f)\n' \
    "$(calc "$fc_total / $tw_s")" "$(calc "$fc_wall / $tw_s")"
echo "load: $(uptime | sed 's/.*load average/load average/')"
