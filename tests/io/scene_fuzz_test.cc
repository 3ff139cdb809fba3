// The reader must answer any input with a Scene or a SceneError: never a
// crash, a hang or another exception, and never a Scene holding a number
// that is not finite (support/scene_numbers.h). Inputs: every prefix of each
// example scene, random byte edits of them (NUL bytes among them), numbers
// written over with ones too large to compute with, and random bytes.
#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "core/io/scene_reader.h"
#include "core/model/imperfection.h"
#include "core/model/scene_error.h"
#include "support/fuzz_input.h"
#include "support/scene_numbers.h"
#include "support/test_paths.h"

namespace drape {
namespace {

std::string ReadText(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Returns true when the text gave a scene, false for a SceneError; anything
// else escapes and fails the test. A scene given must hold finite numbers
// only: each one that is not fails the test, named with its key.
bool Parses(const std::string& text) {
  Scene scene;
  try {
    scene = ParseScene(text, test::ScenesDir());
  } catch (const SceneError&) {
    return false;
  }
  for (const std::string& bad : test::SceneNumbers::NonFinite(scene))
    ADD_FAILURE() << "accepted a scene with " << bad << ", from\n" << text.substr(0, 2000);
  return true;
}

TEST(SceneFuzz, EveryTruncationIsAnErrorNotACrash) {
  for (const auto& file : test::ExampleScenes()) {
    std::string text = ReadText(file);
    // Trailing whitespace may go without harm; anything shorter is invalid JSON.
    size_t end = text.find_last_not_of(" \n\r\t") + 1;
    for (size_t n = 0; n < end; ++n) ASSERT_FALSE(Parses(text.substr(0, n))) << file << " at " << n;
  }
}

TEST(SceneFuzz, RandomByteEditsNeverCrash) {
  SplitMix64 rng(20261123);
  // With its length (test::Bytes): as a C string it would end before its NUL.
  const std::string alphabet = test::Bytes("{}[],:\"0123456789.-eE \\tnull/x\xff\x00");
  int parsed = 0, rejected = 0, with_nul = 0;
  for (const auto& file : test::ExampleScenes()) {
    std::string original = ReadText(file);
    for (int trial = 0; trial < 400; ++trial) {
      std::string text = original;
      int edits = 1 + static_cast<int>(rng.Next() % 3);
      for (int e = 0; e < edits; ++e) {
        size_t at = rng.Next() % text.size();
        char c = alphabet[rng.Next() % alphabet.size()];
        switch (rng.Next() % 3) {
          case 0:
            text[at] = c;
            break;
          case 1:
            text.insert(text.begin() + at, c);
            break;
          default:
            text.erase(at, 1 + rng.Next() % 8);
        }
        if (text.empty()) text.push_back('{');
      }
      with_nul += text.find('\0') != std::string::npos;
      (Parses(text) ? parsed : rejected)++;
    }
  }
  // Most edits break the document; some land in strings and keep it valid.
  EXPECT_GT(rejected, 0);
  EXPECT_GT(with_nul, 0) << "no input held a NUL byte";
  std::cout << "parsed " << parsed << ", rejected " << rejected << ", " << with_nul
            << " inputs with a NUL byte\n";
}

// Every number of every example scene (bare, or the number of a quantity
// such as "0.0469 cm") written over in turn with numbers at the edges of a
// double: the reader refuses the scene or gives one whose numbers are all
// finite (Parses checks them) — a value times its unit's factor, or an angle
// in radians turned into degrees, must not overflow unnoticed.
TEST(SceneFuzz, NumbersAtTheEdgesOfADoubleGiveFiniteScenesOrErrors) {
  const char* const kEdges[] = {"1.7e308", "-1.7e308", "1e308", "1e999", "-1e999", "5e-324"};
  const std::string digits = "0123456789";
  const std::string number = digits + ".eE+-";
  int numbers = 0, parsed = 0, rejected = 0;
  for (const auto& file : test::ExampleScenes()) {
    const std::string original = ReadText(file);
    for (size_t begin = original.find_first_of(digits); begin != std::string::npos;) {
      // The whole number around the digit: back to its sign, on to its end.
      size_t start = original.find_last_not_of(number, begin);
      start = start == std::string::npos ? 0 : start + 1;
      size_t end = original.find_first_not_of(number, begin);
      if (end == std::string::npos) end = original.size();
      // Not a digit inside a name ("block-drape-10", "drape_scene": 1 is a number).
      const bool in_name =
          start > 0 && std::isalpha(static_cast<unsigned char>(original[start - 1]));
      if (!in_name) {
        ++numbers;
        for (const char* edge : kEdges) {
          std::string text = original;
          text.replace(start, end - start, edge);
          (Parses(text) ? parsed : rejected)++;
        }
      }
      begin = original.find_first_of(digits, end);
    }
  }
  std::cout << numbers << " numbers, " << parsed << " edits parsed, " << rejected << " rejected\n";
  EXPECT_GT(numbers, 100);
  EXPECT_GT(parsed, 0);  // some numbers may be anything finite
  EXPECT_GT(rejected, 0);
}

TEST(SceneFuzz, RandomBytesNeverCrash) {
  SplitMix64 rng(7);
  for (int trial = 0; trial < 2000; ++trial) {
    std::string text(rng.Next() % 256, '\0');
    for (char& c : text) c = static_cast<char>(rng.Next() & 0xff);
    EXPECT_FALSE(Parses(text));
  }
  // Deep nesting must not overflow the stack.
  EXPECT_FALSE(Parses(std::string(100000, '[')));
  EXPECT_FALSE(Parses(std::string(50000, '[') + std::string(50000, ']')));
}

}  // namespace
}  // namespace drape
