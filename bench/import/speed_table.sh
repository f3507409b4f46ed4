#!/usr/bin/env bash
# The speed table on imported scenes in one command and one run: fraktal's still
# against mandelbulber2's own at equal coverage error (bench/import/speed.sh, each row with the
# breakdown of what both programs compute), over
#   - the toolbar's nine one-click presets at TOOLBAR_SIZE (default 1280x720);
#   - the formula/img files that match (IoU >= 0.9 at 160x120, bench/import/run.sh);
#   - RANDOM (default 10) matching imports with an edge in view (the object does not fill
#     Mandelbulber2's 160x120 mask), drawn from the whole example library (examples/ and its
#     artist collections) in an order shuffled by SEED; a drawn scene whose mandelbulber2 truth runs
#     over PEER_TIMEOUT seconds (default 600) is listed as not timed and the next one drawn,
# the last two at SIZE (default 640x360). Which files match is measured in the same run
# (bench/import/run.sh on formula/img and on the drawn files, batch by batch until RANDOM are
# found), or read from a previous run's results.tsv (--results).
# The ratio is of CPU time (user + system, threads included), not of the wall clock: both programs
# use every core, and CPU time stays comparable when other work shares the machine.
# Usage: bench/import/speed_table.sh [--seed N] [--random N] [--size WxH] [--toolbar-size WxH]
#          [--only toolbar,formula,random] [--results RESULTS.tsv] [-o TABLE.md] [BUILD]
# BUILD (default build/) holds app/fraktal and bench/bench_de_count. Writes TABLE.md (default
# bench/import/out/speed_table.md): the date, commit, machine and command, then one table.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
seed=1 random=10 size=640x360 toolbarSize=1280x720 only=toolbar,formula,random results="" table="" build=""
command="bench/import/speed_table.sh $*"
while (($#)); do
  case "$1" in
    --seed) seed=$2; shift 2 ;;
    --random) random=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --toolbar-size) toolbarSize=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    --results) results=$(realpath "$2"); shift 2 ;;
    -o) table=$(realpath -m "$2"); shift 2 ;;
    -h | --help) sed -n '2,20p' "$0"; exit 0 ;;
    -*) echo "speed_table.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) build=$1; shift ;;
  esac
done
[[ $seed =~ ^[0-9]+$ ]] || { echo "speed_table.sh: --seed wants a whole number, not '$seed'" >&2; exit 2; }
[[ $random =~ ^[0-9]+$ ]] || { echo "speed_table.sh: --random wants a whole number, not '$random'" >&2; exit 2; }
for s in "$size" "$toolbarSize"; do
  [[ $s =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] || { echo "speed_table.sh: a size is WxH, not '$s'" >&2; exit 2; }
done
for part in ${only//,/ }; do
  case "$part" in toolbar | formula | random) ;; *) echo "speed_table.sh: --only takes toolbar, formula, random; not '$part'" >&2; exit 2 ;; esac
done
build=$(realpath "${build:-$root/build}")
fraktal=$build/app/fraktal deCount=$build/bench/bench_de_count
for f in "$fraktal" "$deCount"; do
  [[ -x $f ]] || { echo "speed_table.sh: $f is missing (cmake --build $build --target fraktal bench_de_count)" >&2; exit 2; }
done
command -v mandelbulber2 > /dev/null || { echo "speed_table.sh: mandelbulber2 is missing (scripts/install-deps.sh)" >&2; exit 2; }
table=${table:-$root/bench/import/out/speed_table.md}
mkdir -p "$(dirname "$table")"
share=/usr/share/mandelbulber2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$root"
has() { [[ ",$only," == *",$1,"* ]]; }
full=$((160 * 120))
# Matching files with an edge, from a results.tsv: "collection<TAB>name" lines.
matchingWithEdge() { awk -F'\t' -v full=$full '$4 == "matching" && $8 != full { print $1 "\t" $2 }' "$@"; }

# Which formula/img files match and which examples are drawn: measured after the toolbar's rows (a
# cut-short run still has them).
formulaScenes="" randomScenes=""
selectScenes() {
  if has formula || has random; then
    shuffle=yes
    if [[ -z $results ]]; then
      shuffle=no  # drawn in the shuffled order already
      # formula/img in one silhouette run, the shuffled examples in batches of 40 until enough match.
      results=$tmp/results.tsv
      if has formula; then
        find "$share/formula/img" -name '*.fract' | sort > "$tmp/list"
        FRACT_LIST=$tmp/list bench/import/run.sh "$fraktal" 160x120 "$tmp/formula" > /dev/null
        cp "$tmp/formula/results.tsv" "$results"
      else
        : > "$results"
      fi
      if has random; then
        find "$share/examples" -name '*.fract' | sort |
          python3 -c "import random, sys; l = sys.stdin.read().splitlines(); random.Random($seed).shuffle(l); print('\n'.join(l))" \
            > "$tmp/shuffled"
        batch=0
        # Twice as many as wanted: a drawn scene may run over the time limit.
        while (( $(awk -F'\t' '$1 != "formula"' "$results" | matchingWithEdge | wc -l) < 2 * random )); do
          sed -n "$((batch * 40 + 1)),$((batch * 40 + 40))p" "$tmp/shuffled" > "$tmp/list"
          [[ -s $tmp/list ]] || break
          FRACT_LIST=$tmp/list bench/import/run.sh "$fraktal" 160x120 "$tmp/batch$batch" > /dev/null
          tail -n +2 "$tmp/batch$batch/results.tsv" >> "$results"
          batch=$((batch + 1))
        done
      fi
    fi
    has formula && formulaScenes=$(awk -F'\t' '$1 == "formula" && $4 == "matching" { print $1 "\t" $2 }' "$results")
    # In the order drawn (a given results.tsv: its own order, shuffled by the seed).
    if has random; then
      randomScenes=$(awk -F'\t' '$1 != "formula" && $1 != "toolbar"' "$results" | matchingWithEdge |
        python3 -c "import random, sys
l = sys.stdin.read().splitlines()
if '$shuffle' == 'yes': random.Random($seed).shuffle(l)
print('\n'.join(l))")
    fi
  fi
}

# Each part through speed.sh: truths at 4 samples per pixel, mandelbulber2 at 1, fraktal at 1 or 2
# (bench/import/README.md, "Speed on imported scenes").
part() {  # TITLE SIZE SCENES [ROWS]
  [[ -n $3 ]] || return 0
  echo
  echo "### $1 at $2"
  echo
  ROWS=${4:-} PEER_TIMEOUT=${PEER_TIMEOUT:-600} SCENES=$3 TRUTH_AA=2 PEER_AA=1 FRAKTAL_SPP="1 2" DE_COUNT=$deCount bench/import/speed.sh /dev/null 0 "$2" "$fraktal" |
    tee -a "$tmp/rows" /dev/stderr
}
toolbarScenes=""
if has toolbar; then
  for f in "$share"/toolbar/*.fract; do toolbarScenes+="toolbar"$'\t'"$(basename "$f" .fract)"$'\n'; done
  toolbarScenes=${toolbarScenes%$'\n'}
fi
{
  echo "# Speed on imported scenes: mandelbulber2 / fraktal CPU time at equal coverage error"
  echo
  echo "Measured $(date -u '+%Y-%m-%d %H:%M UTC') at $(git rev-parse --short HEAD)$(git diff --quiet HEAD -- core app shaders formulas bench || echo ' (with uncommitted changes)')"
  echo "on $(nproc) cores, $(lscpu | sed -nE 's/^Model name: *//p' | head -1), $(uname -sr); mandelbulber2 $(mandelbulber2 --version 2>/dev/null | head -1 | grep -oE '[0-9.]+' | head -1)."
  echo "Command: \`$command\` (seed $seed)."
  echo "The ratio is of CPU time (user + system), not wall time: both programs use every core, and CPU"
  echo "time stays comparable when other work shares the machine."
  has toolbar && part "The toolbar's nine" "$toolbarSize" "$toolbarScenes"
  selectScenes
  has formula && part "formula/img files that match" "$size" "$formulaScenes"
  has random && part "$random matching imports with an edge, drawn with seed $seed" "$size" "$randomScenes" "$random"
  echo
  # Over every row: the median, the worst and how many are under 2x (the issue's goal: each at least 2x, the median 5x).
  grep -E '^\| [a-zA-Z]+ / ' "$tmp/rows" | awk -F'|' '{ split($9, a, /[()]/); if (a[2] != "") print a[2] "\t" $2 }' | sort -g |
    awk -F'\t' '{ r[NR] = $1; n[NR] = $2 } END {
      if (NR == 0) { print "No row had an equal-error fraktal setting."; exit }
      m = NR % 2 ? r[(NR + 1) / 2] : (r[NR / 2] + r[NR / 2 + 1]) / 2
      under = 0; for (i = 1; i <= NR; i++) if (r[i] < 2) under++
      printf "Over %d rows: median %.2f, worst %.2f (%s), best %.2f; %d under 2x.\n", NR, m, r[1], n[1], r[NR], under }'
} > "$tmp/table.md"
mv "$tmp/table.md" "$table"
cat "$table"
