#!/usr/bin/env python3
"""The editor's folders form layers (app/editor/README.md): a file may include headers of its own
folder and of the layers below it, never of a layer above, and folders that share a layer include
each other only where the layer says so. A new folder must be given a layer here.

Usage: editor_layers_test.py REPO_ROOT
"""
import pathlib
import re
import sys

# Lowest first. Folders in one tuple share a layer; `shared` names the folders that the layer's
# other folders may include (the panels' declarations).
LAYERS = [
    {"folders": ("widgets", "input"), "shared": ()},
    {"folders": ("document",), "shared": ()},
    {"folders": ("state",), "shared": ()},
    {"folders": ("viewport",), "shared": ()},
    {"folders": ("timeline",), "shared": ()},
    {"folders": ("panels", "dialogs", "plane"), "shared": ("panels",)},
    {"folders": (".",), "shared": ()},  # editor.cpp: the frame loop, and the state file it writes
]


def main() -> int:
    root = pathlib.Path(sys.argv[1]) / "app" / "editor"
    layer_of, shared_in = {}, {}
    for index, layer in enumerate(LAYERS):
        for folder in layer["folders"]:
            layer_of[folder] = index
            shared_in[folder] = layer["shared"]
    include = re.compile(r'^\s*#\s*include\s+"app/editor/(?:(\w+)/)?(\w+)\.hpp"', re.M)
    problems, checked = [], 0
    for path in sorted(root.rglob("*.[ch]pp")):
        rel = path.relative_to(root)
        folder = rel.parts[0] if len(rel.parts) > 1 else "."
        if folder not in layer_of:
            problems.append(f"app/editor/{rel}: folder '{folder}' has no layer in {sys.argv[0]}")
            continue
        checked += 1
        for inc_folder, name in include.findall(path.read_text()):
            inc_folder = inc_folder or "."
            target = f"app/editor/{inc_folder + '/' if inc_folder != '.' else ''}{name}.hpp"
            if inc_folder not in layer_of:
                problems.append(f"app/editor/{rel} includes {target}: no such layer")
            elif not (root.parent.parent / target).is_file():
                problems.append(f"app/editor/{rel} includes {target}: no such file")
            elif layer_of[inc_folder] > layer_of[folder]:
                problems.append(f"app/editor/{rel} ({folder}) includes {target}: a layer above ({inc_folder})")
            elif (layer_of[inc_folder] == layer_of[folder] and inc_folder != folder
                  and inc_folder not in shared_in[folder]):
                problems.append(f"app/editor/{rel} ({folder}) includes {target}: a sibling folder ({inc_folder})")
    if checked < 50:
        problems.append(f"only {checked} files found under {root}: is the path right?")
    for p in problems:
        print(p)
    print(f"{checked} files checked, {len(problems)} include(s) against the layers")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
