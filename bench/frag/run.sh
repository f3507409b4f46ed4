#!/usr/bin/env bash
# A folder of Fragmentarium / FragM frags through `fraktal import`, proved against each frag's own
# raytracer: every frag outside Include/ folders is run by bench_frag_host (its raytracer GLSL as
# written, one sample per pixel: the hit mask and DE evaluations per pixel), imported strictly
# (no --lenient: a frag that uses what fraktal cannot express is refused, by reason) and, where it
# imports, rendered by fraktal at the same size and camera; the silhouettes are scored by the
# intersection over union of the two hit masks (bench/import/silhouette_iou.cpp).
# Usage: bench/frag/run.sh BUILD FOLDER [OUT] [SIZE]   (OUT default bench/frag/out/NAME, SIZE 160x120)
# The frags' includes resolve next to each frag, then in FOLDER/Include and in FRAG_INCLUDE (a
# colon-separated list: FragM's examples' Include/ for a community repository written against
# it; folders whose paths hold no spaces). JOBS: frags run at once (default 2). Writes OUT/results.tsv (one row per frag),
# OUT/summary.md and OUT/worst.png (the worst matches: fraktal's mask, the frag's own, both
# overlaid; yellow both, red fraktal only, green the frag only).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(realpath "$1")
folder=$(realpath "$2")
size=${4:-160x120}
out=$(realpath -m "${3:-$root/bench/frag/out/$(basename "$folder")}")
# NO_BUILD=1: BUILD already holds the three programs (a copy of an earlier build, for a before/after).
[ -n "${NO_BUILD:-}" ] || cmake --build "$build" --target fraktal bench_frag_host bench_de_count > /dev/null
export fraktal="$build/app/fraktal" host="$build/bench/bench_frag_host" deCount="$build/bench/bench_de_count"
export size out folder root
mkdir -p "$out/img" "$out/rows"
rm -f "$out"/rows/*
tmp=$(mktemp -d)
export tmp
trap 'rm -rf "$tmp"' EXIT
g++ -O2 -std=c++20 -I/usr/include/stb "$root/bench/import/silhouette_iou.cpp" \
  $(pkg-config --cflags --libs OpenEXR) -lstb -o "$tmp/iou"
includes=()
[ -d "$folder/Include" ] && includes+=(--include-dir "$folder/Include")
IFS=: read -r -a extra <<< "${FRAG_INCLUDE:-}"
for d in "${extra[@]}"; do [ -n "$d" ] && includes+=(--include-dir "$(realpath "$d")"); done
export INCLUDES="${includes[*]}"

one() {  # FILE: one row of results.tsv into $out/rows
  local file=$1 rel key work hostLine kind hostStatus hostPx hostDe status reason iou fpx took fde
  rel=${file#"$folder"/}
  key=$(printf '%s' "${rel%.frag}" | tr -c 'A-Za-z0-9_.-' '_')
  work="$tmp/$key"
  mkdir -p "$work"
  # shellcheck disable=SC2086  # INCLUDES is a list of words
  # AntiAliasScale 0: FragM jitters each frame's sample over about a pixel for its progressive
  # anti-aliasing; at one sample per pixel both programs sample the pixel's centre.
  hostLine=$(timeout 180 "$host" "$file" $INCLUDES --size "$size" --set AntiAliasScale=0 \
    -o "$out/img/host_$key.png" 2> "$work/host.err" || true)
  [ -z "$hostLine" ] && hostLine="? fail $( (tail -1 "$work/host.err" || echo "timed out") | tr '\t' ' ' | cut -c1-160)"
  [ -z "${hostLine#* fail }" ] && hostLine="${hostLine}timed out or crashed"
  kind=${hostLine%% *}
  hostStatus=$(echo "$hostLine" | cut -d' ' -f2)
  hostPx="" hostDe=""
  if [ "$hostStatus" = ok ]; then
    hostPx=$(echo "$hostLine" | cut -d' ' -f3)
    hostDe=$(echo "$hostLine" | cut -d' ' -f4)
  fi
  status="" reason="" iou="" fpx="" took="" fde=""
  local start
  start=$(date +%s.%N)
  # shellcheck disable=SC2086
  if timeout 600 "$fraktal" import "$file" $INCLUDES -o "$work/import.json" -q > "$work/import.log" 2>&1; then
    took=$(echo "$(date +%s.%N) - $start" | bc -l | xargs printf %.1f)
    python3 "$root/bench/frag/at_size.py" "$work/import.json" "$size"  # FragM's hit cone (at_size.py says why)
    if timeout 300 "$fraktal" render "$work/import.json" --size "$size" --spp 1 -o "$out/img/$key.exr" -q \
      > "$work/render.log" 2>&1; then
      fde=$(timeout 300 "$deCount" "$work/import.json" "$size" 1 2> /dev/null | awk '{ print $1 }' || true)
      if [ "$hostStatus" = ok ]; then
        read -r iou fpx _ < <("$tmp/iou" "$out/img/$key.exr" "$out/img/host_$key.png")
        status=imported
        awk -v i="$iou" 'BEGIN { exit !(i >= 0.9) }' && status=matching
      else
        read -r _ fpx _ < <("$tmp/iou" "$out/img/$key.exr" "$out/img/$key.exr")
        status=imported-no-reference
        reason=""  # the host column says why there is no reference
      fi
    else
      status=render-failed
      reason=$(tail -1 "$work/render.log" | tr '\t' ' ' | cut -c1-160)
    fi
  else
    # The first thing the import named: "  NAME: reason" lines follow a "refused" line.
    reason=$( (grep -m1 '^  ' "$work/import.log" || true) | sed -E 's/^ +//; s|^/[^:]*\.frag(:[0-9]+)?: ||' |
      tr '\t' ' ' | cut -c1-160)
    status=refused
    if [ -z "$reason" ]; then
      status=error
      # A GLSL error names its first line (the log's last lines are often warnings).
      reason=$( (grep -m1 -E 'GLSL line [0-9]+: error' "$work/import.log" || tail -1 "$work/import.log") |
        sed -E 's/^fraktal: error: //; s|^/[^:]*\.frag(:[0-9]+)?: ||; s/^estimator .*(GLSL line)/\1/' |
        tr '\t' ' ' | cut -c1-160)
    fi
  fi
  local hostColumn=ok
  [ "$hostStatus" = ok ] || hostColumn="fail: ${hostLine#* fail }"
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$rel" "$kind" "$status" "$reason" "$iou" "$fpx" \
    "$hostPx" "$hostDe" "$fde" "$took" "$(printf '%s' "$hostColumn" | tr '\t' ' ' | cut -c1-200)" > "$out/rows/$key.tsv"
  rm -rf "$work"
}
export -f one

find "$folder" -name '*.frag' -not -path '*/Include/*' -print0 | sort -z |
  xargs -0 -P "${JOBS:-2}" -I{} bash -c 'one "$1"' _ {}
{
  printf 'file\tkind\tstatus\treason\tiou\tfraktal_px\thost_px\thost_de_per_px\tfraktal_de_per_px\timport_s\thost\n'
  cat "$out"/rows/*.tsv | sort
} > "$out/results.tsv"
python3 "$root/bench/frag/summarize.py" --pixels $(( ${size%x*} * ${size#*x} )) "$out/results.tsv" > "$out/summary.md"
# The contact sheet: the 12 worst matches.
mapfile -t worst < <(awk -F'\t' 'NR > 1 && $5 != "" { print $5 "\t" $1 }' "$out/results.tsv" | sort -g | head -12 |
  cut -f2 | sed 's/\.frag$//' | tr -c 'A-Za-z0-9_.\n-' '_')
args=()
for k in "${worst[@]}"; do args+=("$out/img/$k.exr" "$out/img/host_$k.png"); done
[ ${#args[@]} -gt 0 ] && "$tmp/iou" --sheet "$out/worst.png" "${args[@]}"
cat "$out/summary.md"
