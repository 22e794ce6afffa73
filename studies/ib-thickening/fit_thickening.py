#!/usr/bin/python3
"""How much thicker the immersed boundary makes a body, measured on rigid bodies of known
intrinsic viscosity: python3 studies/ib-thickening/fit_thickening.py

For each body, eta_sp / phi at N_a is read as X_N = X_inf * B * f(c / N_a), where X_inf is the
unbounded continuum value (Einstein's 5/2 for the sphere; Jeffery's rolling value for the
spheroid), B the box's own raise (walls and periodic images), measured by the same body at
N_a 8 in a box twice as large in every direction (X(L) = X_inf (1 + k / L^3)), and f the
mapping's form:
  volume    the body's volume thickened by delta (Steiner: 1 + (S d + M d^2 + 4 pi d^3 / 3) / V)
  diameter  (1 + delta / b)^3: the size, not the volume
  body      (spheroid) the rigid body with semi-axes (a + delta, b + delta): the exact value of a
            rigid spheroid that size, per the nominal body's volume
  shell     1 + s delta: an additive shell in eta_sp, linear in dx (s from the data)
For each form: the c that each N_a alone needs, and one c for all with its RMS residual.
"""
import functools, glob, json, math, os, re

import numpy

here = os.path.dirname(os.path.abspath(__file__))

def jeffery_integral(a, b, n=4001):
    # J' = int_0^1 2 a t^4 / (a^2 + (b^2 - a^2) t^2)^3 dt (solver/membrane/rigid_spheroid_viscosity.hpp),
    # Simpson on pieces graded towards t = 0, where a thin body's integrand peaks.
    f = lambda t: 2 * a * t ** 4 / (a * a + (b * b - a * a) * t * t) ** 3
    edges = sorted(set([0.0, 1.0] + [min(a / b, 0.5) * 2.0 ** k for k in range(-8, 1)]))
    total = 0.0
    for lo, hi in zip(edges, edges[1:]):
        t = numpy.linspace(lo, hi, n)
        w = numpy.ones(n); w[1:-1:2] = 4; w[2:-1:2] = 2
        total += (hi - lo) / (n - 1) / 3 * numpy.dot(w, f(t))
    return total

@functools.lru_cache(maxsize=None)
def rolling(eps, b=1.0):
    return 1.0 / (eps * b ** 4 * jeffery_integral(eps * b, b))

def spheroid_steiner(eps, n=4000):
    # surface area S and integrated mean curvature M of the spheroid (b = 1, polar semi-axis eps)
    S = M = 0.0
    h = math.pi / n
    for i in range(n):
        t = (i + 0.5) * h
        x, z = math.sin(t), eps * math.cos(t)
        dx, dz = math.cos(t), -eps * math.sin(t)
        ddx, ddz = -math.sin(t), -eps * math.cos(t)
        ds = math.hypot(dx, dz)
        k1 = abs(dx * ddz - dz * ddx) / ds ** 3
        k2 = abs(dz) / (x * ds)
        S += 2 * math.pi * x * ds * h
        M += 2 * math.pi * x * ds * h * 0.5 * (k1 + k2)
    return S, M, 4.0 / 3.0 * math.pi * eps

def steiner_factor(S, M, V):
    return lambda d: 1.0 + (S * d + M * d * d + 4.0 * math.pi * d ** 3 / 3.0) / V

def load(pattern):
    runs = {}
    for path in glob.glob(os.path.join(here, "results", pattern)):
        r = json.load(open(path))
        res = r["result"]
        runs[os.path.basename(path)] = (r["numerics"]["N_a"], r["numerics"]["box"], (res["eta_re"] - 1.0) / res["phi_actual"],
                                        res["eta_re_sem"] / res["phi_actual"])
    return runs

def solve_c(target, f, n_a):
    lo, hi = -0.5, 3.0
    if (f(lo / n_a) - target) * (f(hi / n_a) - target) > 0: return float("nan")
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if (f(lo / n_a) - target) * (f(mid / n_a) - target) <= 0: hi = mid
        else: lo = mid
    return 0.5 * (lo + hi)

def best_c(points, f):
    # least squares in ln X over c on a fine grid, then the RMS relative residual
    best = None
    for k in range(0, 1501):
        c = k / 500.0
        r = [math.log(x / f(c / n)) for n, x in points]
        rms = math.sqrt(sum(v * v for v in r) / len(r))
        if best is None or rms < best[1]: best = (c, rms, r)
    return best

def report(name, x_inf, tiers, big, forms, base_box):
    print(f"\n## {name}: X_inf {x_inf:.4f}")
    if big:
        (n_big, box_big, x_big, _), = big
        x8 = dict((n, x) for n, x, _ in tiers)[n_big]
        ratio = box_big[0] / base_box[0]
        # X(L) = X_inf f (1 + k / L^3): x8 / x_big = (1 + k) / (1 + k / ratio^3), with k for the base box
        q = x8 / x_big
        k = (q - 1.0) / (1.0 - q / ratio ** 3)
        B = 1.0 + k
        print(f"box: N_a {n_big} in the base box {x8:.4f}, in the box x{ratio:g} {x_big:.4f}: the base box raises eta_sp / phi by B = {B:.4f}")
    else:
        B = 1.0
        print("box: no larger-box run yet; B = 1")
    print("| N_a | eta_sp / phi | / (X_inf B) | " + " | ".join(f"c ({f})" for f in forms) + " |")
    print("|---" * (3 + len(forms)) + "|")
    for n, x, sem in tiers:
        cs = [solve_c(x / (x_inf * B), forms[f], n) for f in forms]
        print(f"| {n} | {x:.4f} +- {sem:.4f} | {x / (x_inf * B):.4f} | " + " | ".join(f"{c:.3f}" for c in cs) + " |")
    for f in forms:
        c, rms, r = best_c([(n, x / (x_inf * B)) for n, x, _ in tiers], forms[f])
        print(f"- one c for all, form {f}: c = {c:.3f}, RMS residual {100 * rms:.2f} %, residuals " +
              ", ".join(f"{100 * v:+.2f} %" for v in r))
    return B

def tiers_of(runs, box):
    return sorted((n, x, s) for (n, b, x, s) in runs.values() if b == box)

base = [6.0, 10.0, 8.0]
# The sphere: eta_sp / phi at N_a 6-16 in the base box (docs/validation.md, stresslet) plus
# the larger-box run of this study.
sphere = {f"sphere_n{n}": (n, base, x, 0.0) for n, x in [(6, 3.4489), (8, 3.1371), (10, 2.9774), (12, 2.8831), (16, 2.7733)]}
sphere.update(load("sphere_*.result.json"))
B_sphere = report("Sphere (5120 triangles, Ca_G 0.01)", 2.5, tiers_of(sphere, base),
       [v for v in sphere.values() if v[1] != base],
       {"volume": lambda d: (1 + d) ** 3, "shell": lambda d: 1 + 3 * d}, base)

eps = 0.328
S, M, V = spheroid_steiner(eps)
x_sph = rolling(eps)
body = lambda d: rolling((eps + d) / (1 + d)) / x_sph * ((eps + d) * (1 + d) ** 2) / eps
spheroid = load("spheroid_*.result.json")
B_spheroid = report(f"Rigid oblate spheroid, aspect ratio {eps}, rolling (S {S:.4f}, M {M:.4f}, V {V:.4f})", x_sph,
       tiers_of(spheroid, base), [v for v in spheroid.values() if v[1] != base],
       {"volume": steiner_factor(S, M, V), "diameter": lambda d: (1 + d) ** 3, "body": body,
        "shell": lambda d: 1 + 3 * d}, base)


# The red cell itself: no exact value, so the question is whether the rigid bodies' c at each
# N_a (with their box raise) moves every resolution to one continuum X_inf.
def c_per_n(x_inf, B, tiers, form):
    return {n: solve_c(x / (x_inf * B), form, n) for n, x, _ in tiers}

S_rbc, V_rbc, M_rbc = 8.716, 1.5605, 10.680  # the 1280-triangle Evans-Fung mesh at radius 1 (docs/library.md)
g_rbc = steiner_factor(S_rbc, M_rbc, V_rbc)
c_sphere = c_per_n(2.5, B_sphere, tiers_of(sphere, base), lambda d: (1 + d) ** 3)
c_spheroid = c_per_n(x_sph, B_spheroid, tiers_of(spheroid, base), steiner_factor(S, M, V))
B_rbc = 0.5 * (B_sphere + B_spheroid)
rbc = load("rbc_*.result.json")
# lambda 1 in the shear plane: whether the excess of the swinging cell at coarse resolution
# comes with the viscosity contrast (the inside viscosity spread over the kernel's width).
for lam, label, pattern in ((5, "rolling, Ca 0.01", "roll"), (5, "in the shear plane, Ca 1", "inplane"),
                            (1, "in the shear plane, Ca 1", "inplane")):
    tiers = sorted((n, x, s_) for name, (n, b, x, s_) in rbc.items()
                   if pattern in name and f"_lambda{lam}_" in name and b == base
                   and re.fullmatch(r"rbc_lambda[\d.]+_Ca[\d.]+_[a-z]+_n\d+\.result\.json", name))
    if not tiers:
        continue
    print(f"\n## Red cell, lambda {lam}, {label}: eta_sp / phi and the continuum value each N_a implies")
    print("| N_a | eta_sp / phi | X_inf with the sphere's c | X_inf with the spheroid's c | X_inf with c 0.75 |")
    print("|---|---|---|---|---|")
    for n, x, sem in tiers:
        cols = []
        for cs in (c_sphere, c_spheroid, {n: 0.75}):
            c = cs.get(n)
            cols.append(f"{x / (B_rbc * g_rbc(c / n)):.3f} (c {c:.3f})" if c is not None else "-")
        print(f"| {n} | {x:.4f} +- {sem:.4f} | " + " | ".join(cols) + " |")

# The red cell's own c: with no exact X_inf, fit c and X_inf together (one c for the runs
# used, X_inf the geometric mean that c leaves), over the finest runs; then what each fit,
# and the sphere's c, predict for the next resolution (written before that run finished).
def joint_fit(points, f):
    best = None
    for k in range(0, 1501):
        c = k / 1000.0
        logs = [math.log(x / f(c / n)) for n, x in points]
        x_inf = math.exp(sum(logs) / len(logs))
        rms = math.sqrt(sum((v - math.log(x_inf)) ** 2 for v in logs) / len(logs))
        if best is None or rms < best[2]: best = (c, x_inf, rms)
    return best

roll = sorted((n, x) for name, (n, b, x, s_) in rbc.items() if "roll" in name and "_lambda5_" in name and b == base)
if len(roll) >= 2:
    print("\n## Red cell, lambda 5, rolling, Ca 0.01: c and X_inf fitted together (volume form, box B divided out)")
    print("| runs | c | X_inf | RMS residual | predicted eta_sp / phi at N_a 16 |")
    print("|---|---|---|---|---|")
    pts = [(n, x / B_rbc) for n, x in roll if n <= 12]
    for lo in sorted({n for n, _ in pts})[:-1]:
        sel = [p for p in pts if p[0] >= lo]
        c, x_inf, rms = joint_fit(sel, g_rbc)
        print(f"| N_a {lo}-{sel[-1][0]} | {c:.3f} | {x_inf:.3f} | {100 * rms:.2f} % | {x_inf * B_rbc * g_rbc(c / 16):.4f} |")
    n12 = dict(roll).get(12)
    if n12 is not None:
        x12 = n12 / (B_rbc * g_rbc(c_sphere[12] / 12))
        print(f"| the sphere's c (0.608 at N_a 16), X_inf from N_a 12 | {c_sphere[16]:.3f} | {x12:.3f} | - | "
              f"{x12 * B_rbc * g_rbc(c_sphere[16] / 16):.4f} |")
