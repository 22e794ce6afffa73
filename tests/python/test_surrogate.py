"""rbcal.Surrogate against the command line's `rbcal surrogate predict` (which prints six
significant digits: equality to that precision is equality to round-off of the printout)."""
import re
import subprocess

import numpy as np
import pytest

import rbcal


def cli_predict(exe, surrogate, phi, ca, lam):
    out = subprocess.run([exe, "surrogate", "predict", surrogate, "--phi", str(phi), "--ca", str(ca),
                          "--lambda", str(lam)], check=True, capture_output=True, text=True).stdout
    number = r"(-?[0-9.]+(?:e[-+]?[0-9]+)?)"
    eta, sd = re.search(r"eta_re\s+" + number + r" \+- " + number, out).groups()
    d_phi = re.search(r"d eta_re / d phi\s+" + number, out).group(1)
    d_ca = re.search(r"d eta_re / d ln Ca\s+" + number, out).group(1)
    return float(eta), float(sd), float(d_phi), float(d_ca)


def test_predictions_equal_the_command_line(exe):
    path = rbcal.shipped_file("library/default/surrogate.json")
    s = rbcal.Surrogate(path)
    phi = np.array([0.1, 0.25, 0.4])
    ca = np.array([0.02, 0.1, 0.5])
    p = s.predict(phi, ca, 5.0)
    assert p["eta_re"].shape == (3,)
    for i in range(3):
        eta, sd, d_phi, d_ca = cli_predict(exe, path, phi[i], ca[i], 5.0)
        assert p["eta_re"][i] == pytest.approx(eta, rel=1e-5)
        # The command line prints the sd to 3 significant digits: half a unit in the last.
        assert p["sd"][i] == pytest.approx(sd, abs=0.5 * 10 ** (np.floor(np.log10(sd)) - 2) * 1.0001)
        assert p["d_phi"][i] == pytest.approx(d_phi, rel=1e-5)
        assert p["d_ln_ca"][i] == pytest.approx(d_ca, rel=1e-5)


def test_inputs_broadcast_and_the_range_is_reported():
    s = rbcal.Surrogate(rbcal.shipped_file("library/default/surrogate.json"))
    p = s.predict(np.linspace(0.1, 0.4, 4)[:, None], np.array([0.05, 0.5]), 1.0)
    assert p["eta_re"].shape == (4, 2)
    assert np.all(np.diff(p["eta_re"], axis=1) < 0)  # shear thinning at every phi
    lo, hi = s.range["phi"]
    assert lo < 0.1 and hi > 0.4
    assert not s.predict(0.9, 0.1, 5.0)["inside_hull"]
