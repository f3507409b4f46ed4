#!/usr/bin/env bash
# Mandelbulber2's own example library through `fraktal import`, proved against Mandelbulber2:
# every example (examples/, its five artist collections), the toolbar's one-click presets and the
# settings behind the formula thumbnails (formula/img/, one file a formula) is
# imported (strictly: a file that uses what fraktal cannot express is refused, by reason), and
# every imported one is rendered by both programs at the same small size; the silhouettes are
# scored by the intersection over union of the two hit masks (fraktal's alpha, Mandelbulber2's
# 16-bit PNG alpha; legacy-coordinate files are flipped by the imported camera).
# Usage: bench/import/run.sh [FRAKTAL] [SIZE] [OUT]   (defaults: build/app/fraktal, 160x120,
# bench/import/out). Writes OUT/results.tsv (one row per file), OUT/summary.md (the tables of
# bench/import/README.md) and OUT/worst.png (a contact sheet of the worst matches: fraktal's
# mask, Mandelbulber2's, both overlaid; yellow both, red fraktal only, green Mandelbulber2 only).
# FRACT_LIST: a file of settings files' paths (one a line) to run instead of the whole library.
# PEER_CACHE: a folder of mandelbulber2's masks, keyed by the settings file's content and the size
# (mandelbulber2's image depends on them alone): a mask found there is reused, one rendered is added.
# fraktal's rows are always new.
# Needs mandelbulber2 (scripts/install-deps.sh installs it).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
fraktal=$(realpath "${1:-$root/build/app/fraktal}")
size=${2:-160x120}
out=$(realpath -m "${3:-$root/bench/import/out}")
share=/usr/share/mandelbulber2
mkdir -p "$out/img"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
g++ -O2 -std=c++20 -I/usr/include/stb "$root/bench/import/silhouette_iou.cpp" \
  $(pkg-config --cflags --libs OpenEXR) -lstb -o "$tmp/iou"

collection() {  # the collection's short name, as the reference's T8 writes it
  case "$1" in
    "$share/toolbar"*) echo toolbar ;;
    "$share/formula"*) echo formula ;;
    *Krzysztof*) echo KM ;; *Graeme*) echo GM ;; *Robert*) echo RP ;; *Sebastian*) echo SJ ;; *Daniel*) echo DL ;;
    *) echo root ;;
  esac
}
# mandelbulber2 renders the file as it is, less what adds alpha where there is no surface or blurs
# it: depth of field (its Monte Carlo DOF takes minutes a file; fraktal's fast still has none), fog,
# iteration fog, glow, orbit-trap ("fake") lights, visible light sources, transparent surfaces and
# ray-traced reflections (a mirror takes the alpha of what it reflects: the sky's 0).
# The silhouette is the shape's alone. The same list is in tests/import_fract_test.cpp.
peerKeys="DOF_enabled false|DOF_monte_carlo false|volumetric_fog_enabled false|iteration_fog_enable false|basic_fog_enabled false|glow_enabled false|fake_lights_enabled false|main_light_visibility 0|aux_light_visibility 0|main_light_volumetric_enabled false|mat1_transparency_of_surface 0|raytraced_reflections false"
peerSettings() {  # FILE OUT
  local deletes="" appends=""
  IFS='|' read -r -a pairs <<< "$peerKeys"
  for kv in "${pairs[@]}"; do deletes+="/^${kv%% *} /d;"; appends+="${kv};\\n"; done
  sed "$deletes" "$1" | sed "/^\[main_parameters\]/a ${appends%\\n}" > "$2"
}
# mandelbulber2's mask of FILE as KEY: from PEER_CACHE when it holds one for the file's content at
# this size, else rendered (and added there).
peerMask() {  # FILE KEY
  local cached=
  if [ -n "${PEER_CACHE:-}" ]; then
    mkdir -p "$PEER_CACHE"
    cached="$PEER_CACHE/$(sha256sum "$1" | cut -c1-32)-$size.png"
    if [ -f "$cached" ]; then
      cp "$cached" "$out/img/mb_$2.png"
      return
    fi
  fi
  peerSettings "$1" "$tmp/peer.fract" &&
    HOME="$tmp" QT_QPA_PLATFORM=offscreen timeout 300 mandelbulber2 -n -f png16alpha -r "$size" \
      -o "$out/img/mb_$2" "$tmp/peer.fract" > "$tmp/mb.log" 2>&1 || return
  if [ -n "$cached" ] && [ -f "$out/img/mb_$2.png" ]; then cp "$out/img/mb_$2.png" "$cached.part" && mv "$cached.part" "$cached"; fi
}
expressible() { grep -qxF "$1 / $2" "$root/bench/import/expressible.txt"; }

# missing_formula: whether the import named a formula that has no fraktal blocks (among all it named).
printf 'collection\tfile\texpressible\tstatus\treason\tiou\tfraktal_px\tmb2_px\timport_s\tmissing_formula\n' > "$out/results.tsv"
n=0
while IFS= read -r -d "" -u 3 file; do
  n=$((n + 1))
  c=$(collection "$file")
  name=$(basename "$file" .fract)
  key=$(printf '%s' "$c-$name" | tr -c 'A-Za-z0-9_.-' '_')
  exp=no
  expressible "$c" "$name" && exp=yes
  start=$(date +%s.%N)
  if "$fraktal" import "$file" -o "$tmp/$key.json" -q > "$tmp/import.log" 2>&1; then
    took=$(echo "$(date +%s.%N) - $start" | bc -l | xargs printf %.2f)
    if timeout 300 "$fraktal" render "$tmp/$key.json" --size "$size" --spp 1 -o "$out/img/$key.exr" -q \
        > "$tmp/render.log" 2>&1 &&
      peerMask "$file" "$key" && [ -f "$out/img/mb_$key.png" ]; then
      read -r iou fpx mpx < <("$tmp/iou" "$out/img/$key.exr" "$out/img/mb_$key.png")
      status=imported
      awk -v i="$iou" 'BEGIN { exit !(i >= 0.9) }' && status=matching
      printf '%s\t%s\t%s\t%s\t\t%s\t%s\t%s\t%s\tno\n' "$c" "$name" "$exp" "$status" "$iou" "$fpx" "$mpx" "$took" >> "$out/results.tsv"
    else
      printf '%s\t%s\t%s\trender-failed\t%s\t\t\t\t%s\tno\n' "$c" "$name" "$exp" \
        "$(tail -1 "$tmp/render.log" "$tmp/mb.log" 2>/dev/null | tr '\t\n' '  ' | cut -c1-200)" "$took" >> "$out/results.tsv"
    fi
  else
    # The first thing the import named, reduced to its reason: "the formula X ...", "phase offsets ...".
    reason=$( (grep -m1 '^  ' "$tmp/import.log" || true) | sed -E 's/^  [^:]*\): //; s/^  [a-z]+: //' |
      sed -E 's/^the formula ([a-z0-9_]+) \(id [0-9]+\) has no fraktal blocks yet/formula \1 (no blocks yet)/;
              s/^[A-Za-z0-9_.\/]+ [^:]*: //' | cut -c1-120)
    status=refused
    if [ -z "$reason" ]; then  # not refused for what it uses: an error reading it
      status=error
      reason=$(tail -1 "$tmp/import.log" | sed 's/^fraktal: error: //' | cut -c1-160)
    fi
    missing=no
    grep -q "has no fraktal blocks yet" "$tmp/import.log" && missing=yes
    printf '%s\t%s\t%s\t%s\t%s\t\t\t\t\t%s\n' "$c" "$name" "$exp" "$status" "$reason" "$missing" >> "$out/results.tsv"
  fi
  [ $((n % 25)) -eq 0 ] && echo "$n files" >&2
done 3< <(if [ -n "${FRACT_LIST:-}" ]; then tr '\n' '\0' < "$FRACT_LIST"; else
  find "$share/toolbar" "$share/examples" "$share/formula/img" -name "*.fract" -print0 | sort -z; fi)

{
  # What the table is: one run, its date, the commit of the fraktal that ran (its source tree, with
  # a mark when that tree had changes not committed) and the files it covered.
  commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)
  git -C "$root" diff --quiet HEAD 2>/dev/null || commit+=" (with changes not committed)"
  echo "Run $(date -u +%Y-%m-%d) at $commit, $size, $(( $(wc -l < "$out/results.tsv") - 1 )) files$( [ -n "${FRACT_LIST:-}" ] && echo " (FRACT_LIST)" || echo " (the whole library)")."
  echo
  python3 "$root/bench/import/summarize.py" "$out/results.tsv" "$(( ${size%x*} * ${size#*x} ))"
} > "$out/summary.md"
# The contact sheet: the 12 worst imported matches.
mapfile -t worst < <(awk -F'\t' 'NR > 1 && $6 != "" { print $6 "\t" $1 "-" $2 }' "$out/results.tsv" | sort -g | head -12 |
  cut -f2 | tr -c 'A-Za-z0-9_.\n-' '_')
args=()
for k in "${worst[@]}"; do args+=("$out/img/$k.exr" "$out/img/mb_$k.png"); done
[ ${#args[@]} -gt 0 ] && "$tmp/iou" --sheet "$out/worst.png" "${args[@]}"
cat "$out/summary.md"
