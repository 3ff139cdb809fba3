// Checks that what a run writes holds no NaN or infinity: result.json (where
// nlohmann writes a non-finite number as null), states.bin, and text exports.
#pragma once

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/io/state_file.h"

namespace drape::test {

// JSON has no NaN: nlohmann writes a non-finite number as null. The one null
// a result may hold on purpose is an unlimited (linear) bending range.
inline void CollectNulls(const nlohmann::json& j,
                         const std::string& at,
                         std::vector<std::string>& out) {
  if (j.is_null()) {
    if (at != "/bending/valid_to") out.push_back(at);
  } else if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it)
      CollectNulls(it.value(), at + "/" + it.key(), out);
  } else if (j.is_array()) {
    for (size_t i = 0; i < j.size(); ++i) CollectNulls(j[i], at + "/" + std::to_string(i), out);
  } else if (j.is_number_float() && !std::isfinite(j.get<double>())) {
    out.push_back(at);
  }
}

inline bool LooksNonFinite(std::string token) {
  for (char& c : token) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return token.find("nan") != std::string::npos || token.find("inf") != std::string::npos;
}

// Every comma- or space-separated token of a text export that is not quoted.
inline int NonFiniteTokens(const std::filesystem::path& file, std::string* first) {
  std::ifstream in(file);
  std::string line;
  int bad = 0;
  std::getline(in, line);  // CSV header, or OBJ's comment
  while (std::getline(in, line)) {
    for (char& c : line)
      if (c == ',') c = ' ';
    std::istringstream tokens(line);
    std::string token;
    while (tokens >> token)
      if (token.front() != '"' && LooksNonFinite(token) && bad++ == 0) *first = line;
  }
  return bad;
}

// The first step of a state file with a non-finite position or director, or
// -1 when every number is finite.
inline int FirstNonFiniteStep(const StateFile& states) {
  for (const StoredStep& s : states.steps)
    if (!s.positions.allFinite() || !s.directors.allFinite()) return s.step;
  return -1;
}

}  // namespace drape::test
