"""A run's Result in a notebook: a short HTML table of its status and summary
(Result._repr_html_, which Jupyter shows for a Result at the end of a cell), the replay page
inline (Result.view(), the page `tribo view` writes, in an iframe through IPython's display),
and the trajectory as a pandas DataFrame (Result.to_pandas(); pandas is imported only then).
Not here: the page itself (study/view/, view/), plotting.
"""

import html as _html

# The summary's figures the table shows first, in this order, when present.
_LEADING = ("amplitude_pp", "period", "frequency", "stuck_fraction", "x_mean", "cycles")


def _number(value):
    if isinstance(value, float):
        return f"{value:.6g}"
    return str(value)


def _rows(summary):
    """(name, text) pairs of the summary's scalar figures: the leading ones, then the rest."""
    scalars = {k: v for k, v in summary.items() if isinstance(v, (int, float, str, bool))}
    for key in ("observed",):
        if isinstance(summary.get(key), dict):
            for k, v in summary[key].items():
                if isinstance(v, (int, float, str, bool)):
                    scalars.setdefault(k, v)
    ordered = [k for k in _LEADING if k in scalars]
    ordered += [k for k in scalars if k not in ordered]
    return [(k, _number(scalars[k])) for k in ordered]


def result_html(result):
    """The HTML table Jupyter shows for a Result: status, size, message, figures, warnings."""
    summary = result.summary
    cells = [("status", result.status),
             ("rows", str(len(result["t"]) if "t" in result.columns else 0)),
             ("columns", str(len(result.columns)))]
    if result.message:
        cells.append(("message", result.message))
    cells += _rows(summary)
    body = "".join(f"<tr><th style='text-align:left'>{_html.escape(k)}</th>"
                   f"<td style='text-align:left'>{_html.escape(v)}</td></tr>" for k, v in cells)
    warnings = "".join(f"<li>{_html.escape(w)}</li>" for w in result.warnings)
    if warnings:
        warnings = f"<p>warnings:</p><ul>{warnings}</ul>"
    return f"<table><caption>tribo.Result</caption>{body}</table>{warnings}"


def view_html(result, height=600, frame_cap=20000):
    """The replay page as an iframe element (the whole page in its srcdoc: no files, no server)."""
    page = result._view_page(frame_cap)
    return (f"<iframe srcdoc=\"{_html.escape(page, quote=True)}\" "
            f"style='width:100%;height:{int(height)}px;border:0'></iframe>")


def view(result, height=600, frame_cap=20000):
    """Result.view(): the replay page inline in a notebook (an IPython.display.HTML)."""
    from IPython.display import HTML  # only in a notebook or IPython
    return HTML(view_html(result, height, frame_cap))


def to_pandas(result):
    """Result.to_pandas(): the trajectory as a DataFrame, one column per recorded channel,
    indexed by time `t` (a copy; the Result's arrays stay as they are)."""
    try:
        import pandas
    except ImportError as e:  # pandas is optional: say what to install
        raise ImportError("Result.to_pandas needs pandas (Debian: python3-pandas)") from e
    data = {name: array.copy() for name, array in result.trajectory.items()}
    frame = pandas.DataFrame(data)
    if "t" in frame.columns:
        frame = frame.set_index("t")
    return frame


def attach(result_class):
    """Gives the extension's Result class the methods above."""
    result_class._repr_html_ = result_html
    result_class.view = view
    result_class.to_pandas = to_pandas
