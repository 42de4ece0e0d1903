#!/usr/bin/env python3
"""Checks that cic's layers depend one way: every #include "cic/<layer>/..." in a
layer's sources and public headers names that layer or one below it.

    scripts/check-layers.py [ROOT]     exit 0: clean; 1: upward includes (listed)

The build runs it (target cic_layer_check, a dependency of every layer), so an
upward include fails the build; tests/layers/ shows it does.
"""
import pathlib
import re
import sys

# Each layer and the layers it may include, besides itself (README, "Architecture").
ALLOWED = {
    "core": set(),
    "tree": {"core"},
    "gp": {"tree", "core"},
    "nn": {"tree", "core"},
    "sim": {"core"},
    "io": {"gp", "nn", "sim", "tree", "core"},
    "experiments": {"io", "gp", "nn", "sim", "tree", "core"},
    "viz": {"sim", "core"},
    # The application: report < search < run < study < cli.
    "report": {"experiments", "io", "gp", "nn", "sim", "tree", "core"},
    "search": {"report", "experiments", "io", "gp", "nn", "sim", "tree", "core"},
    "run": {"search", "report", "viz", "experiments", "io", "gp", "nn", "sim", "tree", "core"},
    "study": {"run", "search", "report", "viz", "experiments", "io", "gp", "nn", "sim", "tree", "core"},
    "cli": {"study", "run", "search", "report", "viz", "experiments", "io", "gp", "nn", "sim", "tree", "core"},
}
# Where each layer's files live: its public headers and its sources.
def places(root, layer):
    yield root / "include" / "cic" / layer
    yield root / ("experiments" if layer == "experiments" else "src/" + layer)

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def violations(root):
    found = []
    for layer, allowed in ALLOWED.items():
        for place in places(root, layer):
            if not place.is_dir():
                continue
            for f in sorted(place.rglob("*")):
                if f.suffix not in (".hpp", ".cpp", ".h"):
                    continue
                for n, line in enumerate(f.read_text(errors="replace").splitlines(), 1):
                    m = INCLUDE.match(line)
                    if not m:
                        continue
                    path = m.group(1)
                    if path.startswith("src/") or path.startswith("experiments/"):
                        found.append(f"{f.relative_to(root)}:{n}: includes {path} by its source path; "
                                     "public headers are included as cic/<layer>/..., private ones by name")
                        continue
                    parts = path.split("/")
                    if len(parts) < 2 or parts[0] != "cic":
                        continue   # a private header beside the source
                    target = parts[1]
                    if target not in ALLOWED:
                        found.append(f"{f.relative_to(root)}:{n}: includes {path}: no layer {target}")
                    elif target != layer and target not in allowed:
                        found.append(f"{f.relative_to(root)}:{n}: layer {layer} includes {path} from layer "
                                     f"{target}, which it may not (allowed: {', '.join(sorted(allowed)) or 'none'})")
    return found


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
    found = violations(root)
    for v in found:
        print(v, file=sys.stderr)
    if found:
        print(f"check-layers: {len(found)} include(s) against the layer order", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
