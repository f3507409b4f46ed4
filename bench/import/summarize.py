#!/usr/bin/env python3
"""The tables of bench/import/README.md from bench/import/run.sh's results.tsv."""
import collections
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1]), delimiter="\t"))
order = ["toolbar", "root", "KM", "GM", "RP", "SJ", "DL", "formula"]
names = {"toolbar": "toolbar (one-click presets)", "root": "examples/ (team)", "KM": "Krzysztof Marczak",
         "GM": "Graeme McLaren", "RP": "Robert Pancoast", "SJ": "Sebastian Jennen", "DL": "Daniel Luchansky",
         "formula": "formula/img (one file a formula)"}


def full(r):
    """Mandelbulber2's mask covers the whole image (a view from inside): IoU 1 says little."""
    return r["mb2_px"] != "" and r["mb2_px"] == str(WIDTH_X_HEIGHT)


def counts(subset):
    imported = [r for r in subset if r["status"] in ("imported", "matching")]
    partial = [r for r in imported if not full(r)]
    return (len(subset), len(imported), sum(r["status"] == "matching" for r in subset),
            sum(r["status"] == "matching" for r in partial), len(partial),
            sum(r["status"] == "refused" for r in subset),
            sum(r["status"] in ("render-failed", "error") for r in subset))


WIDTH_X_HEIGHT = int(sys.argv[2]) if len(sys.argv) > 2 else 160 * 120


def line(name, subset):
    n, i, m, mp, p, f, e = counts(subset)
    print(f"| {name} | {n} | {i} | {m} ({100 * m / max(i, 1):.0f} %) | {mp} of {p} | {f} | {e} |")


print("| collection | files | imported | matching (IoU >= 0.9; share of imported) | matching where the object "
      "does not fill the view | refused | failed |")
print("|---|---|---|---|---|---|---|")
for c in order:
    subset = [r for r in rows if r["collection"] == c]
    if subset:
        line(names.get(c, c), subset)
line("**all 422 examples**", [r for r in rows if r["collection"] not in ("toolbar", "formula")])
line("**formula/img files whose formulas fraktal has**",
     [r for r in rows if r["collection"] == "formula" and r.get("missing_formula") != "yes"])
line("**expressible by the reference's T3**", [r for r in rows if r["expressible"] == "yes"])
exp = [r for r in rows if r["expressible"] == "yes"]
print()
print("Refused, by the first reason the import names (all files):")
print()
print("| reason | files |")
print("|---|---|")
for reason, k in collections.Counter(r["reason"] for r in rows if r["status"] == "refused").most_common(25):
    print(f"| {reason} | {k} |")
print()
print("Expressible by T3 but refused here:")
print()
for r in exp:
    if r["status"] in ("refused", "error", "render-failed"):
        print(f"- {r['collection']} / {r['file']}: {r['status']}: {r['reason']}")
print()
print("Imported, IoU below 0.9 (worst first):")
print()
print("| collection / file | IoU | fraktal px | mandelbulber2 px |")
print("|---|---|---|---|")
for r in sorted((r for r in rows if r["status"] == "imported"), key=lambda r: float(r["iou"])):
    print(f"| {r['collection']} / {r['file']} | {r['iou']} | {r['fraktal_px']} | {r['mb2_px']} |")
