#!/usr/bin/env python3
"""Sets an imported frag's preset to render at WxH with FragM's hit cone: FragM's hit test is a cone
independent of the image's size, fraktal's threshold is in pixel footprints, which the import sets
for the preset's own size (render.height). At another size the threshold is rescaled by the
heights, so that both draw the same cone (else 160x120 would draw it 6x as wide as at 720 rows).
Usage: at_size.py PRESET.json WxH (rewrites the file)."""
import json
import sys

path, (w, h) = sys.argv[1], map(int, sys.argv[2].split("x"))
preset = json.load(open(path))
r = preset.setdefault("render", {})
# Within the range a preset holds: a cone finer than 0.001 of a pixel is drawn at 0.001.
r["detail"] = max(r.get("detail", 0.5) * h / r.get("height", 720), 0.001)
r["width"], r["height"] = w, h
json.dump(preset, open(path, "w"), indent=1)
