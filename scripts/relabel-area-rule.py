#!/usr/bin/env python3
"""Adds the area rule cells.skalak_c_per_Ca to case results that were run before the rule
existed, where the rule gives the C they ran with (C = max(skalak_c, per_Ca * Ca) equal to
their skalak_c), so that they join a library of rule cases (docs/library.md, "Area
incompressibility at high Ca"). Each relabelled file says so in provenance.relabelled.
Files that already carry the field are left alone; a file whose C the rule would change
is refused (it must be run again).

Usage: python3 scripts/relabel-area-rule.py PER_CA RESULT.json...   (e.g. 125)
"""
import json
import sys


def main():
    per_ca = float(sys.argv[1])
    changed = 0
    for path in sys.argv[2:]:
        with open(path) as f:
            case = json.load(f)
        cells = case["cells"]
        if "skalak_c_per_Ca" in cells:
            continue
        c, ca = cells["skalak_c"], case["params"]["Ca"]
        if max(c, per_ca * ca) != c:
            sys.exit(f"{path}: the rule gives C {per_ca * ca:g} at Ca {ca:g}, not the {c:g} it ran with: run it again")
        cells["skalak_c_per_Ca"] = per_ca
        case.setdefault("provenance", {})["relabelled"] = (
            f"cells.skalak_c_per_Ca {per_ca:g} added after the run (scripts/relabel-area-rule.py): "
            f"the membrane ran with C = max({c:g}, {per_ca:g} Ca) = {c:g} at this Ca")
        with open(path, "w") as f:
            json.dump(case, f, indent=1)
            f.write("\n")
        changed += 1
    print(f"relabelled {changed} of {len(sys.argv) - 2} file(s)")


if __name__ == "__main__":
    main()
