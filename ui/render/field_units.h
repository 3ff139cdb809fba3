// A colour field's unit in the user's unit system: what its values are
// (a curvature, a moment per width, …), and its colour bar title with the
// unit, "curvature [1/cm]".
#pragma once

#include <string>

#include "core/fe/element_fields.h"
#include "core/model/unit_system.h"

namespace drape {

Measure FieldMeasure(FieldKind kind);
// The field's title (FieldInfo::title) with `system`'s unit in the brackets.
std::string FieldTitle(FieldKind kind, UnitSystem system);

}  // namespace drape
