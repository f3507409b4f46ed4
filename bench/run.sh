#!/usr/bin/env bash
# Runs the whole benchmark set, one benchmark after another on this machine, and writes each
# benchmark's tables as Markdown (bench/results/NAME.md) and all of them as JSON
# (bench/results/results.json: date, commit, machine, and per benchmark its command and tables).
# bench/README.md holds the current figures; this is the command that reproduces them.
# Usage: bench/run.sh BUILD_DIR [NAME...]   (default: every benchmark; names below)
# A benchmark whose prerequisite is missing (e.g. mandelbulber2 cannot be installed) says so in its
# own output and the run goes on; a benchmark that fails is recorded as failed.
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(realpath "${1:?usage: bench/run.sh BUILD_DIR [NAME...]}")"; shift
out="$root/bench/results"
mkdir -p "$out"
cd "$root"

# name|command (run from the repository root)
benchmarks=(
  "viewport|bench/viewport/run.sh $build"
  "stills|JSON=$out/stills.native.json bench/stills/run.sh $build 1280x720 1 4"
  "equal_quality|bench/stills/equal_quality.sh $build 640x360"
  "de_count|bench/stills/de_count_all.sh $build 320x180 1"
  "exr_write|bench/stills/exr_write.sh $build 8192x8192"
  "plane|bench/plane/run.sh $build 2"
  "anim|bench/anim/run.sh $build 240 640x360"
  "editor|bench/viewport/editor_run.sh $build presets/mandelbulb.json 1280x720"
)

selected=("$@")
wanted() {
  [ ${#selected[@]} -eq 0 ] && return 0
  local s; for s in "${selected[@]}"; do [ "$s" = "$1" ] && return 0; done
  return 1
}

parts=()
for entry in "${benchmarks[@]}"; do
  name=${entry%%|*}; command=${entry#*|}
  wanted "$name" || continue
  echo "== $name: $command"
  start=$(date +%s)
  # shellcheck disable=SC2086
  if bash -c "$command" > "$out/$name.md.tmp" 2> "$out/$name.log"; then status=ok; else status=failed; fi
  mv "$out/$name.md.tmp" "$out/$name.md"
  cat "$out/$name.md"
  python3 bench/md_tables_to_json.py "$name" "$command" < "$out/$name.md" |
    python3 -c 'import json,sys; d=json.load(sys.stdin); d["status"]=sys.argv[1]; d["seconds"]=int(sys.argv[2]); json.dump(d,sys.stdout)' \
      "$status" "$(( $(date +%s) - start ))" > "$out/$name.json"
  [ "$status" = ok ] || echo "== $name failed: see $out/$name.log" >&2
  parts+=("$out/$name.json")
done

renderer=$(EGL_PLATFORM=surfaceless eglinfo 2>/dev/null | grep -m1 'OpenGL core profile renderer' | cut -d: -f2- | xargs || true)
python3 - "$out/results.json" "$(git rev-parse --short HEAD 2>/dev/null || echo unknown)" "$(nproc)" \
  "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | xargs)" "${renderer:-unknown}" "${parts[@]}" <<'PY'
import datetime, json, os, sys
path, commit, cores, cpu, renderer, *parts = sys.argv[1:]
result = {"date": datetime.date.today().isoformat(), "commit": commit,
          "machine": {"cores": int(cores), "cpu": cpu, "gl_renderer": renderer,
                      "load_average_at_end": os.getloadavg()[0]},
          "benchmarks": [json.load(open(p)) for p in parts]}
tmp = path + ".tmp"
json.dump(result, open(tmp, "w"), indent=1)
os.replace(tmp, path)
print("wrote", path)
PY
