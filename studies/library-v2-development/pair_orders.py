#!/usr/bin/env python3
"""What the N_a 6 / N_a 8 pairs of library v2 say about the order of the resolution error.

For every design point run at both resolutions (data/library/v2/n6 and n8): the raw eta_re,
the ratio (eta_6 - 1) / (eta_8 - 1) of the particle contributions, and the lowest order p
for which the Richardson estimate eta_8 + (eta_8 - eta_6) / ((8/6)^p - 1) keeps eta_re > 1
(a continuum suspension is more viscous than its plasma). Usage, from the repository root:
    python3 studies/library-v2-development/pair_orders.py [COARSE_LIBRARY FINE_LIBRARY]
"""
import glob
import json
import math
import os
import sys


def results(folder):
    out = {}
    for path in glob.glob(os.path.join(folder, "cases", "*.json")):
        case = json.load(open(path))
        out[os.path.basename(path)[:-5]] = case
    return out


def main():
    coarse_dir, fine_dir = (sys.argv[1:3] if len(sys.argv) >= 3 else ("data/library/v2/n6", "data/library/v2/n8"))
    coarse, fine = results(coarse_dir), results(fine_dir)
    n_c = next(iter(coarse.values()))["numerics"]["N_a"]
    n_f = next(iter(fine.values()))["numerics"]["N_a"]
    r = n_f / n_c
    print(f"{'point':34s} {'phi':>6s} {'eta_' + str(n_c):>8s} {'eta_' + str(n_f):>8s} "
          f"{'(eta_c-1)/(eta_f-1)':>20s} {'lowest p':>9s}")
    for name in sorted(fine, key=lambda k: fine[k]["params"]["phi"]):
        if name not in coarse:
            continue
        e_c = coarse[name]["result"]["eta_re"]
        e_f = fine[name]["result"]["eta_re"]
        ratio = (e_c - 1.0) / (e_f - 1.0)
        # eta_f - (e_c - e_f) / (r^p - 1) > 1  <=>  r^p - 1 > (e_c - e_f) / (e_f - 1)
        need = (e_c - e_f) / (e_f - 1.0)
        p_min = math.log(1.0 + need) / math.log(r) if need > 0 else 0.0
        print(f"{name:34s} {fine[name]['params']['phi']:6.3f} {e_c:8.3f} {e_f:8.3f} {ratio:20.3f} {p_min:9.2f}")


if __name__ == "__main__":
    main()
