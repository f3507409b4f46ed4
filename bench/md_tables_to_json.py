#!/usr/bin/env python3
"""Turns the Markdown tables a benchmark script prints into JSON.

Usage: md_tables_to_json.py NAME COMMAND < table.md > result.json
Every table becomes {"columns": [...], "rows": [{column: value}]}; a cell that reads as a number
(optionally followed by a unit such as "ms", "dB", "s" or "x") is stored as a number, with the
unit kept in the column's entry of "units". Text outside tables is kept in "notes"."""
import json
import re
import sys

NUMBER = re.compile(r"^(-?\d+(?:\.\d+)?)\s*(x|ms|s|dB|%|MB|MiB|GB)?$")


def cell_value(text, units, column):
    match = NUMBER.match(text)
    if not match:
        return text
    if match.group(2):
        units.setdefault(column, match.group(2))
    value = float(match.group(1))
    return int(value) if value.is_integer() and "." not in match.group(1) else value


def parse(lines):
    tables, notes, current = [], [], None
    for line in lines:
        line = line.rstrip("\n")
        if line.startswith("|"):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if current is None:
                current = {"columns": cells, "units": {}, "rows": []}
                tables.append(current)
            elif all(re.fullmatch(r":?-+:?", c) for c in cells):
                continue
            else:
                current["rows"].append({col: cell_value(c, current["units"], col)
                                        for col, c in zip(current["columns"], cells)})
        else:
            current = None
            if line.strip():
                notes.append(line.strip())
    return tables, notes


def main():
    name, command = sys.argv[1], sys.argv[2]
    tables, notes = parse(sys.stdin)
    json.dump({"benchmark": name, "command": command, "tables": tables, "notes": notes}, sys.stdout, indent=1)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
