#!/usr/bin/env python3
"""The Cusick tests of docs/validation.md §8: four fabrics of Matsudaira et
al. (2015) with and without their bending hysteresis, on two testers.

usage: cusick_matsudaira.py DRAPE OUT_DIR [--mesh SIZE_CM] [--fabrics ABCF]
                            [--testers bs,jis] [--shear G]

Writes one scene per fabric, tester and hysteresis to OUT_DIR, runs
`DRAPE run` and `DRAPE measure --drape-coefficient --json` on each, and
prints one row per run. Standard library only.

The fabrics' KES figures (B, 2HB, W, T) are those of M. Matsudaira,
T. Masuda, M. Wada, H. Yokura, "Shape Factor of Flared Skirts Compared with
That of Circular Fabrics", J. Textile Eng. 61(6) 69-73 (2015),
doi:10.4188/jte.61.69, Table 1, as reprinted in
github.com/antonbj3/3fold-motion-engine (src/motion_engine/cloth/r6_setup.py,
lines 25-28). The membrane is assumed (the reprint gives no tensile or shear
figures): E h = 9807 N/m in warp and weft (EMT 5 % at KES-FB1's 500 gf/cm),
nu12 = 0.2, and with --shear G the in-plane shear rigidity G in gf/(cm deg)
(KES-FB1's unit; without it the membrane is isotropic, G h = E h / 2.4).
"""
import json
import subprocess
import sys
import time
from pathlib import Path

# id: name, B [gf cm^2/cm], 2HB [gf cm/cm], W [mg/cm^2], T [mm], DC [%], nodes
FABRICS = {
    "A": ("cotton broadcloth", 0.118, 0.124, 12.38, 0.497, 82.9, 2),
    "B": ("wool tropical", 0.067, 0.033, 16.29, 0.407, 49.8, 5),
    "C": ("polyester tropical", 0.077, 0.029, 11.65, 0.340, 50.7, 5),
    "F": ("polyester faille", 0.019, 0.007, 10.43, 0.226, 28.3, 7),
}
# tester: specimen radius, disc radius [cm]
TESTERS = {"bs": (15.0, 9.0), "jis": (12.7, 6.35)}
TENSILE = 9807.0  # E h [N/m]


def scene(fabric, tester, hysteresis, mesh_cm, shear=None):
    name, b, two_hb, w, t, _, _ = FABRICS[fabric]
    radius, disc = TESTERS[tester]
    bending = {"model": "linear", "rigidity": f"{b} gf*cm^2/cm"}
    if hysteresis:
        bending["hysteresis"] = f"{two_hb} gf*cm/cm"
    h = t * 1e-3
    if shear is None:
        membrane = {"youngs_modulus": f"{TENSILE / h} Pa", "poisson_ratio": 0.2}
    else:  # G [gf/(cm deg)] per width and degree: G12 h = G * 0.980665 N/m * 180/pi
        g12 = shear * 0.980665 * 180 / 3.141592653589793 / h
        membrane = {"membrane": {"E1": f"{TENSILE / h} Pa", "E2": f"{TENSILE / h} Pa",
                                 "nu12": 0.2, "G12": f"{g12} Pa"}}
    result = {
        "drape_scene": 1,
        "name": f"Cusick test of Matsudaira et al.'s {name} ({tester})",
        "fabric": {
            "outline": {"disk": {"radius": f"{radius} cm"}},
            "mesh": {"size": f"{mesh_cm} cm"},
            "imperfection": {"amplitude": "0.5 mm", "seed": 1},
        },
        "material": {
            "thickness": f"{t} mm",
            "areal_density": f"{w * 10} g/m^2",  # 1 mg/cm^2 = 10 g/m^2
            "bending": bending,
        },
        "supports": [{"name": "discs", "fix": "clamp",
                      "select": {"circle": {"center": [0, 0], "radius": f"{disc} cm"}}}],
        "stages": [{"name": "hang", "kind": "gravity"}],
    }
    result["material"].update(membrane)
    return result


def main():
    args = sys.argv[1:]
    if len(args) < 2:
        sys.exit(__doc__)
    drape, out = args[0], Path(args[1])
    mesh = float(args[args.index("--mesh") + 1]) if "--mesh" in args else 1.0
    fabrics = args[args.index("--fabrics") + 1] if "--fabrics" in args else "ABCF"
    testers = args[args.index("--testers") + 1].split(",") if "--testers" in args else ["bs"]
    shear = float(args[args.index("--shear") + 1]) if "--shear" in args else None
    out.mkdir(parents=True, exist_ok=True)
    print("fabric tester 2HB mesh_cm G status seconds DC nodes DC_published nodes_published")
    for tester in testers:
        for fabric in fabrics:
            for hysteresis in (False, True):
                tag = f"{fabric}-{tester}-{'2hb' if hysteresis else 'elastic'}-{mesh:g}cm"
                path = out / f"{tag}.json"
                path.write_text(json.dumps(scene(fabric, tester, hysteresis, mesh, shear), indent=1))
                start = time.monotonic()
                run = subprocess.run([drape, "run", str(path), "-o", str(out / tag), "--quiet",
                                      "--time-limit", "120"],
                                     capture_output=True, text=True)
                seconds = time.monotonic() - start
                result = json.loads((out / tag / "result.json").read_text())
                measured = subprocess.run(
                    [drape, "measure", str(out / tag), "--drape-coefficient", "--json"],
                    capture_output=True, text=True)
                dc, nodes = "-", "-"
                if measured.returncode == 0:
                    m = json.loads(measured.stdout)
                    dc, nodes = f"{m['drape_coefficient']:.3f}", str(m["nodes"])
                published = FABRICS[fabric]
                print(f"{fabric} {tester} {'yes' if hysteresis else 'no'} {mesh:g} {shear or '-'} "
                      f"{result['status']}(rc{run.returncode}) {seconds:.1f} {dc} {nodes} "
                      f"{published[5] / 100:.3f} {published[6]}", flush=True)


if __name__ == "__main__":
    main()
