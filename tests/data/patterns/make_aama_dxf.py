#!/usr/bin/python3
"""Writes AAMA / ASTM D6673 pattern files with ezdxf, an independent DXF
writer, for the pattern reader's tests (tests/io/dxf_pattern_reader_test.cc).

    make_aama_dxf.py OUT.dxf [--units mm|in|cm|text-metric|text-english|none]
                             [--variant good|open|crossing|bulge|no-grain]

Two pieces, FRONT and BACK, drawn in centimetres and written in the unit
asked for. FRONT: a 40 x 30 cm panel with a 5 x 4 cm cut-out (layer 11),
four notches (layer 4, short lines into the piece), a grain line at 30
degrees (layer 7), two drill holes (layer 13) and a fold line (layer 8).
BACK: a trapezoid with a vertical grain line, drawn as a 2-D POLYLINE.
"""
import argparse
import math

import ezdxf

CM_PER_UNIT = {"mm": 0.1, "in": 2.54, "cm": 1.0, "text-metric": 0.1, "text-english": 2.54, "none": 0.1}
INSUNITS = {"mm": 4, "in": 1, "cm": 5, "text-metric": 0, "text-english": 0, "none": 0}

FRONT = [(0, 0), (40, 0), (40, 30), (20, 32), (0, 30)]
FRONT_HOLE = [(10, 10), (15, 10), (15, 14), (10, 14)]
# (point on the cut line, inward normal)
FRONT_NOTCHES = [((10, 0), (0, 1)), ((40, 15), (-1, 0)), ((30, 31), (-0.1, -1)), ((0, 20), (1, 0))]
FRONT_DRILLS = [(25, 20), (30, 8)]
FRONT_FOLD = [(20, 0), (20, 32)]
GRAIN_FROM, GRAIN_LENGTH, GRAIN_DEG = (20, 15), 12.0, 30.0
BACK = [(0, 0), (36, 0), (32, 28), (4, 28)]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("out")
    parser.add_argument("--units", default="mm", choices=sorted(CM_PER_UNIT))
    parser.add_argument("--variant", default="good",
                        choices=["good", "open", "crossing", "bulge", "no-grain"])
    args = parser.parse_args()
    scale = 1.0 / CM_PER_UNIT[args.units]

    def u(p):
        return (p[0] * scale, p[1] * scale)

    doc = ezdxf.new("R2000")
    doc.header["$INSUNITS"] = INSUNITS[args.units]
    msp = doc.modelspace()
    if args.units == "text-metric":
        msp.add_text("UNITS = METRIC", dxfattribs={"layer": "1"})
    if args.units == "text-english":
        msp.add_text("UNITS = ENGLISH", dxfattribs={"layer": "1"})

    front = doc.blocks.new(name="FRONT")
    outline = [u(p) for p in FRONT]
    if args.variant == "crossing":
        outline[1], outline[2] = outline[2], outline[1]
    if args.variant == "bulge":
        front.add_lwpolyline([(*p, 0, 0, 0.3 if i == 0 else 0) for i, p in enumerate(outline)],
                             format="xyseb", close=True, dxfattribs={"layer": "1"})
    else:
        front.add_lwpolyline(outline, close=args.variant != "open", dxfattribs={"layer": "1"})
    front.add_lwpolyline([u(p) for p in FRONT_HOLE], close=True, dxfattribs={"layer": "11"})
    for point, normal in FRONT_NOTCHES:
        inner = (point[0] + 0.6 * normal[0], point[1] + 0.6 * normal[1])
        front.add_line(u(point), u(inner), dxfattribs={"layer": "4"})
    for p in FRONT_DRILLS:
        front.add_point(u(p), dxfattribs={"layer": "13"})
    front.add_line(u(FRONT_FOLD[0]), u(FRONT_FOLD[1]), dxfattribs={"layer": "8"})
    if args.variant != "no-grain":
        a = math.radians(GRAIN_DEG)
        to = (GRAIN_FROM[0] + GRAIN_LENGTH * math.cos(a), GRAIN_FROM[1] + GRAIN_LENGTH * math.sin(a))
        front.add_line(u(GRAIN_FROM), u(to), dxfattribs={"layer": "7"})
    front.add_text("Piece Name: FRONT", dxfattribs={"layer": "1"})
    msp.add_blockref("FRONT", (0, 0))

    back = doc.blocks.new(name="BACK")
    back.add_polyline2d([u(p) for p in BACK], close=True, dxfattribs={"layer": "1"})
    back.add_line(u((18, 4)), u((18, 24)), dxfattribs={"layer": "7"})
    msp.add_blockref("BACK", (50 * scale, 0))

    doc.saveas(args.out)


if __name__ == "__main__":
    main()
