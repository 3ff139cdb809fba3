// Seeded mutation of reader inputs for the fuzz tests (reader_fuzz_test.cc,
// result_fuzz_test.cc): byte edits from an alphabet tuned to the format,
// whole tokens from a dictionary, copied chunks, binary words, truncations,
// splices of two seeds and random bytes. Deterministic for a given seed, so
// a failure names an input that can be made again.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "core/model/imperfection.h"

namespace drape::test {

// Inputs per reader: DRAPE_FUZZ_INPUTS (a long run sets it to 100000), or
// `fallback`, small enough for the sanitized CTest run.
inline int FuzzInputs(int fallback = 2000) {
  const char* text = std::getenv("DRAPE_FUZZ_INPUTS");
  if (text == nullptr || *text == '\0') return fallback;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (*end != '\0' || value <= 0 || value > 100000000) {
    ADD_FAILURE() << "DRAPE_FUZZ_INPUTS='" << text << "' is not a positive count";
    return fallback;
  }
  return static_cast<int>(value);
}

// The bytes of a string literal, its NUL bytes included: a literal passed as
// a C string ends at its first NUL ("\x00\x01" is then empty).
template <std::size_t N>
std::string Bytes(const char (&literal)[N]) {
  return std::string(literal, N - 1);
}

// What the format's readers are fed beyond single bytes.
struct FuzzAlphabet {
  std::string bytes;                // replaced and inserted one at a time (Bytes() for NULs)
  std::vector<std::string> tokens;  // inserted or written over whole
  bool binary = false;              // also overwrite 4- and 8-byte words
  // Written over a whole number of the text: values that overflow what a
  // reader computes from them are found this way, rarely by byte edits.
  std::vector<std::string> numbers = {
      "0",       "-0",         "1",           "-1",         "1e100",  "-1e100", "1e200", "-1e200",
      "1.7e308", "-1.7e308",   "1e308",       "1e-200",     "1e-310", "5e-324", "1e999", "nan",
      "inf",     "2147483647", "-2147483648", "4294967296", "1e10",   "0.5",    "3"};
};

class Mutator {
 public:
  Mutator(std::uint64_t seed, FuzzAlphabet alphabet) : rng_(seed), alphabet_(std::move(alphabet)) {}

  std::uint64_t Next() { return rng_.Next(); }
  std::size_t Below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(Next() % n); }

  // One input made from `seeds`: mostly a few edits of one seed; sometimes a
  // prefix of one, a splice of two, or random bytes.
  // `picked`, when given, is set to the index of the seed used.
  std::string Make(const std::vector<std::string>& seeds, std::size_t* picked = nullptr) {
    const std::size_t index = Below(seeds.size());
    if (picked != nullptr) *picked = index;
    const std::string& seed = seeds[index];
    switch (Below(20)) {
      case 0:
        return seed.substr(0, Below(seed.size() + 1));
      case 1: {
        const std::string& other = seeds[Below(seeds.size())];
        return seed.substr(0, Below(seed.size() + 1)) + other.substr(Below(other.size() + 1));
      }
      case 2:
        return RandomBytes(1 + Below(512));
      default:
        return Edited(seed, 1 + static_cast<int>(Below(Below(8) == 0 ? 32 : 4)));
    }
  }

  std::string Edited(std::string text, int edits) {
    for (int e = 0; e < edits; ++e) Edit(text);
    return text;
  }

  std::string RandomBytes(std::size_t size) {
    std::string text(size, '\0');
    for (char& c : text) c = static_cast<char>(Next() & 0xff);
    return text;
  }

 private:
  char Byte() {
    if (alphabet_.bytes.empty() || Below(8) == 0) return static_cast<char>(Next() & 0xff);
    return alphabet_.bytes[Below(alphabet_.bytes.size())];
  }
  const std::string& Token() { return alphabet_.tokens[Below(alphabet_.tokens.size())]; }

  // Binary words that count or size something are where readers trust the
  // file: zero, all ones, sign bits, and doubles that are not numbers.
  std::string Word() {
    static const std::uint64_t kWords[] = {0,
                                           1,
                                           0xffffffffull,
                                           0x7fffffffull,
                                           0x80000000ull,
                                           0x40000000ull,
                                           0x00010000ull,
                                           0x7ff8000000000000ull,  // NaN
                                           0x7ff0000000000000ull,  // +inf
                                           0xfff0000000000000ull,  // -inf
                                           0x7fefffffffffffffull,  // largest double
                                           0x0000000000000001ull,  // smallest subnormal
                                           0xffffffffffffffffull};
    std::uint64_t word = Below(4) == 0 ? Next() : kWords[Below(std::size(kWords))];
    std::string bytes(Below(2) == 0 ? 4 : 8, '\0');
    std::memcpy(bytes.data(), &word, bytes.size());
    return bytes;
  }

  void Edit(std::string& text) {
    const std::size_t at = Below(text.size() + 1);
    const int kinds = alphabet_.binary ? 10 : 9;
    switch (Below(kinds)) {
      case 8: {
        const std::size_t begin = text.find_first_of("0123456789", at);
        if (begin == std::string::npos) break;
        const std::size_t first = text.find_last_not_of("0123456789.eE+-", begin);
        const std::size_t start = first == std::string::npos ? 0 : first + 1;
        const std::size_t end = text.find_first_not_of("0123456789.eE+-", begin);
        text.replace(start,
                     (end == std::string::npos ? text.size() : end) - start,
                     alphabet_.numbers[Below(alphabet_.numbers.size())]);
        break;
      }
      case 0:
      case 1:
        if (at < text.size()) text[at] = Byte();
        break;
      case 2:
        text.insert(text.begin() + at, Byte());
        break;
      case 3:
        text.erase(std::min(at, text.size()), 1 + Below(Below(4) == 0 ? 64 : 4));
        break;
      case 4:
        if (!alphabet_.tokens.empty()) text.insert(at, Token());
        break;
      case 5:
        if (!alphabet_.tokens.empty() && at < text.size()) {
          const std::string& token = Token();
          text.replace(at, 1 + Below(8), token);
        }
        break;
      case 6: {  // a chunk repeated elsewhere: rows, facets, records twice
        if (text.empty()) break;
        const std::size_t from = Below(text.size());
        const std::string chunk = text.substr(from, 1 + Below(Below(4) == 0 ? 256 : 32));
        text.insert(Below(text.size() + 1), chunk);
        break;
      }
      case 7:
        if (at < text.size()) text[at] = static_cast<char>(text[at] ^ (1 << Below(8)));
        break;
      default: {
        const std::string word = Word();
        // Aligned to the word most of the time: counts and doubles sit there.
        std::size_t where = Below(text.size() + 1);
        if (Below(4) != 0) where -= where % word.size();
        if (where + word.size() <= text.size()) {
          text.replace(where, word.size(), word);
        } else {
          text.insert(std::min(where, text.size()), word);
        }
      }
    }
  }

  SplitMix64 rng_;
  FuzzAlphabet alphabet_;
};

// Counts per reader, printed at the end of each test for the long run's record.
struct FuzzTally {
  std::string reader;
  long accepted = 0, rejected = 0;
  ~FuzzTally() {
    std::cout << "[fuzz] " << reader << ": " << accepted + rejected << " inputs, " << accepted
              << " accepted, " << rejected << " rejected\n";
  }
};

}  // namespace drape::test
