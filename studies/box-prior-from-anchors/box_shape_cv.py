#!/usr/bin/python3
"""Does a box correction that depends on phi_eff and Ca carry to points it was not fitted on?

Reads the anchor table of a model build report (each anchor's N_a, phi_eff, beta and se, beta =
ln eta_run / ln eta_model - 1), fits beta by least squares with several shapes, and holds out in
turn each hematocrit row (phi_eff label 0.30 / 0.40 / 0.50), each Ca column (0.1 / 0.5 / 2 / 8) and
each resolution tier (N_a 8 / 12). Prints the root mean square of the held-out residuals per
shape, then the held-out rows' z-scores under the constant prior rebuilt without them (mean and
scatter of the other rows, the run's se added).

  python3 studies/box-prior-from-anchors/box_shape_cv.py data/library/default/build_report.txt
"""
import re
import sys

import numpy as np

SHAPES = {
    "constant": [],
    "phi": ["phi"],
    "ln Ca": ["lnca"],
    "phi + ln Ca": ["phi", "lnca"],
    "ln Ca + ln^2 Ca": ["lnca", "lnca2"],
    "phi + ln Ca + ln^2 Ca": ["phi", "lnca", "lnca2"],
    "phi + N_a tier": ["phi", "tier"],
}


def read_anchors(report):
    anchors, inside = [], False
    for line in open(report):
        if line.startswith("box correction from anchor runs"):
            inside = True
            continue
        if not inside:
            continue
        fields = line.split()
        if not fields or not fields[0].startswith("n") or "anchors:" in line:
            if anchors:
                break
            continue
        name = fields[0]
        label = re.search(r"phieff(0\.\d+)", name).group(1)
        ca = float(re.search(r"_Ca([0-9.]+)_", name).group(1))
        anchors.append({"name": name, "na": int(fields[1]), "phi_eff": float(fields[3]), "ca": ca, "row": label,
                        "beta": float(fields[-3]), "se": float(fields[-1])})
    if not anchors:
        sys.exit(f"{report}: no anchor table (the line 'box correction from anchor runs' and the rows below it)")
    return anchors


def design(anchors, terms):
    columns = [np.ones(len(anchors))]
    for term in terms:
        if term == "phi":
            columns.append(np.array([a["phi_eff"] - 0.45 for a in anchors]))
        elif term == "lnca":
            columns.append(np.log([a["ca"] for a in anchors]))
        elif term == "lnca2":
            columns.append(np.log([a["ca"] for a in anchors]) ** 2)
        elif term == "tier":
            columns.append(np.array([1.0 if a["na"] == 12 else 0.0 for a in anchors]))
    return np.column_stack(columns)


def held_out_residuals(x, y, groups):
    """Each group's residuals from the fit without it, by group in sorted order."""
    out = {}
    for key in sorted(set(groups)):
        train = np.array([g != key for g in groups])
        coef, *_ = np.linalg.lstsq(x[train], y[train], rcond=None)
        out[key] = y[~train] - x[~train] @ coef
    return out


def rms(values):
    return float(np.sqrt(np.mean(np.square(values))))


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    anchors = read_anchors(sys.argv[1])
    y = np.array([a["beta"] for a in anchors])
    rows = [a["row"] for a in anchors]
    print(f"{len(anchors)} anchors from {sys.argv[1]}")
    print(f"shape                    in sample  row out  Ca out  N_a out   rows {' / '.join(sorted(set(rows)))} out")
    for shape, terms in SHAPES.items():
        x = design(anchors, terms)
        coef, *_ = np.linalg.lstsq(x, y, rcond=None)
        by_row = held_out_residuals(x, y, rows)
        by_ca = held_out_residuals(x, y, [a["ca"] for a in anchors])
        by_tier = held_out_residuals(x, y, [a["na"] for a in anchors])
        print(f"{shape:24s} {rms(y - x @ coef):9.3f} {rms(np.concatenate(list(by_row.values()))):8.3f} "
              f"{rms(np.concatenate(list(by_ca.values()))):7.3f} {rms(np.concatenate(list(by_tier.values()))):8.3f}"
              f"   {' / '.join(f'{rms(r):.3f}' for r in by_row.values())}")
    print("\nheld-out row under the constant prior rebuilt without it (z = (beta - mean) / hypot(scatter, se)):")
    for key in sorted({a["row"] for a in anchors}):
        train = np.array([a["beta"] for a in anchors if a["row"] != key])
        mean, scatter = train.mean(), train.std(ddof=1)
        z = [(a["beta"] - mean) / np.hypot(scatter, a["se"]) for a in anchors if a["row"] == key]
        print(f"  phi_eff {key}: prior {mean:+.3f} +- {scatter:.3f}, z {min(z):+.2f} .. {max(z):+.2f}, "
              f"mean {np.mean(z):+.2f}, rms {np.sqrt(np.mean(np.square(z))):.2f} ({len(z)} runs)")


if __name__ == "__main__":
    main()
