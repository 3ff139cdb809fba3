#!/usr/bin/python3
"""Figure of docs/bending.md: the cotton strip fold with the nonlinear law and
its linear equivalent (final shapes), and the two laws with the curvature each
run reached. Needs Debian's python3-matplotlib (not part of the build).

  drape run resources/scenes/strip-convergence-80.json -o results/fold-nl
  drape run resources/scenes/strip-convergence-80-linear.json -o results/fold-lin
  scripts/plot_bending_report.py results/fold-nl results/fold-lin docs/images/cotton-strip-fold.png
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

PAPER = [1.33387, -2.23070, 2.36510, -1.08471, 0.17876]  # gf*cm/cm, K in 1/cm
VALID_TO = 2.5  # 1/cm
LINEAR_B = 0.589  # gf*cm^2/cm


def cotton(k):
    """The paper's law, continued with its end tangent beyond 2.5 1/cm."""
    if k <= VALID_TO:
        return sum(c * k ** (i + 1) for i, c in enumerate(PAPER))
    m_end = cotton(VALID_TO)
    slope = sum((i + 1) * c * VALID_TO ** i for i, c in enumerate(PAPER))
    return m_end + slope * (k - VALID_TO)


def centreline(result_dir):
    """Final (x, z) in cm of the strip's centre line: the mean over its width."""
    r = json.load(open(f"{result_dir}/result.json"))
    pos = r["final"]["positions"]
    columns = len(pos) // 2  # an n x 1 mesh: two rows of nodes
    xs = [100 * (pos[i][0] + pos[i + columns][0]) / 2 for i in range(columns)]
    zs = [100 * (pos[i][2] + pos[i + columns][2]) / 2 for i in range(columns)]
    return xs, zs, r["bending"]["max_curvature"] / 100


def main(nonlinear_dir, linear_dir, out):
    fig, (shape, law) = plt.subplots(1, 2, figsize=(11, 4.2), gridspec_kw={"width_ratios": [1.6, 1]})
    runs = [("nonlinear (paper's fit)", nonlinear_dir, "tab:red"), ("linear, B = 0.589", linear_dir, "tab:blue")]
    reached = {}
    for label, d, colour in runs:
        xs, zs, k_max = centreline(d)
        reached[label] = k_max
        shape.plot(xs, zs, "-", color=colour, label=f"{label}: crown {max(zs):.2f} cm")
    shape.axhline(-0.02445, color="0.5", lw=0.8)
    shape.set_xlabel("x [cm]")
    shape.set_ylabel("z [cm]")
    shape.set_aspect("equal")
    shape.set_title("20 x 1 cm cotton twill strip folded in half (80 x 1 elements)", fontsize=10)
    shape.legend(loc="upper right", fontsize=8)

    ks = [i * 0.02 for i in range(0, 201)]
    law.plot(ks, [cotton(k) for k in ks], color="tab:red", label="cotton, M = sum c_k K^k")
    law.plot(ks, [LINEAR_B * k for k in ks], color="tab:blue", label="linear, B = 0.589")
    law.axvspan(VALID_TO, 4, color="0.92", label="beyond the fit: end tangent")
    for (label, _, colour) in runs:
        law.axvline(reached[label], color=colour, ls="--", lw=1)
    law.text(reached[runs[0][0]] + 0.05, 0.1, f"largest K reached\n{reached[runs[0][0]]:.2f} 1/cm", fontsize=8)
    law.set_xlim(0, 4)
    law.set_ylim(0, 2.5)
    law.set_xlabel("K [1/cm]")
    law.set_ylabel("M [gf cm/cm]")
    law.set_title("bending laws, curvature each fold reached", fontsize=10)
    law.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
