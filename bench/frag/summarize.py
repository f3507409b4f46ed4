#!/usr/bin/env python3
"""The tables of bench/frag/README.md from bench/frag/run.sh's results.tsv (one or more: one a row).
Usage: summarize.py [--pixels W*H] RESULTS.tsv... (W*H: the image's pixels, 160x120 by default)."""
import collections
import csv
import os
import re
import sys


def kind_of(reason):
    """A refusal reason without the names and values of the file it came from, to rank them."""
    reason = re.sub(r"^uniform (?!(time|Eye|Target|Up|FOV):)\w+: ", "uniform NAME: ", reason)
    reason = re.sub(r"\(`(\w+) \w+`\)", r"(`\1 NAME`)", reason)
    reason = re.sub(r"(it keeps the value|the value) .*$", r"\1 it has", reason)
    return re.sub(r"^GLSL line \d+: ", "GLSL: ", reason)


def load(path):
    return list(csv.DictReader(open(path), delimiter="\t"))


def imported(r):
    return r["status"] in ("imported", "matching", "imported-no-reference")


def partial(r):
    """The frag's own raytracer neither misses nor hits everywhere: an IoU of 1 says something."""
    return r["host_px"] not in ("", "0", str(PIXELS))


def row(name, rows):
    de = [r for r in rows if r["kind"] == "de"]
    imp = [r for r in de if imported(r)]
    compared = [r for r in imp if r["iou"] != ""]
    match = [r for r in de if r["status"] == "matching"]
    host_ok = [r for r in de if r["host"] == "ok"]
    pct = lambda a, b: f"{100 * a / b:.0f} %" if b else "-"
    print(f"| {name} | {len(rows)} | {len(de)} | {len(host_ok)} | {len(imp)} ({pct(len(imp), len(de))}) | "
          f"{len(match)} ({pct(len(match), len(de))} of the DE frags; {pct(len(match), len(compared))} of "
          f"{len(compared)} compared) | {sum(partial(r) for r in match)} of {sum(partial(r) for r in compared)} |")


args = sys.argv[1:]
PIXELS = 160 * 120
if args[:1] == ["--pixels"]:
    PIXELS, args = int(args[1]), args[2:]
paths = args
sets = [(os.path.basename(os.path.dirname(os.path.abspath(p))), load(p)) for p in paths]
print("| folder | frags | 3D DE frags | their own raytracer ran | imported (of the DE frags) | "
      "matching, IoU >= 0.9 | matching where the object neither fills the view nor misses it |")
print("|---|---|---|---|---|---|---|")
for name, rows in sets:
    row(name, rows)
if len(sets) > 1:
    row("**all**", [r for _, rows in sets for r in rows])
everything = [r for _, rows in sets for r in rows]
print()
print("Kinds of frag (the host's reading: a 3D camera and a `float DE(vec3)`, a Brute-Raytracer `inside()`, "
      "other 3D, 2D, not read):")
print()
print("| kind | frags | imported |")
print("|---|---|---|")
for kind, k in collections.Counter(r["kind"] for r in everything).most_common():
    print(f"| {kind} | {k} | {sum(imported(r) for r in everything if r['kind'] == kind)} |")
print()
print("3D DE frags refused or failing, by the first reason the import names:")
print()
print("| reason | frags |")
print("|---|---|")
for reason, k in collections.Counter(kind_of(r["reason"]) for r in everything
                                     if r["kind"] == "de" and r["status"] in ("refused", "error",
                                                                              "render-failed")).most_common(30):
    print(f"| {reason} | {k} |")
print()
print("3D DE frags whose own raytracer the host could not run:")
print()
print("| why | frags |")
print("|---|---|")
for reason, k in collections.Counter(r["host"] for r in everything if r["kind"] == "de" and r["host"] != "ok").most_common(15):
    print(f"| {reason[:150]} | {k} |")
print()
print("Imported, IoU below 0.9 (worst first):")
print()
print("| file | IoU | fraktal px | own raytracer px |")
print("|---|---|---|---|")
for r in sorted((r for r in everything if r["status"] == "imported"), key=lambda r: float(r["iou"])):
    print(f"| {r['file']} | {r['iou']} | {r['fraktal_px']} | {r['host_px']} |")
print()
print("DE evaluations per pixel, matching frags (the frag's own raytracer: every DE call of the pixel, "
      "march, normal, AO, shadows; fraktal: bench_de_count, the same):")
print()
print("| file | own raytracer | fraktal | own / fraktal |")
print("|---|---|---|---|")
speed = [r for r in everything if r["status"] == "matching" and r["host_de_per_px"] not in ("", "-")
         and r["fraktal_de_per_px"] not in ("",)]
for r in sorted(speed, key=lambda r: r["file"]):
    h, f = float(r["host_de_per_px"]), float(r["fraktal_de_per_px"])
    print(f"| {r['file']} | {h:.1f} | {f:.1f} | {h / f:.2f} |" if f > 0 else f"| {r['file']} | {h:.1f} | {f} | - |")
