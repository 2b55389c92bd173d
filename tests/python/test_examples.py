"""The examples run: the roh_yoo fit recovers the parameters of the curve its measurement
was made from (a known truth plus 0.002 rms noise) to within what that noise allows."""
import importlib.util
import pathlib

import pytest


def load_example(source_dir, name):
    spec = importlib.util.spec_from_file_location(name, source_dir / "examples" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.mark.parametrize("seed", [1, 7, 42])
def test_fit_recovers_the_truth(source_dir, seed):
    example = load_example(pathlib.Path(source_dir), "fit_roh_yoo")
    truth, fitted, rms = example.main(seed)
    # 70 points at 0.002 noise: the residual is the noise, the levels good to ~1e-3 and
    # the decay base (seen through the 0.11 drop over ~2 m/s) to a few percent.
    assert rms == pytest.approx(0.002, rel=0.3)
    assert fitted[0] == pytest.approx(truth[0], abs=5e-3)
    assert fitted[1] == pytest.approx(truth[1], abs=5e-3)
    assert fitted[2] == pytest.approx(truth[2], rel=0.1)
