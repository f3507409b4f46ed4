#!/usr/bin/env bash
# Speed on imported scenes: fraktal's still of each imported Mandelbulber2 example against
# mandelbulber2's own, at equal coverage error (the method of bench/stills/equal_quality.sh: each
# program scored by the RMSE of its coverage against its own converged coverage, and for each
# mandelbulber2 setting the fastest fraktal setting with at most its error).
# Usage: bench/import/speed.sh RESULTS.tsv [COUNT] [WxH] [FRAKTAL]   (defaults: 12 scenes, 1280x720,
# build/app/fraktal). RESULTS.tsv is bench/import/run.sh's; the scenes are COUNT of its matching
# imports, spread evenly over its list: those whose object does not fill the view first (an edge to
# measure), then views from inside. Environment: FRAKTAL_SPP (default "1 2 4"), PEER_AA (default "1 2"), TRUTH_AA (default 3:
# both truths take 9 samples per pixel), DE_COUNT (bench_de_count: with it each row gains the
# breakdown of what each program computes, below), PEER_TIMEOUT (seconds, default none: a scene
# whose mandelbulber2 truth runs longer is listed as not timed, and the next one is taken), ROWS
# (default all: stop once this many scenes have a timed row; with SCENES, candidates in order).
# Each render is timed by the wall clock and by its CPU time (user + system, threads included): both
# programs render on every core, and the CPU time stays comparable when something else runs beside
# the bench. The last lines give the distribution of the CPU-time ratio.
set -euo pipefail
results=$1; count=${2:-12}; size=${3:-1280x720}
root=$(cd "$(dirname "$0")/../.." && pwd)
fraktal=$(realpath "${4:-$root/build/app/fraktal}")
read -r -a fraktalSpp <<< "${FRAKTAL_SPP:-1 2 4}"
read -r -a peerAa <<< "${PEER_AA:-1 2}"
truthAa=${TRUTH_AA:-3}
share=/usr/share/mandelbulber2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
g++ -O2 -std=c++20 -I"$root" -I/usr/include/stb "$root/bench/stills/coverage_error.cpp" \
  $(pkg-config --cflags --libs OpenEXR) -lstb -o "$tmp/coverage_error"
# Runs a command, its output kept in $tmp/timed.log; sets wall and cpu (seconds: elapsed, and
# user + system).
timed() {
  local report user system
  report=$( { TIMEFORMAT='%R %U %S'; time "$@" > "$tmp/timed.log" 2>&1 < /dev/null; } 2>&1 )
  read -r wall user system <<< "$report"
  cpu=$(awk -v u="$user" -v s="$system" 'BEGIN { printf "%.2f", u + s }')
}
pixels=$(( 160 * 120 ))
# collection / file of the matching imports: the partial views first, then the rest evenly spaced.
mapfile -t partial < <(awk -F'\t' -v full=$pixels '$4 == "matching" && $8 != full { print $1 "\t" $2 }' "$results")
mapfile -t rest < <(awk -F'\t' -v full=$pixels '$4 == "matching" && $8 == full { print $1 "\t" $2 }' "$results")
scenes=()
# SCENES: "collection<TAB>name" lines to time instead of the choice below.
if [[ -n ${SCENES:-} ]]; then mapfile -t scenes <<< "$SCENES"; count=0; partial=(); rest=(); fi
for ((i = 0; i < count && i < ${#partial[@]}; i++)); do scenes+=("${partial[$(( i * ${#partial[@]} / count ))]}"); done
want=$(( count - ${#scenes[@]} ))
if (( want > 0 && ${#rest[@]} > 0 )); then
  for ((i = 0; i < want && i < ${#rest[@]}; i++)); do scenes+=("${rest[$(( i * ${#rest[@]} / want ))]}"); done
fi
fractOf() {  # the settings file of collection $1, name $2
  case "$1" in
    toolbar) echo "$share/toolbar/$2.fract" ;;
    formula) echo "$share/formula/img/$2.fract" ;;
    root) echo "$share/examples/$2.fract" ;;
    *) find "$share/examples" -path "*$(case "$1" in KM) echo Krzysztof ;; GM) echo Graeme ;; RP) echo Robert ;;
         SJ) echo Sebastian ;; DL) echo Daniel ;; esac)*" -name "$2.fract" | head -1 ;;
  esac
}
# A copy of the settings with the given main parameters set (each removed first, then appended).
withSettings() {  # FILE OUT KEY=VALUE...
  local file=$1 out=$2; shift 2
  local keys=() lines=""
  for kv in "$@"; do keys+=("${kv%%=*}"); lines+="${kv%%=*} ${kv#*=};\n"; done
  local pattern; pattern=$(printf '^%s \\|' "${keys[@]}"); pattern=${pattern%\\|}
  sed "/$pattern/d" "$file" | sed "/^\[main_parameters\]/a $lines" > "$out"
}
deCount=${DE_COUNT:-}
# The breakdown (with DE_COUNT): what each program computes for the scene. fraktal's from the
# imported preset (iterations, estimator, step factor, hit threshold in pixel footprints, AO, shadow
# and reflection march steps) and bench_de_count at the row's setting (DE evaluations per pixel,
# march steps per camera ray, the evaluations of shading); mandelbulber2's from the settings file
# (its defaults where the file is silent: core/import/mb2_defaults.inc) and its own statistics of
# the timed render (`--stats`: fractal iterations per pixel, over every DE call it made).
mb2Value() {  # FILE KEY: the file's value of KEY, else Mandelbulber2's default
  local v
  v=$(grep -m1 "^$2 " "$1" | sed -E "s/^$2 (.*);\r?$/\1/" || true)
  [[ -n $v ]] || v=$(grep -m1 "{\"$2\", " "$root/core/import/mb2_defaults.inc" | sed -E 's/.*, "(.*)"\},?$/\1/' || true)
  echo "${v:-?}"
}
fraktalBreakdown() {  # PRESET.json
  python3 - "$1" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))
f, r, s = p["formula"], p.get("render", {}), p.get("shading", {})
est = f["nodes"][-1].get("block", "?") if f.get("nodes") else "?"
print(f"N {f.get('iterations', '?')}, {est}, factor {f.get('deFactor', 1):.3g}, detail {r.get('detail', 0.5):.3g} px, "
      f"AO {s.get('aoSteps', 5)}, shadow {s.get('shadowSteps', 96)}, reflection {s.get('reflectionSteps', 96) if s.get('reflection', 0) > 0 else 0}")
PY
}
mb2Breakdown() {  # FILE.fract
  local f=$1 ao refl
  ao=$( [[ $(mb2Value "$f" ambient_occlusion_enabled) == true || $(mb2Value "$f" ambient_occlusion_enabled) == 1 ]] &&
    case $(mb2Value "$f" ambient_occlusion_mode) in 0) echo "fast" ;; 1) echo "multiple rays x$(mb2Value "$f" ambient_occlusion_quality)" ;; *) echo "screen space" ;; esac || echo off)
  refl=$( [[ $(mb2Value "$f" raytraced_reflections) =~ ^(true|1)$ ]] && awk -v r="$(mb2Value "$f" mat1_reflectance)" 'BEGIN { exit !(r > 0) }' &&
    echo "traced ($(mb2Value "$f" mat1_reflectance))" || echo none)
  # DE method and function as Mandelbulber2 numbers them (0: the formula's preferred; method 1 delta,
  # 2 analytic; function 1 linear, 2 logarithmic: fractparams.cpp's enums).
  echo "formula $(mb2Value "$f" formula_1), N $(mb2Value "$f" N), DE method $(mb2Value "$f" delta_DE_method) function $(mb2Value "$f" delta_DE_function), factor $(mb2Value "$f" DE_factor), detail $(mb2Value "$f" detail_level), AO $ao, shadow $( [[ $(mb2Value "$f" shadows_enabled) =~ ^(true|1)$ ]] && echo on || echo off), reflection $refl"
}
extra=""; extraRule=""
if [[ -n $deCount ]]; then
  extra=" fraktal: what it computes | fraktal DE evaluations/px (march steps/ray; shading) | mandelbulber2: what it computes | mandelbulber2 iterations/px (all DE calls) |"
  extraRule="---|---|---|---|"
fi
echo "| scene | mandelbulber2 samples/px | mandelbulber2 s (CPU s) | its coverage RMSE | fraktal setting | fraktal s (CPU s) | fraktal coverage RMSE | mandelbulber2 / fraktal, wall (CPU) |$extra"
echo "|---|---|---|---|---|---|---|---|$extraRule"
ratios=()
for scene in "${scenes[@]}"; do
  c=${scene%%$'\t'*}; name=${scene#*$'\t'}
  fract=$(fractOf "$c" "$name")
  "$fraktal" import "$fract" -o "$tmp/s.json" -q
  "$fraktal" render "$tmp/s.json" -o "$tmp/truth.exr" --size "$size" --spp $(( truthAa * truthAa )) --adaptive-tolerance 0 -q
  declare -A fTime=() fCpu=() fError=()
  for spp in "${fraktalSpp[@]}"; do
    timed "$fraktal" render "$tmp/s.json" -o "$tmp/f.exr" --size "$size" --spp "$spp" -q
    fTime[$spp]=$wall fCpu[$spp]=$cpu
    read -r fError[$spp] _ _ < <("$tmp/coverage_error" "$tmp/truth.exr" "$tmp/f.exr")
  done
  withSettings "$fract" "$tmp/truth.fract" antialiasing_enabled=true antialiasing_size=$truthAa
  # A truth over the time limit (Monte Carlo global illumination at 4 samples a pixel ran for hours):
  # the scene is named, not timed, and not counted.
  if ! HOME="$tmp" QT_QPA_PLATFORM=offscreen timeout "${PEER_TIMEOUT:-0}" mandelbulber2 -n -f png16alpha -r "$size" \
      -o "$tmp/mb_truth" "$tmp/truth.fract" > /dev/null 2>&1 < /dev/null; then
    echo "| $c / $name | not timed: mandelbulber2's $((truthAa * truthAa))-sample truth ran over ${PEER_TIMEOUT:-0} s | | | | | | |"
    unset fTime fCpu fError
    continue
  fi
  for aa in "${peerAa[@]}"; do
    withSettings "$fract" "$tmp/peer.fract" antialiasing_enabled=$([[ $aa -gt 1 ]] && echo true || echo false) antialiasing_size=$aa
    timed env HOME="$tmp" QT_QPA_PLATFORM=offscreen mandelbulber2 -n --stats -f png16alpha -r "$size" -o "$tmp/mb" \
      "$tmp/peer.fract"
    t=$wall peerCpu=$cpu
    peerIters=$(tr '\r' '\n' < "$tmp/timed.log" | sed -nE 's/.*iters \/ pixel *: *([0-9.e+]+).*/\1/p' | tail -1)
    read -r peerError _ _ < <("$tmp/coverage_error" "$tmp/mb_truth.png" "$tmp/mb.png")
    best=""
    for spp in "${fraktalSpp[@]}"; do
      # awk, not bc: the errors may be printed as 1e-05.
      if awk -v a="${fError[$spp]}" -v b="$peerError" 'BEGIN { exit !(a <= b + 1e-6) }'; then
        if [[ -z $best ]] || awk -v a="${fCpu[$spp]}" -v b="${fCpu[$best]}" 'BEGIN { exit !(a < b) }'; then best=$spp; fi
      fi
    done
    if [[ -n $best ]]; then
      ratio=$(awk -v a="$peerCpu" -v b="${fCpu[$best]}" 'BEGIN { printf "%.2f", a / b }')
      ratios+=("$ratio $c / $name")
      cols=""
      if [[ -n $deCount ]]; then
        counts=$("$deCount" "$tmp/s.json" "$size" "$best" | sed -nE 's/^([0-9.]+) DE evaluations per pixel .*, ([0-9.]+) march steps per camera ray, .*, ([0-9.]+) of the DE .*/\1 (\2; \3)/p')
        cols=" $(fraktalBreakdown "$tmp/s.json") | $counts | $(mb2Breakdown "$fract") | ${peerIters:-?} |"
      fi
      echo "| $c / $name | $((aa * aa)) | $t ($peerCpu) | $peerError | $best spp | ${fTime[$best]} (${fCpu[$best]}) | ${fError[$best]} | $(awk -v a="$t" -v b="${fTime[$best]}" 'BEGIN { printf "%.2f", a / b }') ($ratio) |$cols"
    else
      echo "| $c / $name | $((aa * aa)) | $t | $peerError | none of spp ${fraktalSpp[*]} | | | |"
    fi
  done
  unset fTime fCpu fError
  timedRows=$((${timedRows:-0} + 1))
  [[ -n ${ROWS:-} ]] && ((timedRows >= ROWS)) && break
done
# The CPU-time ratio's distribution over the rows with an equal-error fraktal setting.
if (( ${#ratios[@]} > 0 )); then
  printf '%s\n' "${ratios[@]}" | sort -g | awk '{ r[NR] = $1; $1 = ""; n[NR] = $0 }
    END { m = NR % 2 ? r[(NR + 1) / 2] : (r[NR / 2] + r[NR / 2 + 1]) / 2
          printf "\nCPU-time ratio mandelbulber2 / fraktal over %d rows: median %.2f, worst %.2f (%s), best %.2f\n", NR, m, r[1], n[1], r[NR]
          for (i = 1; i <= NR && r[i] < 1; i++) printf "fraktal slower: %s (%.2f)\n", n[i], r[i] }'
fi
