#include "core/io/json_cursor.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/io/scene_parser.h"
#include "core/model/scene_error.h"

namespace drape {
namespace {

const char* TypeName(const nlohmann::json& v) {
  switch (v.type()) {
    case nlohmann::json::value_t::null:
      return "null";
    case nlohmann::json::value_t::object:
      return "an object";
    case nlohmann::json::value_t::array:
      return "an array";
    case nlohmann::json::value_t::string:
      return "a string";
    case nlohmann::json::value_t::boolean:
      return "a boolean";
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float:
      return "a number";
    default:
      return "an unsupported value";
  }
}

std::string QuoteList(std::initializer_list<std::string_view> words) {
  std::string out;
  for (auto w : words) {
    if (!out.empty()) out += ", ";
    out += Quoted(w);
  }
  return out;
}

// "a length", "an angle", "a force/area".
std::string WithArticle(const std::string& noun) {
  const bool vowel = !noun.empty() && std::string("aeiou").find(noun[0]) != std::string::npos;
  return (vowel ? "an " : "a ") + noun;
}

}  // namespace

// AsTyped, FoundValue and IsWord: see scene_parser.h.
std::string AsTyped(const nlohmann::json& v) {
  if (v.is_string() || v.is_number() || v.is_boolean() || v.is_null()) return v.dump();
  return TypeName(v);
}

std::string FoundValue(const nlohmann::json& v) {
  if (v.is_string()) return "a string " + v.dump();
  if (v.is_number()) return "the number " + v.dump();
  if (v.is_boolean() || v.is_null()) return v.dump();
  return TypeName(v);
}

bool IsWord(const nlohmann::json& v) {
  if (!v.is_string()) return false;
  const std::string& s = v.get_ref<const std::string&>();
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return false;
  const char c = s[first];
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

std::string Quoted(std::string_view word) {
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "'" + s + "'".
  std::string out;
  out.reserve(word.size() + 2);
  out += '\'';
  out += word;
  out += '\'';
  return out;
}

int EditDistance(std::string_view a, std::string_view b) {
  std::vector<int> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = static_cast<int>(j);
  for (size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = static_cast<int>(i);
    for (size_t j = 1; j <= b.size(); ++j) {
      int above = row[j];
      int substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      row[j] = std::min({above + 1, row[j - 1] + 1, substitution});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::optional<std::string> NearestWord(std::string_view word,
                                       std::initializer_list<std::string_view> candidates) {
  std::optional<std::string> best;
  int best_distance = std::numeric_limits<int>::max();
  for (auto c : candidates) {
    int d = EditDistance(word, c);
    // A prefix or an extension ("element" for "elements") is a likely typo too.
    bool prefix = word.size() >= 3 && (c.starts_with(word) || word.starts_with(c));
    int limit = std::max<int>(2, static_cast<int>(c.size()) / 3);
    if ((d <= limit || prefix) && d < best_distance) {
      best = std::string(c);
      best_distance = d;
    }
  }
  return best;
}

void JsonCursor::Fail(const std::string& message) const {
  throw SceneError(path_, message);
}

JsonCursor JsonCursor::Child(std::string_view key) const {
  std::string p = path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  return JsonCursor((*value_)[std::string(key)], std::move(p));
}

JsonCursor JsonCursor::Child(size_t index) const {
  return JsonCursor((*value_)[index], path_ + "[" + std::to_string(index) + "]");
}

void JsonCursor::ExpectObject(std::initializer_list<std::string_view> allowed) const {
  if (!value_->is_object()) Fail("expected an object, found " + FoundValue(*value_));
  for (const auto& [key, unused] : value_->items()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string p = path_.empty() ? key : path_ + "." + key;
    if (auto near = NearestWord(key, allowed))
      throw SceneError(p, "unknown key; did you mean '" + *near + "'?");
    throw SceneError(p, "unknown key; expected one of " + QuoteList(allowed));
  }
}

bool JsonCursor::Has(std::string_view key) const {
  return value_->is_object() && value_->contains(key);
}

JsonCursor JsonCursor::operator[](std::string_view key) const {
  if (!value_->is_object()) Fail("expected an object, found " + FoundValue(*value_));
  if (!value_->contains(key)) Fail("missing required key '" + std::string(key) + "'");
  return Child(key);
}

std::optional<JsonCursor> JsonCursor::Find(std::string_view key) const {
  if (!Has(key)) return std::nullopt;
  return Child(key);
}

int JsonCursor::OneOf(std::initializer_list<std::string_view> keys) const {
  if (!value_->is_object()) Fail("expected an object, found " + FoundValue(*value_));
  int found = -1;
  int index = 0;
  for (auto k : keys) {
    if (value_->contains(k)) {
      if (found >= 0) Fail("give only one of " + QuoteList(keys));
      found = index;
    }
    ++index;
  }
  if (found < 0) Fail("expected one of " + QuoteList(keys));
  return found;
}

std::vector<JsonCursor> JsonCursor::Items(std::optional<size_t> size) const {
  if (!value_->is_array()) {
    if (size)
      Fail("expected an array of " + std::to_string(*size) + ", found " + FoundValue(*value_));
    Fail("expected an array, found " + FoundValue(*value_));
  }
  if (size && value_->size() != *size)
    Fail("expected " + std::to_string(*size) + " values, found " + std::to_string(value_->size()));
  std::vector<JsonCursor> items;
  items.reserve(value_->size());
  for (size_t i = 0; i < value_->size(); ++i) items.push_back(Child(i));
  return items;
}

double JsonCursor::Number() const {
  if (!value_->is_number()) Fail("expected a number, found " + FoundValue(*value_));
  double x = value_->get<double>();
  if (!std::isfinite(x)) Fail("expected a finite number");
  return x;
}

int JsonCursor::Integer() const {
  if (!value_->is_number_integer())
    Fail("expected an integer (a whole number), found " +
         (value_->is_number() ? value_->dump() : FoundValue(*value_)));
  if (value_->is_number_unsigned()) {
    auto u = value_->get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
      Fail("integer " + std::to_string(u) + " is too large (at most " +
           std::to_string(std::numeric_limits<int>::max()) + ")");
    return static_cast<int>(u);
  }
  auto i = value_->get<std::int64_t>();
  if (i > std::numeric_limits<int>::max())
    Fail("integer " + std::to_string(i) + " is too large (at most " +
         std::to_string(std::numeric_limits<int>::max()) + ")");
  if (i < std::numeric_limits<int>::min())
    Fail("integer " + std::to_string(i) + " is too small (at least " +
         std::to_string(std::numeric_limits<int>::min()) + ")");
  return static_cast<int>(i);
}

bool JsonCursor::Boolean() const {
  if (!value_->is_boolean()) Fail("expected true or false, found " + FoundValue(*value_));
  return value_->get<bool>();
}

std::string JsonCursor::String() const {
  if (!value_->is_string()) Fail("expected a string, found " + FoundValue(*value_));
  return value_->get<std::string>();
}

double JsonCursor::Quantity(Dimension d) const {
  if (value_->is_number()) return Number();
  if (!value_->is_string())
    Fail("expected " + WithArticle(DimensionName(d)) +
         " (a number in SI units or a \"number unit\" string), found " + FoundValue(*value_));
  try {
    return ParseQuantityAs(value_->get<std::string>(), d);
  } catch (const UnitError& e) {
    Fail(e.what());
  }
}

double JsonCursor::PositiveQuantity(Dimension d) const {
  double x = Quantity(d);
  if (!(x > 0)) Fail("must be greater than zero, found " + AsTyped(*value_));
  return x;
}

double JsonCursor::NonNegativeQuantity(Dimension d) const {
  double x = Quantity(d);
  if (x < 0) Fail("must not be negative, found " + AsTyped(*value_));
  return x;
}

Vec2 JsonCursor::QuantityVec2(Dimension d) const {
  auto items = Items(2);
  return {items[0].Quantity(d), items[1].Quantity(d)};
}

Vec3 JsonCursor::QuantityVec3(Dimension d) const {
  auto items = Items(3);
  return {items[0].Quantity(d), items[1].Quantity(d), items[2].Quantity(d)};
}

Vec3 JsonCursor::Direction() const {
  auto items = Items(3);
  Vec3 v{items[0].Number(), items[1].Number(), items[2].Number()};
  double norm = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (!(norm > 1e-12)) Fail("a direction must not be the zero vector");
  // Axes written as [1, 1, 0] are meant as directions: normalise them. One that
  // is already unit to rounding is kept bit for bit, so save → load is exact.
  if (std::abs(norm - 1.0) < 1e-14) return v;
  return {v[0] / norm, v[1] / norm, v[2] / norm};
}

int JsonCursor::Choice(std::initializer_list<std::string_view> words) const {
  std::string s = String();
  int index = 0;
  for (auto w : words) {
    if (s == w) return index;
    ++index;
  }
  if (auto near = NearestWord(s, words))
    Fail("'" + s + "' is not valid; did you mean '" + *near + "'?");
  Fail("'" + s + "' is not valid; expected one of " + QuoteList(words));
}

}  // namespace drape
