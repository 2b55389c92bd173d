"""scripts/plot_stability.sh map: a stability map from a `tribo sweep --analysis modes`
results.csv. Where the growth rate changes sign the zero contour (the stability boundary) is
drawn in black; where it does not, nothing is drawn and the title says so; gnuplot reports
no error either way. Black pixels are counted with PIL (the frame and tics are black in
both, the boundary only in the first). Exit 0 pass, 1 fail, 77 skipped (no gnuplot)."""
import os
import shutil
import subprocess
import sys

from PIL import Image


def results(path, rate):
    """A 9 x 7 grid over (mu, c): growth rate rate(mu, c)."""
    with open(path, "w") as f:
        f.write("point,mu,c,status,max_growth_rate,frequency,unstable_modes,warnings,message\n")
        p = 0
        for i in range(9):
            for j in range(7):
                mu, c = 0.3 + 0.075 * i, 0.5 * j
                f.write(f"{p},{mu},{c},complete,{rate(mu, c)},1.0,0,,\n")
                p += 1


def dark_pixels(png):
    im = Image.open(png).convert("RGB")
    return sum(1 for r, g, b in im.getdata() if r < 60 and g < 60 and b < 60)


def plot(source, work, name, rate):
    csv = os.path.join(work, name + ".csv")
    png = os.path.join(work, name + ".png")
    results(csv, rate)
    r = subprocess.run(["bash", os.path.join(source, "scripts", "plot_stability.sh"), "map", png, csv],
                       capture_output=True, text=True, timeout=60)
    if r.returncode != 0 or "gnuplot>" in r.stderr or not os.path.exists(png):
        print(f"FAIL {name}: exit {r.returncode}\n{r.stderr}")
        sys.exit(1)
    return dark_pixels(png)


def main():
    source, work = sys.argv[1], sys.argv[2]
    if shutil.which("gnuplot") is None:
        print("SKIP: no gnuplot")
        sys.exit(77)
    os.makedirs(work, exist_ok=True)
    crossing = plot(source, work, "crossing", lambda mu, c: 10 * (mu - 0.6) - 0.2 * c)
    stable = plot(source, work, "stable", lambda mu, c: -1 - mu - c)
    unstable = plot(source, work, "unstable", lambda mu, c: 1 + mu + c)
    print(f"dark pixels: crossing {crossing}, stable {stable}, unstable {unstable}")
    # The boundary runs across the whole map height (~450 px) in a 2.5 px line.
    if not crossing > max(stable, unstable) + 600:
        print("FAIL: no boundary drawn where the growth rate changes sign")
        sys.exit(1)
    print("PASS")


main()
