#!/usr/bin/python3
"""Writes the shipped recipe's box_correction lists from the committed runs: as twins, the four
library twins already listed and every 8a twin of an N_a 8 anchor
(data/library/anchors/twins/results/NAME_h8[_seedK].result.json) paired with the 16a anchor of
the same seed when it exists, else with seed 1 (NAME.result.json); as anchors, every N_a 8 and
12 anchor in the 16a gap, seeds included (the N_a 16 ones are held out). Then rebuild:
  python3 studies/box-prior-from-anchors/recipe_lists.py
  ./build/bin/rbcal model build data/library/default/recipe.json -o data/library/default
"""
import glob
import json
import os
import re

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
RECIPE = os.path.join(ROOT, "data", "library", "default", "recipe.json")
ANCHORS = os.path.join(ROOT, "data", "library", "anchors")


def relative(path):
    return os.path.relpath(path, os.path.dirname(RECIPE))


recipe = json.load(open(RECIPE))
box = recipe["box_correction"]
twins = [t for t in box["twins"] if "/anchors/" not in t["library_box"]]
for small in sorted(glob.glob(os.path.join(ANCHORS, "twins", "results", "*_h8*.result.json"))):
    name, seed = re.match(r"(.*)_h8(_seed\d+)?\.result\.json$", os.path.basename(small)).groups()
    big = os.path.join(ANCHORS, "results", f"{name}{seed or ''}.result.json")
    if not os.path.exists(big):
        big = os.path.join(ANCHORS, "results", f"{name}.result.json")
    if os.path.exists(big):
        twins.append({"library_box": relative(small), "bigger_box": relative(big)})
box["twins"] = twins
box["anchors"] = [relative(f) for f in sorted(glob.glob(os.path.join(ANCHORS, "results", "n*.result.json")))
                  if not os.path.basename(f).startswith("n16_")]
with open(RECIPE, "w") as out:
    json.dump(recipe, out, indent=2)
    out.write("\n")
print(f"{len(twins)} twins, {len(box['anchors'])} anchors -> {relative(RECIPE)}")
