#!/usr/bin/python3
"""Reads an AAMA pattern file with ezdxf (independent of the project's
reader) and prints what the writer's tests check, as JSON:

    {"insunits": 4, "pieces": {"FRONT": {"cut_area": A, "cut_points": n,
     "holes": [area, ...], "notches": [[x, y], ...], "drills": k,
     "grain_deg": g}}}

Areas and points in the file's units; the cut line is layer 1's polyline.
"""
import json
import math
import sys

import ezdxf


def area(points):
    twice = 0.0
    for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1]):
        twice += x0 * y1 - x1 * y0
    return abs(twice) / 2


def loop(entity):
    if entity.dxftype() == "LWPOLYLINE":
        return [(p[0], p[1]) for p in entity.get_points("xy")]
    return [(v.dxf.location.x, v.dxf.location.y) for v in entity.vertices]


def main():
    doc = ezdxf.readfile(sys.argv[1])
    out = {"insunits": doc.header.get("$INSUNITS", 0), "pieces": {}}
    for block in doc.blocks:
        if block.name.startswith("*"):
            continue
        piece = {"holes": [], "notches": [], "drills": 0}
        for e in block:
            layer = e.dxf.layer
            if e.dxftype() in ("LWPOLYLINE", "POLYLINE") and layer == "1":
                points = loop(e)
                piece["cut_area"] = area(points)
                piece["cut_points"] = len(points)
            elif e.dxftype() in ("LWPOLYLINE", "POLYLINE") and layer == "11":
                piece["holes"].append(area(loop(e)))
            elif e.dxftype() == "POINT" and layer == "4":
                piece["notches"].append([e.dxf.location.x, e.dxf.location.y])
            elif e.dxftype() == "POINT" and layer == "13":
                piece["drills"] += 1
            elif e.dxftype() == "LINE" and layer == "7":
                d = e.dxf.end - e.dxf.start
                piece["grain_deg"] = math.degrees(math.atan2(d.y, d.x))
        out["pieces"][block.name] = piece
    print(json.dumps(out))


if __name__ == "__main__":
    main()
