#!/usr/bin/env python3
"""The include graph points one way (docs/ARCHITECTURE.md, "Layers").

engine/ includes nothing of liquid/; the public headers (include/) include only public headers;
each internal folder of liquid/ includes only itself and the folders below it:

    scene  <  physics  <  analysis  <  solver  <  render, export  <  node.cpp

Usage: include_layers.py SOURCE_DIR. Prints one line per wrong include and exits 1, else 0.
"""
import pathlib
import re
import sys

LIQUID_LAYERS = ["scene", "physics", "analysis", "solver", "render", "export"]
RANK = {"scene": 0, "physics": 1, "analysis": 2, "solver": 3, "render": 4, "export": 4}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def public(root, target):
    return (root / "include" / target).is_file()


def problems(root):
    for path in sorted(root.glob("include/**/*.h")):
        for target in INCLUDE.findall(path.read_text()):
            if not public(root, target):
                yield f"{path.relative_to(root)}: includes {target}, which is not a public header"
    for path in sorted(list(root.glob("engine/**/*.cpp")) + list(root.glob("engine/**/*.h"))):
        for target in INCLUDE.findall(path.read_text()):
            if target.startswith("liquid/"):
                yield f"{path.relative_to(root)}: the engine includes {target}"
    for layer in LIQUID_LAYERS:
        for path in sorted(list((root / "liquid" / layer).glob("*.cpp")) + list((root / "liquid" / layer).glob("*.h"))):
            for target in INCLUDE.findall(path.read_text()):
                parts = target.split("/")
                if parts[0] != "liquid" or public(root, target) or len(parts) < 3:
                    continue
                if parts[1] != layer and RANK.get(parts[1], 99) >= RANK[layer]:
                    yield f"{path.relative_to(root)}: liquid/{layer} includes {target}, a folder above or beside it"


def main():
    root = pathlib.Path(sys.argv[1]).resolve()
    found = list(problems(root))
    for line in found:
        print(line)
    checked = len(list(root.glob("liquid/*/*.cpp")))
    if checked < 20:
        print(f"only {checked} sources found under {root}/liquid: wrong folder?")
        return 1
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
