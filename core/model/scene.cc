#include "core/model/scene.h"

namespace drape {

const char* ToString(StageKind kind) {
  switch (kind) {
    case StageKind::kGravity:
      return "gravity";
    case StageKind::kLoad:
      return "load";
    case StageKind::kMove:
      return "move";
    case StageKind::kHold:
      return "hold";
  }
  return "?";
}

const char* ToString(StepControl control) {
  return control == StepControl::kArcLength ? "arc_length" : "load";
}

const char* ToString(Fixity fixity) {
  return fixity == Fixity::kPosition ? "position" : "clamp";
}

const char* ToString(Side side) {
  switch (side) {
    case Side::kLeft:
      return "left";
    case Side::kRight:
      return "right";
    case Side::kBottom:
      return "bottom";
    case Side::kTop:
      return "top";
    case Side::kBoundary:
      return "boundary";
  }
  return "?";
}

std::vector<const Fabric*> FabricParts(const Scene& scene) {
  std::vector<const Fabric*> parts{&scene.fabric};
  for (const Fabric& f : scene.other_parts) parts.push_back(&f);
  return parts;
}

const char* PatternMarkKey(PatternMark mark) {
  switch (mark) {
    case PatternMark::kNotch:
      return "notch";
    case PatternMark::kDrill:
      return "drill";
    case PatternMark::kInternalLine:
      return "internal_line";
  }
  return "?";
}

const char* PatternMarkName(PatternMark mark) {
  switch (mark) {
    case PatternMark::kNotch:
      return "notch";
    case PatternMark::kDrill:
      return "drill hole";
    case PatternMark::kInternalLine:
      return "internal line";
  }
  return "?";
}

const char* ToString(Interpolation interpolation) {
  return interpolation == Interpolation::kLinear ? "linear" : "smooth";
}

const char* ToString(ImperfectionPattern pattern) {
  return pattern == ImperfectionPattern::kSmooth ? "smooth" : "nodal";
}

const char* ToString(Branching branching) {
  return branching == Branching::kStable ? "stable" : "fundamental";
}

}  // namespace drape
