// What a user types into a field, as the scene file's JSON for the scene
// reader to read: "0.5" is a number (SI), "5 cm" a quantity string the
// reader converts; "1 cm, 0, 2 cm" a list; "x, y; x, y" a list of lists.
// Wrong text is not judged here: the reader's message says what is wrong.
#pragma once

#include <QString>
#include <nlohmann/json.hpp>

#include <array>

#include "core/model/unit_system.h"

namespace drape {

nlohmann::json TypedQuantity(const QString& text);
nlohmann::json TypedList(const QString& text);   // comma separated
nlohmann::json TypedLists(const QString& text);  // ';' between lists

// Text typed for one value of `measure` to its SI value: a plain number is
// SI, as the scene reader reads a JSON number; a quantity may be in any
// unit ParseMeasure takes ("2 in"). Throws UnitError.
double TypedMeasure(const QString& text, Measure measure);
// "x, y" lengths typed so ("2 in, 0") to SI. Throws UnitError.
std::array<double, 2> TypedPoint(const QString& text);

// The other way: SI numbers as a field shows them, "0.1, 0, 0.02".
QString ListText(const std::array<double, 2>& v);
QString ListText(const std::array<double, 3>& v);
// Lengths in `system`'s unit, "20 cm, 2 cm" (a zero as "0"): text the
// scene reader reads back.
QString ListText(const std::array<double, 2>& v, UnitSystem system);
QString ListText(const std::array<double, 3>& v, UnitSystem system);
// Values of `measure` (a force, a moment) in `system`'s unit, "0, 0, -1 gf".
QString ListText(const std::array<double, 3>& v, Measure measure, UnitSystem system);
// One value of `measure` in `system`'s unit, 6 digits: "0.469 mm".
QString QuantityText(double si, Measure measure, UnitSystem system);

// An obstacle as SceneToJson writes it (SI numbers) with its lengths
// (point, min, max, center, radius, length, edge_radius, a mesh's at) as quantities in
// `system`'s unit, ["10 cm", 0, "2 cm"]; unchanged in SI. The scene reader
// reads it back to the same obstacle.
nlohmann::json ObstacleInUnits(const nlohmann::json& obstacle, UnitSystem system);

}  // namespace drape
