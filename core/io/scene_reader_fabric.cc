// Reading a scene's fabric: its outline, how finely it is meshed, where it
// lies and the imperfection that lets it buckle.
#include "core/io/dxf_pattern_reader.h"
#include "core/io/scene_parser.h"

namespace drape {

void SceneParser::ReadFabricParts(const JsonCursor& c, Scene& scene) {
  if (!c.value().is_array()) {
    scene.fabric = ReadFabric(c);
    return;
  }
  const auto items = c.Items();
  if (items.empty()) c.Fail("expected the fabric's parts, at least one");
  for (std::size_t i = 0; i < items.size(); ++i) {
    // Selections and probes tell the parts apart by name.
    const std::string name = ReadName(items[i], "fabric part");
    Fabric part = ReadFabric(items[i]);
    part.name = name;
    (i == 0 ? scene.fabric : scene.other_parts.emplace_back()) = std::move(part);
  }
}

std::optional<std::string> SceneParser::ReadPartName(const JsonCursor& c) const {
  const auto part = c.Find("part");
  if (!part) return std::nullopt;
  const std::string name = part->String();
  std::string names;
  for (const Fabric* f : parts_) {
    if (!f->name.empty() && f->name == name) return name;
    names += (names.empty() ? "'" : ", '") + f->name + "'";
  }
  if (parts_.size() < 2)
    part->Fail(Quoted(name) + " names a part, but this fabric is one part: leave out 'part'");
  part->Fail("no fabric part is named '" + name + "'; the parts are " + names);
}

Fabric SceneParser::ReadFabric(const JsonCursor& c) {
  c.ExpectObject({"name", "outline", "mesh", "elevation", "imperfection"});
  Fabric fabric;
  if (auto n = c.Find("name")) fabric.name = n->String();
  fabric.outline = ReadOutline(c["outline"]);
  fabric.mesh = ReadMeshSpec(c["mesh"], fabric.outline);
  if (auto e = c.Find("elevation")) fabric.elevation = e->Quantity(dim::kLength);
  if (auto i = c.Find("imperfection")) fabric.imperfection = ReadImperfection(*i);
  return fabric;
}

Outline SceneParser::ReadOutline(const JsonCursor& c) {
  c.ExpectObject({"rectangle", "disk", "polygon", "pattern"});
  switch (c.OneOf({"rectangle", "disk", "polygon", "pattern"})) {
    case 0: {
      auto r = c["rectangle"];
      r.ExpectObject({"size", "center"});
      RectangleOutline out;
      auto size = r["size"].Items(2);
      out.size = {size[0].PositiveQuantity(dim::kLength), size[1].PositiveQuantity(dim::kLength)};
      if (auto center = r.Find("center")) out.center = center->QuantityVec2(dim::kLength);
      return out;
    }
    case 1: {
      auto d = c["disk"];
      d.ExpectObject({"radius", "center"});
      DiskOutline out;
      out.radius = d["radius"].PositiveQuantity(dim::kLength);
      if (auto center = d.Find("center")) out.center = center->QuantityVec2(dim::kLength);
      return out;
    }
    case 3:
      return ReadPatternOutline(c["pattern"]);
    default: {
      auto p = c["polygon"];
      PolygonOutline out;
      for (const auto& v : p.Items()) out.vertices.push_back(v.QuantityVec2(dim::kLength));
      if (out.vertices.size() < 3)
        p.Fail("a polygon needs at least 3 vertices, found " + std::to_string(out.vertices.size()));
      return out;
    }
  }
}

PatternOutline SceneParser::ReadPatternOutline(const JsonCursor& c) {
  c.ExpectObject({"file", "piece", "at", "rotation_deg", "flip"});
  PatternOutline out;
  out.file = ReadFileReference(c["file"]);
  out.piece = c["piece"].String();
  if (auto at = c.Find("at")) out.placement.at = at->QuantityVec2(dim::kLength);
  if (auto r = c.Find("rotation_deg")) out.placement.rotation_deg = ReadAngleDeg(*r);
  if (auto f = c.Find("flip")) out.placement.flip = f->Boolean();
  const std::filesystem::path file(out.file);
  const std::filesystem::path full = file.is_absolute() ? file : base_ / file;
  out.resolved_path = std::filesystem::absolute(full).lexically_normal().string();
  DxfPattern pattern;
  try {
    pattern = ReadDxfPattern(full);
  } catch (const DxfPatternError& e) {
    c["file"].Fail(e.what());
  }
  try {
    out.shape = Placed(FindPiece(pattern, out.piece, out.file), out.placement);
  } catch (const DxfPatternError& e) {
    c["piece"].Fail(e.what());
  }
  return out;
}

MeshSpec SceneParser::ReadMeshSpec(const JsonCursor& c, const Outline& outline) {
  c.ExpectObject({"elements", "size"});
  MeshSpec spec;
  if (c.OneOf({"elements", "size"}) == 0) {
    auto e = c["elements"];
    if (!std::holds_alternative<RectangleOutline>(outline)) {
      const char* kind = std::holds_alternative<DiskOutline>(outline)      ? "a disk"
                         : std::holds_alternative<PolygonOutline>(outline) ? "a polygon"
                                                                           : "a pattern piece";
      e.Fail(std::string("element counts are for rectangle outlines; this outline is ") + kind +
             ": give 'size' (a target element edge)");
    }
    auto items = e.Items(2);
    std::array<int, 2> n{items[0].Integer(), items[1].Integer()};
    for (int k = 0; k < 2; ++k)
      if (n[k] < 1) items[k].Fail("must be at least 1, found " + std::to_string(n[k]));
    constexpr long long kMaxElements = 4'000'000;
    const long long total = static_cast<long long>(n[0]) * n[1];
    if (total > kMaxElements)
      e.Fail(std::to_string(n[0]) + " x " + std::to_string(n[1]) + " = " + std::to_string(total) +
             " elements, more than the " + std::to_string(kMaxElements) + " allowed");
    spec.elements = n;
  } else {
    spec.size = c["size"].PositiveQuantity(dim::kLength);
  }
  return spec;
}

ImperfectionSpec SceneParser::ReadImperfection(const JsonCursor& c) {
  c.ExpectObject({"amplitude", "seed", "pattern", "wavelength"});
  ImperfectionSpec spec;
  spec.amplitude = c["amplitude"].NonNegativeQuantity(dim::kLength);
  if (auto s = c.Find("seed")) {
    // nlohmann stores every non-negative integer literal as unsigned.
    if (!s->value().is_number_unsigned())
      s->Fail("expected a non-negative integer, found " +
              (s->value().is_number() ? s->value().dump() : FoundValue(s->value())));
    spec.seed = s->value().get<std::uint64_t>();
  }
  if (auto p = c.Find("pattern"))
    spec.pattern = p->Choice({"smooth", "nodal"}) == 0 ? ImperfectionPattern::kSmooth
                                                       : ImperfectionPattern::kNodal;
  if (auto w = c.Find("wavelength")) spec.wavelength = w->PositiveQuantity(dim::kLength);
  return spec;
}

}  // namespace drape
