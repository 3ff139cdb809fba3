// A position in a JSON document that knows its own path, so that every check
// made through it can name the key that failed (`fabric.mesh.elements[1]`).
// Private to core/io: nlohmann/json stays out of every other header.
#pragma once

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/model/scene.h"
#include "core/model/units.h"

namespace drape {

class JsonCursor {
 public:
  JsonCursor(const nlohmann::json& value, std::string path)
      : value_(&value), path_(std::move(path)) {}

  const nlohmann::json& value() const { return *value_; }
  const std::string& path() const { return path_; }

  // Throws SceneError naming this cursor's path.
  [[noreturn]] void Fail(const std::string& message) const;

  // Checks that this is an object whose keys are all in `allowed`; an unknown
  // key fails at its own path, with the nearest allowed key suggested.
  void ExpectObject(std::initializer_list<std::string_view> allowed) const;

  bool Has(std::string_view key) const;
  // A required member: fails "missing required key" when absent.
  JsonCursor operator[](std::string_view key) const;
  std::optional<JsonCursor> Find(std::string_view key) const;
  // Exactly one of `keys` must be present; returns its index.
  int OneOf(std::initializer_list<std::string_view> keys) const;

  // Array elements; fails unless this is an array (of `size` elements when given).
  std::vector<JsonCursor> Items(std::optional<size_t> size = std::nullopt) const;

  double Number() const;  // any finite JSON number
  int Integer() const;    // a JSON integer that fits in int
  bool Boolean() const;
  std::string String() const;
  // A JSON number in SI units, or a "number unit" string of dimension `d`.
  double Quantity(Dimension d) const;
  // As Quantity, then checked: > 0, >= 0 ...
  double PositiveQuantity(Dimension d) const;
  double NonNegativeQuantity(Dimension d) const;
  Vec2 QuantityVec2(Dimension d) const;
  Vec3 QuantityVec3(Dimension d) const;
  // A direction: three numbers, not all zero; returned normalised.
  Vec3 Direction() const;
  // One of the given words; returns its index.
  int Choice(std::initializer_list<std::string_view> words) const;

 private:
  JsonCursor Child(std::string_view key) const;
  JsonCursor Child(size_t index) const;

  const nlohmann::json* value_;
  std::string path_;
};

// 'word' in single quotes, for messages.
std::string Quoted(std::string_view word);

// Smallest number of single-character edits turning a into b.
int EditDistance(std::string_view a, std::string_view b);

// Nearest word to `word` among `candidates` when close enough to be a likely typo.
std::optional<std::string> NearestWord(std::string_view word,
                                       std::initializer_list<std::string_view> candidates);

}  // namespace drape
