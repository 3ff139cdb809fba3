#!/usr/bin/env python3
"""Tabulate the result folders of a validation study (docs/validation.md).

usage: summarize.py block STUDY_DIR      block drapes: modes, pivots, events
       summarize.py first STUDY_DIR      first load step: lambda and every ||R||/||R0||
       summarize.py loop  STUDY_DIR      folds: loop height (highest midsurface z)
       summarize.py runs  RESULT_DIR...  one line per `drape run` result folder
Standard library only; reads each run's scene.json and result/result.json.
"""
import json
import math
import sys
from pathlib import Path

INCH = 0.0254


def load(run):
    res = json.load(open(run / "result" / "result.json")) if (run / "result" / "result.json").exists() \
        else json.load(open(run / "result.json"))
    return res


SYMMETRIES = {  # name: image of node (i, j) on an n x n mesh
    "mx": lambda i, j, n: (n - i, j),       # x -> -x
    "my": lambda i, j, n: (i, n - j),       # y -> -y
    "d": lambda i, j, n: (j, i),            # x <-> y
    "a": lambda i, j, n: (n - j, n - i),    # x <-> -y
    "r90": lambda i, j, n: (n - j, i),      # quarter turn
    "r180": lambda i, j, n: (n - i, n - j), # half turn
}


def block_metrics(res):
    """Centre, edge-midpoint and corner sags [m] and, per symmetry of the square,
    max |z - z o g| over the nodes relative to the largest |z|, from final.positions."""
    scene = res["scene_resolved"]
    nx, ny = scene["fabric"]["mesh"]["elements"]
    pos = res["final"]["positions"]
    z = lambda i, j: pos[j * (nx + 1) + i][2]
    sag = -z(nx // 2, ny // 2)
    edges = [-z(nx, ny // 2), -z(0, ny // 2), -z(nx // 2, ny), -z(nx // 2, 0)]  # E W N S
    corners = [-z(0, 0), -z(nx, 0), -z(nx, ny), -z(0, ny)]
    zmax = max(abs(p[2]) for p in pos)
    asym = {}
    for name, g in SYMMETRIES.items():
        asym[name] = max(abs(z(i, j) - z(*g(i, j, nx))) for j in range(ny + 1) for i in range(nx + 1)) / zmax
    return sag, edges, corners, asym


def symmetry_class(asym, threshold=1e-2):
    """The symmetry group the drape keeps (to `threshold` of its largest |z|)."""
    keep = {k for k, v in asym.items() if v < threshold}
    if {"mx", "my", "d", "a"} <= keep:
        return "D4"
    if {"mx", "my"} <= keep:
        return "D2 (mirrors x, y)"
    if {"d", "a"} <= keep:
        return "D2 (diagonals)"
    if "r90" in keep:
        return "C4"
    if "r180" in keep:
        return "C2"
    mirrors = sorted(keep & {"mx", "my", "d", "a"})
    return ("mirror " + ",".join(mirrors)) if mirrors else "none"


def block(study):
    study = Path(study)
    spec = json.load(open(study / "study.json"))
    runs = spec.get("list")
    print("| run | settings | status | steps | iters | 1st step: lambda, iters | final neg. pivots (max on path) | events | centre sag [in] | edge sags E W N S [in] | corner sags [in] | mirror asym. / max abs z | symmetry kept (1e-2) | wall [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for k, d in enumerate(sorted((study / "runs").iterdir())):
        res = load(d)
        st = runs[k] if runs else {}
        short = ", ".join(f"{key.split('.')[-1]}={json.dumps(v)}" for key, v in st.items() if "supports[1]" not in key and "supports[3]" not in key and "supports[0]" not in key)
        if not res["steps"]:
            print(f"| {d.name} | {short} | {res['status']} | 0 | | | | | | | | | | |")
            continue
        s1 = res["steps"][0]
        maxpiv = max(s["negative_pivots"] for s in res["steps"])
        ev = res["stability_events"]
        evs = "; ".join(f"{e['kind']} λ={e['lambda']:.3g} {e['negative_pivots_before']}->{e['negative_pivots_after']} {e['branch']}" for e in ev[:3])
        if len(ev) > 3:
            evs += f"; … ({len(ev)} in all)"
        line = f"| {d.name} | {short} | {res['status']} (λ={res['steps'][-1]['lambda']:.3g}) | {res['counts']['steps']} | {res['counts']['iterations']} | {s1['lambda']:.3e}, {s1['iterations']} | {res['steps'][-1]['negative_pivots']} ({maxpiv}) | {evs or '—'} |"
        if res.get("final") and "positions" in res["final"]:
            sag, edges, corners, asym = block_metrics(res)
            worst = max(asym[k] for k in ("mx", "my", "d", "a"))
            line += f" {sag/INCH:.4f} | {' '.join(f'{e/INCH:.4f}' for e in edges)} | {' '.join(f'{e/INCH:.3f}' for e in corners)} | {worst:.1e} | {symmetry_class(asym)} |"
        else:
            line += " | | | | |"
        line += f" {res['timing']['total_s']:.2f} |"
        print(line)


def loop(study):
    study = Path(study)
    spec = json.load(open(study / "study.json"))
    runs = spec.get("list")
    print("| run | settings | status | steps | iters | loop height [cm] | fold probe z [cm] | max curvature [1/cm] | final neg. pivots | events | wall [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for k, d in enumerate(sorted((study / "runs").iterdir())):
        res = load(d)
        st = runs[k] if runs else {}
        short = ", ".join(f"{key.split('.')[-1]}={json.dumps(v)}" for key, v in st.items())
        one(d.name, short, res)


def one(name, short, res):
    if not res["steps"]:
        print(f"| {name} | {short} | {res['status']} | 0 | | | | | | | |")
        return
    zmax = max(p[2] for p in res["final"]["positions"])
    fold = res["final"]["probes"].get("fold", [math.nan] * 3)[2]
    kmax = res.get("bending", {}).get("max_curvature", math.nan)
    evs = "; ".join(f"{e['kind']} λ={e['lambda']:.3g} {e['negative_pivots_before']}->{e['negative_pivots_after']} {e['branch']}" for e in res["stability_events"][:3])
    stages = " + ".join(str(s["steps"]) for s in res["stages"])
    print(f"| {name} | {short} | {res['status']} | {res['counts']['steps']} ({stages}) | {res['counts']['iterations']} | {100*zmax:.3f} | {100*fold:.3f} | {kmax/100:.3f} | {res['steps'][-1]['negative_pivots']} | {evs or '—'} | {res['timing']['total_s']:.2f} |")


def runs(dirs):
    print("| result | status | steps | iters | loop height [cm] | fold probe z [cm] | max curvature [1/cm] | final neg. pivots | events | wall [s] |")
    for d in dirs:
        res = load(Path(d))
        one(Path(d).name, "", res)
    for d in dirs:
        res = load(Path(d))
        print(d, "probes [cm]:", {k: [round(100 * x, 3) for x in v] for k, v in res["final"]["probes"].items()})


def first(study):
    study = Path(study)
    spec = json.load(open(study / "study.json"))
    runs = spec.get("list")
    for k, d in enumerate(sorted((study / "runs").iterdir())):
        res = load(d)
        st = runs[k] if runs else {}
        short = ", ".join(f"{key.split('.')[-1]}={json.dumps(v)}" for key, v in st.items() if "supports" not in key)
        if not res["steps"]:
            print(f"{d.name} ({short}): no converged step ({res['status']})")
            continue
        s = res["steps"][0]
        print(f"{d.name} ({short}): lambda {s['lambda']:.4e}, {s['iterations']} iterations, "
              f"||R||/||R0||: {' '.join(f'{r:.3e}' for r in s['residuals'])} ({s['converged_by']})")


if __name__ == "__main__":
    {"block": lambda a: block(a[0]), "first": lambda a: first(a[0]), "loop": lambda a: loop(a[0]), "runs": runs}[sys.argv[1]](sys.argv[2:])
