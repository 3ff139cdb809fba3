// What a user types into a field, as the scene file's JSON for the scene
// reader to read: "0.5" is a number (SI), "5 cm" a quantity string the
// reader converts; "1 cm, 0, 2 cm" a list; "x, y; x, y" a list of lists.
// Wrong text is not judged here: the reader's message says what is wrong.
#pragma once

#include <QString>
#include <nlohmann/json.hpp>

#include <array>

namespace drape {

nlohmann::json TypedQuantity(const QString& text);
nlohmann::json TypedList(const QString& text);   // comma separated
nlohmann::json TypedLists(const QString& text);  // ';' between lists

// The other way: SI numbers as a field shows them, "0.1, 0, 0.02".
QString ListText(const std::array<double, 2>& v);
QString ListText(const std::array<double, 3>& v);

}  // namespace drape
