#!/usr/bin/env bash
# `fraktal farm` on a real (local, single-node) Slurm cluster: a 12-frame animation submitted as a
# job array of 2-frame chunks, one running task cancelled with scancel, `farm status` reporting the
# frames it did not write, a resubmission running only that chunk, and every frame then complete and
# identical to a single-process `fraktal render --frames`; a still in 3 tiles with its merge job
# equal to a whole render; sbatch missing or refusing, and a missing output folder, are clear errors.
# Usage: farm_slurm_test.sh FRAKTAL SOURCE_DIR WORK_DIR
set -euo pipefail
fraktal="$1"
src="$2"
work="$3"
slurm_local="$src/scripts/slurm-local.sh"
export FRAKTAL_SLURM_DIR="$work/slurm"

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

rm -rf "$work"
mkdir -p "$work/farm" "$work/single" "$work/still"
trap '"$slurm_local" stop >/dev/null 2>&1 || true' EXIT
"$slurm_local" start
eval "$("$slurm_local" env)"

# Waits until job $1 has left the queue (every task finished, failed or cancelled).
wait_for_job() {
  for _ in $(seq 1 300); do
    [ -z "$(squeue --noheader --array --jobs="$1" 2>/dev/null)" ] && return 0
    sleep 0.2
  done
  squeue --array --jobs="$1" >&2 || true
  fail "job $1 still queued after 60 s"
}

preset="$src/presets/mandelbox_flythrough.json"
frames=(--frames 0-11 --size 64x36 --spp 1)

# 1. Submit; cancel a task as soon as squeue shows it RUNNING. A task's two small frames render
# fast, and it can finish between squeue's answer and scancel's arrival: then every frame is
# written and nothing was cancelled, so the test starts again from an empty folder (three
# attempts).
for attempt in 1 2 3; do
  rm -rf "$work/farm"
  mkdir -p "$work/farm"
  out="$("$fraktal" farm submit "$preset" "${frames[@]}" --chunk 2 -o "$work/farm/frame_####.exr")"
  echo "$out"
  job="$(echo "$out" | sed -n 's/^submitted job \([0-9]*\): frames array 0-5$/\1/p')"
  [ -n "$job" ] || fail "no array 0-5 submitted: $out"
  grep -q '"id": "'"$job"'"' "$work/farm/.farm/jobs.json" || fail "jobs.json does not record job $job"
  cancelled=""
  for _ in $(seq 1 600); do
    cancelled="$(squeue --noheader --array --jobs="$job" --states=RUNNING --format=%i | head -n1)"
    [ -n "$cancelled" ] && break
    sleep 0.05
  done
  [ -n "$cancelled" ] || fail "no task of job $job was seen RUNNING"
  scancel "$cancelled"
  echo "cancelled task $cancelled while RUNNING"
  wait_for_job "$job"

  # 2. The cancelled chunk's frames are missing (or broken), and status says so.
  status="$("$fraktal" farm status "$work/farm")"
  echo "$status"
  missing="$(echo "$status" | sed -n 's/^missing: \([0-9]*\).*/\1/p')"
  broken="$(echo "$status" | sed -n 's/^broken: \([0-9]*\).*/\1/p')"
  [ -n "$missing" ] && [ -n "$broken" ] || fail "farm status prints no missing and broken counts"
  if [ "$((missing + broken))" -gt 0 ]; then
    break
  fi
  echo "$status" | grep -q "^done: 12 frames$" ||
    fail "farm status reports no missing frame after task $cancelled was cancelled, yet not every frame done"
  [ "$attempt" -lt 3 ] || fail "three times task $cancelled finished before scancel reached it"
  echo "task $cancelled finished before scancel reached it: again"
done
echo "$status" | grep -q "^job $job (frames 0-5): not in the queue (finished)" || fail "status does not show job $job as finished"

# 3. Resubmission runs only the cancelled chunk.
task="${cancelled#*_}"
out="$("$fraktal" farm submit "$preset" "${frames[@]}" --chunk 2 -o "$work/farm/frame_####.exr")"
echo "$out"
job2="$(echo "$out" | sed -n 's/^submitted job \([0-9]*\): frames array '"$task"'$/\1/p')"
[ -n "$job2" ] || fail "the resubmission is not array $task alone: $out"
wait_for_job "$job2"
status="$("$fraktal" farm status "$work/farm")"
echo "$status"
echo "$status" | grep -q "^done: 12 frames$" || fail "not every frame is done after the resubmission"
echo "$status" | grep -q "^missing: 0$" || fail "frames still missing"
echo "$status" | grep -q "^broken: 0$" || fail "frames broken"
"$fraktal" farm submit "$preset" "${frames[@]}" --chunk 2 -o "$work/farm/frame_####.exr" | grep -q "nothing to submit" ||
  fail "a third submission submitted something"

# 4. Every frame equals a single-process render of the same frames, byte for byte (pixels, header, embedded preset).
"$fraktal" render "$preset" "${frames[@]}" -q -o "$work/single/frame_####.exr"
for i in $(seq -f %04g 0 11); do
  cmp "$work/farm/frame_$i.exr" "$work/single/frame_$i.exr" || fail "frame $i differs from the single-process render"
done
echo "12 farm frames identical to the single-process render"

# 5. A still in 3 tiles and a merge job after the array: the same image as a whole render.
still=(--size 64x48 --spp 2)
out="$("$fraktal" farm submit "$src/presets/mandelbulb.json" "${still[@]}" --tiles 3 -o "$work/still/bulb.exr")"
echo "$out"
tiles_job="$(echo "$out" | sed -n 's/^submitted job \([0-9]*\): tiles array 0-2$/\1/p')"
merge_job="$(echo "$out" | sed -n 's/^submitted job \([0-9]*\): merge after job '"$tiles_job"'$/\1/p')"
[ -n "$tiles_job" ] && [ -n "$merge_job" ] || fail "no tiles array and merge job: $out"
wait_for_job "$tiles_job"
wait_for_job "$merge_job"
"$fraktal" farm status "$work/still" | grep -q "merged, complete" || fail "the still is not merged"
"$fraktal" render "$src/presets/mandelbulb.json" "${still[@]}" -q -o "$work/whole.exr"
# Compression blocks may differ; uncompressed copies (every channel and attribute) must not.
exrmaketiled -z none "$work/still/bulb.exr" "$work/merged-plain.exr"
exrmaketiled -z none "$work/whole.exr" "$work/whole-plain.exr"
cmp "$work/merged-plain.exr" "$work/whole-plain.exr" || fail "the merged still differs from a whole render"
echo "merged still identical to a whole render (every channel, header)"

# 6. Errors: sbatch refusing (its message shown), sbatch missing, no output folder; nothing recorded.
set +e
err="$("$fraktal" farm submit "$preset" "${frames[@]}" --partition nosuch -o "$work/bad/frame_####.exr" 2>&1)"
rc=$?
[ $rc -ne 0 ] && echo "$err" | grep -q "does not exist" || fail "a missing output folder was not refused: $err"
mkdir -p "$work/bad"
err="$("$fraktal" farm submit "$preset" "${frames[@]}" --partition nosuch -o "$work/bad/frame_####.exr" 2>&1)"
rc=$?
[ $rc -ne 0 ] && echo "$err" | grep -q "sbatch failed" && echo "$err" | grep -qi "partition" ||
  fail "sbatch's refusal is not reported with its message: $err"
err="$(PATH=/nonexistent "$fraktal" farm submit "$preset" "${frames[@]}" -o "$work/bad/frame_####.exr" 2>&1)"
rc=$?
[ $rc -ne 0 ] && echo "$err" | grep -q "cannot run sbatch" || fail "a missing sbatch is not reported: $err"
set -e
[ ! -e "$work/bad/.farm/jobs.json" ] || fail "a failed submission recorded a job"
echo "farm_slurm_test: passed"
