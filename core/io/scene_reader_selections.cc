// Reading what a scene holds and loads the fabric by: the selections of
// nodes, and the supports, grippers and point loads made of them.
#include "core/io/scene_parser.h"
#include "core/io/selection_reader.h"

namespace drape {
namespace {

// A point as typed: [0, "1 cm"].
std::string PointAsTyped(const JsonCursor& c) {
  std::string out = "[";
  for (const auto& item : c.Items()) {
    if (out.size() > 1) out += ", ";
    out += AsTyped(item.value());
  }
  return out + "]";
}

}  // namespace

Selection SceneParser::ReadSelectionFor(const JsonCursor& c, const Scene& scene) {
  parts_ = FabricParts(scene);
  Selection s = ReadSelection(c);
  parts_.clear();
  return s;
}

Selection ReadSelection(const nlohmann::json& value, const std::string& path, const Scene& scene) {
  return SceneParser(".").ReadSelectionFor(JsonCursor(value, path), scene);
}

Selection SceneParser::ReadSelection(const JsonCursor& c) {
  c.ExpectObject({"point",
                  "line",
                  "box",
                  "circle",
                  "corners",
                  "edge",
                  "nodes",
                  "notch",
                  "drill",
                  "internal_line",
                  "tolerance",
                  "part"});
  Selection s;
  switch (c.OneOf({"point",
                   "line",
                   "box",
                   "circle",
                   "corners",
                   "edge",
                   "nodes",
                   "notch",
                   "drill",
                   "internal_line"})) {
    case 0:
      s.shape = PointSelection{c["point"].QuantityVec2(dim::kLength)};
      break;
    case 1: {
      auto ends = c["line"].Items(2);
      LineSelection line{ends[0].QuantityVec2(dim::kLength), ends[1].QuantityVec2(dim::kLength)};
      if (line.from == line.to)
        c["line"].Fail("the two ends of a line must differ, found " + PointAsTyped(ends[0]) +
                       " and " + PointAsTyped(ends[1]));
      s.shape = line;
      break;
    }
    case 2: {
      auto corners = c["box"].Items(2);
      BoxSelection box{corners[0].QuantityVec2(dim::kLength),
                       corners[1].QuantityVec2(dim::kLength)};
      for (int k = 0; k < 2; ++k)
        if (box.min[k] > box.max[k]) {
          const char* axis = k == 0 ? "x" : "y";
          c["box"].Fail(
              std::string("expected [[xmin, ymin], [xmax, ymax]] with min <= max, found ") + axis +
              "min " + AsTyped(corners[0].value()[k]) + " > " + axis + "max " +
              AsTyped(corners[1].value()[k]));
        }
      s.shape = box;
      break;
    }
    case 3: {
      const JsonCursor circle = c["circle"];
      circle.ExpectObject({"center", "radius"});
      s.shape = CircleSelection{circle["center"].QuantityVec2(dim::kLength),
                                circle["radius"].PositiveQuantity(dim::kLength)};
      break;
    }
    case 4:
      if (!c["corners"].Boolean()) c["corners"].Fail("write \"corners\": true to select corners");
      s.shape = CornersSelection{};
      break;
    case 5: {
      int side = c["edge"].Choice({"left", "right", "bottom", "top", "boundary"});
      s.shape = EdgeSelection{static_cast<Side>(side)};
      break;
    }
    case 7:
    case 8:
    case 9: {
      const char* key = c.Has("notch") ? "notch" : c.Has("drill") ? "drill" : "internal_line";
      const PatternMark kind = c.Has("notch")   ? PatternMark::kNotch
                               : c.Has("drill") ? PatternMark::kDrill
                                                : PatternMark::kInternalLine;
      auto k = c[key];
      PatternMarkSelection mark{kind, k.Integer()};
      if (mark.index < 1)
        k.Fail("counts from 1 (the first in the pattern file), found " +
               std::to_string(mark.index));
      s.shape = mark;
      break;
    }
    default: {
      auto nodes = c["nodes"];
      NodesSelection n;
      for (const auto& item : nodes.Items()) {
        int index = item.Integer();
        if (index < 0) item.Fail("node indices start at 0, found " + std::to_string(index));
        n.nodes.push_back(index);
      }
      if (n.nodes.empty()) nodes.Fail("an empty node list selects nothing");
      s.shape = n;
    }
  }
  if (auto t = c.Find("tolerance")) s.tolerance = t->PositiveQuantity(dim::kLength);
  s.part = ReadPartName(c);
  return s;
}

Support SceneParser::ReadSupport(const JsonCursor& c) {
  c.ExpectObject({"name", "select", "fix"});
  Support s;
  s.name = ReadName(c, "support or gripper");
  s.select = ReadSelection(c["select"]);
  if (auto f = c.Find("fix")) s.fix = static_cast<Fixity>(f->Choice({"position", "clamp"}));
  return s;
}

Gripper SceneParser::ReadGripper(const JsonCursor& c) {
  c.ExpectObject({"name", "select", "hold"});
  Gripper g;
  g.name = ReadName(c, "support or gripper");
  g.select = ReadSelection(c["select"]);
  if (auto h = c.Find("hold")) g.hold = static_cast<Fixity>(h->Choice({"position", "clamp"}));
  return g;
}

PointLoad SceneParser::ReadLoad(const JsonCursor& c) {
  c.ExpectObject({"name", "select", "force", "moment"});
  PointLoad load;
  load.name = ReadName(c, "load");
  load.select = ReadSelection(c["select"]);
  if (!c.Has("force") && !c.Has("moment")) c.Fail("a load needs a 'force', a 'moment' or both");
  if (auto f = c.Find("force")) load.force = f->QuantityVec3(dim::kForce);
  if (auto m = c.Find("moment")) load.moment = m->QuantityVec3(dim::kMoment);
  return load;
}

}  // namespace drape
