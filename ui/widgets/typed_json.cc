#include "ui/widgets/typed_json.h"

#include <QStringList>

namespace drape {

nlohmann::json TypedQuantity(const QString& text) {
  bool number = false;
  const QString trimmed = text.trimmed();
  const double v = trimmed.toDouble(&number);
  if (!number) return trimmed.toStdString();
  // As JSON reads it where it can ("-1" stays an integer), so a message
  // quotes the number as it was typed.
  const auto as_json = nlohmann::json::parse(trimmed.toStdString(), nullptr, false);
  return as_json.is_number() ? as_json : nlohmann::json(v);
}

nlohmann::json TypedList(const QString& text) {
  nlohmann::json list = nlohmann::json::array();
  for (const QString& part : text.split(',')) list.push_back(TypedQuantity(part));
  return list;
}

nlohmann::json TypedLists(const QString& text) {
  nlohmann::json lists = nlohmann::json::array();
  for (const QString& part : text.split(';', Qt::SkipEmptyParts)) lists.push_back(TypedList(part));
  return lists;
}

double TypedMeasure(const QString& text, Measure measure) {
  bool number = false;
  const double v = text.trimmed().toDouble(&number);
  if (number) return v;
  return ParseMeasure(text.trimmed().toStdString(), measure);
}

std::array<double, 2> TypedPoint(const QString& text) {
  const QStringList parts = text.split(',');
  if (parts.size() != 2) throw UnitError("give two coordinates, x, y");
  return {TypedMeasure(parts[0], Measure::kLength), TypedMeasure(parts[1], Measure::kLength)};
}

QString ListText(const std::array<double, 2>& v) {
  return QString("%1, %2").arg(v[0]).arg(v[1]);
}

QString ListText(const std::array<double, 3>& v) {
  return QString("%1, %2, %3").arg(v[0]).arg(v[1]).arg(v[2]);
}

}  // namespace drape

namespace drape {

QString QuantityText(double si, Measure measure, UnitSystem system) {
  // A zero is one in every unit; "0" reads plainer than "0 cm".
  if (si == 0) return "0";
  return QString::fromStdString(FormatQuantity(si, measure, system, 6));
}

QString ListText(const std::array<double, 2>& v, UnitSystem system) {
  return QString("%1, %2").arg(QuantityText(v[0], Measure::kLength, system),
                               QuantityText(v[1], Measure::kLength, system));
}

QString ListText(const std::array<double, 3>& v, UnitSystem system) {
  return ListText(v, Measure::kLength, system);
}

QString ListText(const std::array<double, 3>& v, Measure measure, UnitSystem system) {
  return QString("%1, %2, %3")
      .arg(QuantityText(v[0], measure, system),
           QuantityText(v[1], measure, system),
           QuantityText(v[2], measure, system));
}

nlohmann::json ObstacleInUnits(const nlohmann::json& obstacle, UnitSystem system) {
  nlohmann::json shown = obstacle;
  if (system == UnitSystem::kSI || !shown.is_object()) return shown;
  auto in_units = [system](nlohmann::json& value) {
    if (value.is_number() && value.get<double>() != 0)
      value = QuantityText(value.get<double>(), Measure::kLength, system).toStdString();
  };
  for (auto& [key, shape] : shown.items()) {
    if (!shape.is_object()) continue;  // the name
    for (const char* length :
         {"point", "min", "max", "center", "radius", "length", "edge_radius", "at"}) {
      if (!shape.contains(length)) continue;
      nlohmann::json& value = shape[length];
      if (value.is_array())
        for (nlohmann::json& x : value) in_units(x);
      else
        in_units(value);
    }
  }
  return shown;
}

}  // namespace drape
