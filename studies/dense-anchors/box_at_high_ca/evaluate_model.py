"""One model file judged the way the box studies judge it: a known G_s recovered from the N_a 8
and N_a 12 anchors (ten noise draws per truth), and the shipped sample calibrated. Imported by
trial_ca_box.py and family_with_ca_step.py; prints one line per recovery and the main job's
G_s and offset lines."""
import glob
import json
import os
import subprocess

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
RBCAL = os.environ.get("RBCAL", os.path.join(ROOT, "build", "bin", "rbcal"))
# Further options of both the recovery and the calibration, e.g. FIT_FLAGS=--hold-points.
FIT_FLAGS = os.environ.get("FIT_FLAGS", "").split()


def evaluate(family_file, out):
    for tier in ("n8", "n12"):
        anchors = sorted(path for ca in ("0.1", "0.5", "2", "8") for path in glob.glob(
            os.path.join(ROOT, "data", "library", "anchors", "results", f"{tier}_*_Ca{ca}_lambda5.result.json")))
        with open(os.path.join(out, f"recover_{tier}.txt"), "w") as log:
            subprocess.run([RBCAL, "recover", *anchors, "--surrogate", family_file, "--replicates", "10",
                            "-o", os.path.join(out, f"recover_{tier}.json"), *FIT_FLAGS], check=True, stdout=log,
                           stderr=subprocess.STDOUT)
    with open(os.path.join(out, "calibrate.txt"), "w") as log:
        subprocess.run([RBCAL, "calibrate", "--surrogate", family_file, "--no-plots", "-o", os.path.join(out, "report"), *FIT_FLAGS],
                       check=True, stdout=log, stderr=subprocess.STDOUT, cwd=ROOT)
    for tier in ("n8", "n12"):
        recovery = json.load(open(os.path.join(out, f"recover_{tier}.json")))
        for name, m in recovery["coverage"].items():
            print(f"recovery {tier} ({len(recovery['points'])} runs) {name}: {m['covered']} of {m['asked']}, "
                  f"estimate / truth {m['bias_factor']:.2f} +- {m['bias_factor_se']:.2f}, "
                  f"median width {m['median_width_factor']:.2f}")
    for line in open(os.path.join(out, "calibrate.txt")):
        if line.strip().startswith(("G_s", "offset_c")):
            print("main job:", line.strip())
