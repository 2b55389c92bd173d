"""A run's Result in a notebook: its HTML table carries the status and the summary's figures,
to_pandas() is the trajectory (the same numbers, indexed by time), save() writes the
trajectory `tribo run` writes, and view() is the page `tribo view` makes of the same run
(only the scratch folder's name differs); the example notebook examples/belt_notebook.ipynb
runs from top to bottom in a fresh kernel without an error."""
import html
import json
import os
import re
import subprocess
import sys

import numpy as np
import pytest

import tribo


@pytest.fixture(scope="module")
def run(belt):
    return tribo.load_scene(belt, set={"duration": 8}).run()


def test_the_html_table_shows_status_and_figures(run):
    page = run._repr_html_()
    assert "<th style='text-align:left'>status</th><td style='text-align:left'>complete</td>" in page
    s = run.summary
    for key in ("amplitude_pp", "period"):
        assert f"<th style='text-align:left'>{key}</th><td style='text-align:left'>{s[key]:.6g}</td>" in page


def test_to_pandas_is_the_trajectory(run):
    frame = run.to_pandas()
    assert frame.index.name == "t"
    np.testing.assert_array_equal(frame.index.to_numpy(), run["t"])
    assert list(frame.columns) == [c for c in run.columns if c != "t"]
    for c in frame.columns:
        np.testing.assert_array_equal(frame[c].to_numpy(), run[c])


def test_save_writes_what_tribo_run_writes(cli, belt, run, tmp_path):
    run.save(tmp_path / "py")
    subprocess.run([cli, "run", belt, "--set", "duration=8", "--out", str(tmp_path / "cli"),
                    "--quiet"], check=True, capture_output=True)
    assert (tmp_path / "py" / "trajectory.csv").read_bytes() == \
        (tmp_path / "cli" / "trajectory.csv").read_bytes()
    ours = json.loads((tmp_path / "py" / "summary.json").read_text())
    theirs = json.loads((tmp_path / "cli" / "summary.json").read_text())
    for key in ("status", "amplitude_pp", "period", "parameters"):
        assert ours[key] == theirs[key], key


def test_view_is_the_page_tribo_view_makes(cli, run, tmp_path):
    run.save(tmp_path)
    subprocess.run([cli, "view", str(tmp_path)], check=True, capture_output=True)
    cli_page = (tmp_path / "view.html").read_text()

    def strip(page):  # the run folder's name is the one difference
        return re.sub(r'\\?"run_dir\\?":\\?"[^"\\]*\\?"', "", page)

    framed = tribo._notebook.view_html(run, height=300)
    assert framed.startswith("<iframe srcdoc=\"") and "height:300px" in framed
    page = html.unescape(framed[len("<iframe srcdoc=\""):framed.index("\" style=")])
    assert strip(page) == strip(cli_page)
    assert "window.TRIBO_DATA" in page


@pytest.fixture
def kernel_dir(tmp_path):
    """A kernelspec that starts this interpreter (the one with tribo on its path)."""
    spec = tmp_path / "kernels" / "python3"
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": "Python 3 (tribo tests)", "language": "python"}))
    return tmp_path


def test_the_example_notebook_runs(source_dir, kernel_dir, monkeypatch):
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    monkeypatch.setenv("JUPYTER_PATH", str(kernel_dir))
    path = source_dir / "examples" / "belt_notebook.ipynb"
    nb = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(nb, timeout=300, kernel_name="python3",
                                     resources={"metadata": {"path": str(path.parent)}})
    client.execute()  # raises CellExecutionError naming the cell that failed
    outputs = [o for cell in nb.cells if cell.cell_type == "code" for o in cell.outputs]
    html_outputs = [o["data"]["text/html"] for o in outputs if "text/html" in o.get("data", {})]
    assert any("<caption>tribo.Result</caption>" in h for h in html_outputs)
    assert any(h.startswith("<iframe srcdoc=") for h in html_outputs)
    assert any("amplitude_pp" in h and "complete" in h for h in html_outputs)  # the sweep table
