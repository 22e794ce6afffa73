"""Bad input raises exceptions that name the file, line and field, as the command line does."""
import pytest

import rbcal


def test_a_bad_rheometer_file_names_file_line_and_field(source):
    bad = source / "tests/calibration/data/bad_rheometer.csv"
    with pytest.raises(rbcal.RheometerDataError) as caught:
        rbcal.read_rheometer_csv(str(bad))
    e = caught.value
    assert isinstance(e, ValueError)
    assert e.file.endswith("bad_rheometer.csv")
    assert e.line == 5
    assert e.field == "phi"
    assert "'0.2x' is not a finite number" in str(e)


def test_a_missing_surrogate_raises_with_its_path(tmp_path):
    with pytest.raises(ValueError, match="nonexistent.json"):
        rbcal.Surrogate(str(tmp_path / "nonexistent.json"))


def test_a_malformed_surrogate_raises_format_error(tmp_path):
    bad = tmp_path / "surrogate.json"
    bad.write_text('{"schema": "rbcal.surrogate/1"}')
    with pytest.raises(rbcal.FormatError, match="surrogate.json: field"):
        rbcal.Surrogate(str(bad))


def test_invalid_options_name_the_option(source):
    with pytest.raises(ValueError, match="--method"):
        rbcal.calibrate(str(source / "tests/calibration/data/synthetic_rheometer.csv"),
                        rbcal.shipped_file("library/default/surrogate.json"), method="fit")


def test_infinite_or_nan_inputs_raise_instead_of_returning_nan():
    # predict(ca=inf) had returned arrays of NaN.
    s = rbcal.Surrogate(rbcal.shipped_file("library/default/surrogate.json"))
    for bad in ({"ca": float("inf")}, {"lam": float("inf")}, {"phi": float("nan")}):
        args = {"phi": 0.3, "ca": 0.1, "lam": 5.0}
        args.update(bad)
        with pytest.raises(ValueError, match="finite"):
            s.predict(**args)


def test_chain_diagnostics_refuse_a_nan_draw_instead_of_hanging():
    import numpy as np
    chains = np.random.default_rng(1).normal(size=(4, 100))
    chains[1, 17] = np.nan
    with pytest.raises(ValueError, match="draw 17 of chain 1 is not finite"):
        rbcal.chain_diagnostics(chains)
