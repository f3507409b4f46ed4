#!/usr/bin/env bash
# Sequence rendering: frames per hour of a shipped animated preset rendered by one process
# (`fraktal render --frames`, every core) against the same frames through the local Slurm cluster
# (scripts/slurm-local.sh) as a job array of 2 tasks with 1 CPU each (`fraktal farm submit`), one
# after the other on this machine; then the bytes written per frame and the cost of a tile merge.
# Prints Markdown tables on stdout, progress on stderr.
# Usage: bench/anim/run.sh BUILD_DIR [FRAMES=240] [SIZE=640x360] [PRESET=presets/mandelbox_flythrough.json]
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(realpath "${1:?usage: bench/anim/run.sh BUILD_DIR [FRAMES] [SIZE] [PRESET]}")"
frames="${2:-240}"
size="${3:-640x360}"
preset="$(realpath "${4:-$root/presets/mandelbox_flythrough.json}")"
fraktal="$build/app/fraktal"
work="$(mktemp -d /tmp/fraktal-bench-anim.XXXXXX)"
export FRAKTAL_SLURM_DIR="$work/slurm"
trap '"$root/scripts/slurm-local.sh" stop >/dev/null 2>&1 || true; rm -rf "$work"' EXIT
last=$((frames - 1))
mkdir -p "$work/single" "$work/farm" "$work/parts"

now() { date +%s.%N; }
per_hour() { awk -v n="$1" -v s="$2" 'BEGIN { printf "%.0f", n / s * 3600 }'; }

echo "one process: frames 0-$last of $preset at $size" >&2
t0=$(now)
"$fraktal" render "$preset" --frames "0-$last" --size "$size" -q -o "$work/single/frame_####.exr"
single_s=$(awk -v a="$t0" -v b="$(now)" 'BEGIN { print b - a }')

"$root/scripts/slurm-local.sh" start >&2
eval "$("$root/scripts/slurm-local.sh" env)"
chunk=$(((frames + 1) / 2))
echo "Slurm: 2 array tasks of $chunk frames, 1 CPU each" >&2
t0=$(now)
job=$("$fraktal" farm submit "$preset" --frames "0-$last" --chunk "$chunk" --cpus-per-task 1 --size "$size" \
  -o "$work/farm/frame_####.exr" | sed -n 's/^submitted job \([0-9]*\):.*/\1/p')
[ -n "$job" ] || { echo "bench/anim: the array was not submitted" >&2; exit 1; }
while [ -n "$(squeue --noheader --array --jobs="$job" 2>/dev/null)" ]; do sleep 0.5; done
farm_s=$(awk -v a="$t0" -v b="$(now)" 'BEGIN { print b - a }')
"$fraktal" farm status "$work/farm" | grep -q "^done: $frames frames$" ||
  { echo "bench/anim: the farm did not complete every frame" >&2; "$fraktal" farm status "$work/farm" >&2; exit 1; }
"$root/scripts/slurm-local.sh" stop >&2

bytes=$(du -cb "$work"/single/frame_*.exr | tail -n1 | cut -f1)

# Merge cost: a still of this size in 4 parts (rendered here, not on the cluster), joined.
for i in 1 2 3 4; do "$fraktal" render "$preset" --size "$size" -q --tile "$i/4" -o "$work/parts/p$i.exr"; done
t0=$(now)
"$fraktal" merge "$work"/parts/p*.exr -o "$work/merged.exr" 2>/dev/null
merge_s=$(awk -v a="$t0" -v b="$(now)" 'BEGIN { print b - a }')

cat <<EOF
### Sequence: $frames frames of $(basename "$preset") at $size, $(nproc) cores

| how | seconds | s/frame | frames/hour |
|---|---|---|---|
| one process (\`fraktal render --frames\`, all cores) | $(printf %.1f "$single_s") | $(awk -v s="$single_s" -v n="$frames" 'BEGIN { printf "%.2f", s / n }') | $(per_hour "$frames" "$single_s") |
| local Slurm array, 2 tasks x 1 CPU (\`fraktal farm submit --chunk $chunk\`) | $(printf %.1f "$farm_s") | $(awk -v s="$farm_s" -v n="$frames" 'BEGIN { printf "%.2f", s / n }') | $(per_hour "$frames" "$farm_s") |

| per frame | value |
|---|---|
| EXR written (half float, 13 channels, ZIP) | $((bytes / frames)) bytes |
| merge of a $size still from 4 parts (\`fraktal merge\`) | $(printf %.3f "$merge_s") s |
EOF
