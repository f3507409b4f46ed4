#!/usr/bin/env bash
# Runs the benchmark set, one benchmark after another on this machine, and writes each benchmark's
# output as Markdown (bench/results/NAME.md, its log in NAME.log) and all of them as JSON
# (bench/results/results.json: date, commit, machine, and per benchmark its command, status and
# tables). bench/README.md and the area READMEs hold the figures; each table there names the
# command this runs for it.
# Usage: bench/run.sh BUILD_DIR [NAME...]   (default: every benchmark below; --list prints them)
# Every table of bench/*/README.md is reproduced by one of the names below, but those it prints
# as left out at the start (with why and how to run them). The whole set takes hours on a 2-core
# machine: the import library alone about 35 minutes, mandelbulber2's side of the stills and
# import speed benchmarks much of the rest.
# A benchmark whose prerequisite is missing (e.g. mandelbulber2 cannot be installed) says so in its
# own output and the run goes on; a benchmark that fails is recorded as failed.
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
usage="usage: bench/run.sh BUILD_DIR [NAME...] | bench/run.sh --list"
[ $# -ge 1 ] || { echo "$usage" >&2; exit 2; }
cd "$root"
out=bench/results  # relative to the root, where every command runs
list=0
if [ "$1" = --list ]; then list=1; build=build; else
  # The area scripts take BUILD_DIR relative to the repository root ("$root/$build"), and some
  # relative to the current folder: a path relative to the root serves both, as they run from it.
  [ -d "$1" ] || { echo "bench/run.sh: $1: no such build folder" >&2; echo "$usage" >&2; exit 2; }
  build="$(realpath --relative-to="$root" "$1")"
fi
shift
fraktal="$build/app/fraktal"

# The import speed tables' scenes (bench/import/README.md), one "collection<TAB>name" a line.
tab=$'\t'
import_scenes_640x360=""
for s in "toolbar${tab}dodecahedron" "toolbar${tab}icosahedron" "toolbar${tab}mandelbox scale -2" \
    "toolbar${tab}mandelbulb_power_9" "toolbar${tab}octahedron" "toolbar${tab}quaternion" \
    "toolbar${tab}menger sponge" "formula${tab}mandelbulb_eye" "formula${tab}menger_smooth" \
    "formula${tab}transf_abs_add_conditional4d" "toolbar${tab}mandelbulb_power_2" \
    "formula${tab}menger_smooth_mod1" "formula${tab}abox_mod_kali_v2" "formula${tab}sierpinski3d" \
    "formula${tab}box_fold_bulb_pow2_v3" "formula${tab}amazing_surf_mod2" \
    "formula${tab}transf_diagonal_fold" "root${tab}boolean001"; do
  import_scenes_640x360+="$s"$'\n'
done
import_scenes_1280x720=""
for s in "mandelbox scale 2" "mandelbox scale -2" "menger sponge" dodecahedron octahedron quaternion \
    mandelbulb_power_2 mandelbulb_power_9 icosahedron; do
  import_scenes_1280x720+="toolbar${tab}$s"$'\n'
done
export import_scenes_640x360="${import_scenes_640x360%$'\n'}" import_scenes_1280x720="${import_scenes_1280x720%$'\n'}"

# name|command (run by bash from the repository root), in the order of bench/README.md's index.
benchmarks=(
  # bench/viewport: sections 1-5 of its README, then the pass times (one run each; the README's
  # figures are medians of 5-9 such runs), the editor under load, the editor path-tracing at rest.
  "viewport|bench/viewport/run.sh $build"
  "viewport_passes|for p in mandelbulb menger; do echo \"## \$p\"; $fraktal bench viewport presets/\$p.json --size 640x360 --frames 8 --degrees 0.5 --from-rest --time-passes; done"
  "editor_load|bench/viewport/editor_load.sh $build 2"
  "editor_rest_frames|bench/viewport/rest_frames.sh $build 20"
  "editor_pathtrace|FRAKTAL_PATHTRACE_MEASURE=1 tests/editor_pathtrace_xvfb_test.sh $fraktal presets $out/editor_pathtrace"
  # bench/stills
  "equal_quality|bench/stills/equal_quality.sh $build 640x360"
  "equal_quality_1280x720|PEER_AA='1 2' FRAKTAL_SPP='1 2 4 6 8' TRUTH_SPP=16 bench/stills/equal_quality.sh $build 1280x720"
  "stills|JSON=$out/stills.native.json bench/stills/run.sh $build 640x360 1 4"
  "stills_1280x720|JSON=$out/stills_1280x720.native.json bench/stills/run.sh $build 1280x720 1"
  "de_count|bench/stills/de_count_all.sh $build 320x180 1"
  "overshoot|bench/stills/overshoot_pixels.sh $build 320x180"
  "overshoot_factor1|bench/stills/overshoot_pixels.sh $build 320x180 1.0"
  "safe_step|$build/tests/fraktal_tests --gtest_filter='SafeStep.RandomStacks*'"
  "exr_write|bench/stills/exr_write.sh $build 8192x8192"
  "exr_write_16384|bench/stills/exr_write.sh $build 16384x16384"
  "exr_menger_16384|/usr/bin/time -v $fraktal render presets/menger.json -o $out/menger_16384.exr --size 16384x16384 --spp 1 -q 2>&1 | grep -E 'Elapsed|User time|System time|Maximum resident'; ls -l $out/menger_16384.exr; rm -f $out/menger_16384.exr"
  "wide_exr|bench/stills/wide_exr.sh $build"
  "pathtrace_256|bench/stills/pathtrace.sh $build 320x180 256 64"
  "pathtrace_1024|bench/stills/pathtrace.sh $build 320x180 1024 64"
  # bench/import: the library (its OUT in bench/results/import), then the speed tables' scenes.
  "import|bench/import/run.sh $fraktal 160x120 $out/import"
  "import_speed_table|bench/import/speed_table.sh --seed 1 -o $out/import_speed_table.md $build"
  "import_speed_640x360|SCENES=\"\$import_scenes_640x360\" TRUTH_AA=2 PEER_AA=1 FRAKTAL_SPP='1 2' bench/import/speed.sh /dev/null 0 640x360 $fraktal"
  "import_speed_1280x720|SCENES=\"\$import_scenes_1280x720\" TRUTH_AA=2 PEER_AA=1 FRAKTAL_SPP='1 2' bench/import/speed.sh /dev/null 0 1280x720 $fraktal"
  # bench/anim: three frames of the power morph twice (the second run skips them), then the farm.
  "anim_sequence|rm -rf $out/anim_sequence && mkdir -p $out/anim_sequence && for run in render rerun; do echo \"## \$run\"; /usr/bin/time -v $fraktal render presets/mandelbulb_power_morph.json --frames 0-239:100 -o $out/anim_sequence/f_####.exr -q 2>&1 | grep -E 'Elapsed|Maximum resident'; done; du -b $out/anim_sequence/*.exr; rm -rf $out/anim_sequence"
  "anim|bench/anim/run.sh $build 240 640x360"
  # bench/plane
  "plane|bench/plane/run.sh $build 2"
  # bench/mesh
  "mesh|bench/mesh/run.sh $build $out/mesh"
)

# What this script does not run, and why (printed at the start of every run).
left_out=(
  "gpu: needs a lent GPU machine; run \`bash bench/gpu/pack.sh\` here, then \`bash .gpu/run.sh\` there (bench/gpu/README.md)"
  "stills 'Adaptive sampling and tetrahedral normals': a comparison with the build before cda8758, which its 'before' rows need; its commands are in bench/stills/README.md"
  "overshoot 'without the recovery' column: a build with the recovery switched off by a local edit of shaders/march.glsl"
  "anim 48-frame runs: \`bench/anim/run.sh BUILD_DIR 48 640x360\`, the shorter form of 'anim'"
  "frag: the Fragmentarium libraries it runs are the artists' (not shipped, licences vary); fetch them and run \`bench/frag/run.sh BUILD_DIR FOLDER\` (bench/frag/README.md)"
)

if [ "$list" = 1 ]; then
  for entry in "${benchmarks[@]}"; do printf '%s\n    %s\n' "${entry%%|*}" "${entry#*|}"; done
  echo "left out:"; printf '  %s\n' "${left_out[@]}"
  exit 0
fi

selected=("$@")
for s in "${selected[@]}"; do
  known=0
  for entry in "${benchmarks[@]}"; do [ "${entry%%|*}" = "$s" ] && known=1; done
  [ "$known" = 1 ] || { echo "bench/run.sh: no benchmark named $s (bench/run.sh --list)" >&2; exit 2; }
done
wanted() {
  [ ${#selected[@]} -eq 0 ] && return 0
  local s; for s in "${selected[@]}"; do [ "$s" = "$1" ] && return 0; done
  return 1
}

echo "== left out of this run:" >&2
printf '   %s\n' "${left_out[@]}" >&2
mkdir -p "$out"
parts=()
for entry in "${benchmarks[@]}"; do
  name=${entry%%|*}; command=${entry#*|}
  wanted "$name" || continue
  echo "== $name: $command"
  start=$(date +%s)
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
