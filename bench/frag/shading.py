#!/usr/bin/env python3
"""How DE-Raytracer's look reaches fraktal's presets over a folder of frags.

Usage: bench/frag/shading.py FRAKTAL FOLDER OUT [JOBS]

Imports every frag outside Include/ folders strictly (`fraktal import FRAG --include-dir
FOLDER/Include`, as bench/frag/run.sh does), keeps the presets in OUT/json/, and prints a Markdown
table: of the frags that import and are drawn by DE-Raytracer, how many get each mapped setting
(read from the preset written) and how many name each approximation (read from its description).
"""
import concurrent.futures
import json
import os
import pathlib
import re
import subprocess
import sys

fraktal, folder, out = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
jobs = int(sys.argv[4]) if len(sys.argv) > 4 else 2
(out / "json").mkdir(parents=True, exist_ok=True)
frags = sorted(p for p in folder.rglob("*.frag") if "Include" not in p.relative_to(folder).parts)
include = ["--include-dir", str(folder / "Include")] if (folder / "Include").is_dir() else []


def key(path):
    return re.sub(r"[^A-Za-z0-9_.-]", "_", str(path.relative_to(folder).with_suffix("")))


def run(path):
    target = out / "json" / (key(path) + ".json")
    done = subprocess.run([fraktal, "import", str(path), *include, "-o", str(target), "-q"],
                          capture_output=True, timeout=600)
    return path, done.returncode == 0 and target.exists()


with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
    results = list(pool.map(run, frags))

imported = [p for p, ok in results if ok]
counts, total = {}, 0
for path in imported:
    preset = json.loads((out / "json" / (key(path) + ".json")).read_text())
    description = preset.get("description", "")
    if "not DE-Raytracer" in description or "lightDirection" not in preset.get("shading", {}):
        continue
    total += 1
    s = preset["shading"]
    found = {
        "key light from SpotLight, SpotLightDir": True,
        "fill light from CamLight": "fillColor" in s,
        "shadows (HardShadow >= 0.5), ShadowSoft's penumbra": s.get("shadowSteps", 96) > 0,
        "AO along the normal (AO > 0)": s.get("aoSteps", 5) > 0,
        "fog (Fog > 0)": s.get("fogDensity", 0) > 0,
        "background BackgroundColor": "backgroundTop" in s,
        "orbit-trap palette ramp (OrbitStrength > 0)": "OrbitStrength:" in description,
        "cycling palette (CycleColors)": "CycleColors:" in description,
        "flat BaseColor (OrbitStrength 0)": all(v == 0 for v in s.get("paletteB", [1])),
        "reflection (Reflection > 0)": s.get("reflection", 0) > 0,
        "named: Glow not drawn": "Glow:" in description,
        "named: GradientBackground vignette not drawn": "GradientBackground:" in description,
        "named: tone curve (ToneMapping not 1)": "ToneMapping:" in description,
        "named: AO by step count (DetailAO >= 0)": "DetailAO:" in description,
        "named: coloured AO": re.search(r"\bAO: the occlusion", description) is not None,
        "named: partial HardShadow": "HardShadow:" in description,
    }
    for name, hit in found.items():
        counts[name] = counts.get(name, 0) + int(bool(hit))

print(f"{len(frags)} frags, {len(imported)} import strictly, {total} of them drawn by DE-Raytracer\n")
print("| setting | frags |")
print("|---|---|")
for name, n in counts.items():
    print(f"| {name} | {n} |")
