"""The paper's Fig. 4 from Python: the box on the belt (Table 1) with the proposed law
(roh_yoo), whose oscillation grows into a stick-slip limit cycle, against the RecurDyn law,
whose does not. Writes fig4_belt.png (matplotlib, Debian's python3-matplotlib).

    PYTHONPATH=build/python python3 examples/fig4_belt.py [OUT.png]
"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402

import tribo  # noqa: E402

BELT = pathlib.Path(__file__).resolve().parents[1] / "scenes" / "belt.yaml"
out = sys.argv[1] if len(sys.argv) > 1 else "fig4_belt.png"

fig, ax = plt.subplots(figsize=(8, 4))
for law, style in (("roh_yoo", "-"), ("recurdyn", "--")):
    result = tribo.load_scene(BELT, set={"friction": law}).run()
    ax.plot(result["t"], result["box.x"], style, lw=0.8, label=law)
    s = result.summary
    print(f"{law}: {result.status}, box.x peak-to-peak {s['amplitude_pp']:.4f} m "
          f"(mean of the last {s['cycles_used']} cycles)" if s["oscillating"] else
          f"{law}: {result.status}, no oscillation")
ax.set_xlabel("time [s]")
ax.set_ylabel("box displacement x [m]")
ax.set_title("Box on a moving belt (Roh & Yoo 2007, Fig. 4)")
ax.legend()
fig.tight_layout()
fig.savefig(out, dpi=120)
print("wrote", out)
