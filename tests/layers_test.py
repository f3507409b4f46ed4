#!/usr/bin/env python3
"""The tree's folders form layers.

The whole tree: core never includes app or formulas (the library knows no program and no block
by name: the registries live in formulas/); formulas includes only core; the command line
(app/cli) never includes the editor (what both need lives in core); and no folder includes
another that includes it back, directly or around a longer loop (core's root folder counts as
one folder, each subfolder as another).

The editor (app/editor/README.md): a file may include headers of its own folder and of the
layers below it, never of a layer above, and folders that share a layer include each other only
where the layer says so. A new folder must be given a layer here.

Usage: layers_test.py REPO_ROOT
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


INCLUDE = re.compile(r'^\s*#\s*include\s+"((?:core|formulas|app)/[^"]+)"', re.M)


def folder_of(rel: pathlib.PurePosixPath) -> str:
    """The folder a file belongs to for the cycle rule: its directory."""
    return str(rel.parent)


def tree_problems(repo: pathlib.Path) -> tuple[list[str], int]:
    problems, edges, checked = [], {}, 0
    for top in ("core", "formulas", "app"):
        for path in sorted((repo / top).rglob("*.[ch]pp")):
            rel = pathlib.PurePosixPath(path.relative_to(repo).as_posix())
            checked += 1
            for target in INCLUDE.findall(path.read_text()):
                if not (repo / target).is_file():
                    continue  # a header of a library that happens to share the prefix
                t = pathlib.PurePosixPath(target)
                if top == "core" and t.parts[0] in ("app", "formulas"):
                    problems.append(f"{rel} includes {target}: core includes neither app nor formulas")
                if top == "formulas" and t.parts[0] == "app":
                    problems.append(f"{rel} includes {target}: formulas includes only core")
                if rel.parts[:2] == ("app", "cli") and t.parts[:2] == ("app", "editor"):
                    problems.append(f"{rel} includes {target}: the command line never includes the editor")
                a, b = folder_of(rel), folder_of(t)
                if a != b:
                    edges.setdefault(a, {}).setdefault(b, []).append(f"{rel} -> {target}")
    # Folder cycles: the strongly connected components of the folder graph (Tarjan).
    index, low, stack, on_stack, components, counter = {}, {}, [], set(), [], [0]

    def visit(v: str) -> None:
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on_stack.add(v)
        for w in edges.get(v, {}):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                components.append(sorted(component))

    for v in sorted(set(edges) | {w for e in edges.values() for w in e}):
        if v not in index:
            visit(v)
    for component in components:
        ties = [line for a in component for b in component if b in edges.get(a, {}) for line in edges[a][b]]
        problems.append(f"folders include each other around a loop: {', '.join(component)}\n    " + "\n    ".join(ties))
    return problems, checked


def main() -> int:
    repo = pathlib.Path(sys.argv[1])
    problems, tree_checked = tree_problems(repo)
    if tree_checked < 300:
        problems.append(f"only {tree_checked} files found under {repo}: is the path right?")
    root = repo / "app" / "editor"
    layer_of, shared_in = {}, {}
    for index, layer in enumerate(LAYERS):
        for folder in layer["folders"]:
            layer_of[folder] = index
            shared_in[folder] = layer["shared"]
    include = re.compile(r'^\s*#\s*include\s+"app/editor/(?:(\w+)/)?(\w+)\.hpp"', re.M)
    checked = 0
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
    print(f"{tree_checked} files checked for the tree's rules and {checked} for the editor's layers, "
          f"{len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
