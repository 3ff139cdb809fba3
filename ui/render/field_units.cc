#include "ui/render/field_units.h"

#include <stdexcept>

namespace drape {

Measure FieldMeasure(FieldKind kind) {
  switch (kind) {
    case FieldKind::kDisplacement:
      return Measure::kLength;
    case FieldKind::kCurvature:
      return Measure::kCurvature;
    case FieldKind::kBendingMoment:
      return Measure::kMomentPerWidth;
    case FieldKind::kMembraneStrain:
      return Measure::kNone;
    case FieldKind::kElementEnergy:
      return Measure::kEnergyPerArea;
    case FieldKind::kContactPressure:
      return Measure::kPressure;
    case FieldKind::kFrictionState:
      return Measure::kNone;
  }
  throw std::logic_error("a field without a measure");
}

std::string FieldTitle(FieldKind kind, UnitSystem system) {
  for (const FieldInfo& f : Fields()) {
    if (f.kind != kind) continue;
    const std::string title = f.title;
    const std::string label = UnitFor(FieldMeasure(kind), system).label;
    if (label.empty()) return title;  // a strain: "[-]" in every system
    return title.substr(0, title.find(" [")) + " [" + label + "]";
  }
  throw std::logic_error("a field without a name");
}

}  // namespace drape
