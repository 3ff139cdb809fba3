// The reader must answer any input with a Scene or a SceneError: never a
// crash, a hang or another exception. Inputs: every prefix of each example
// scene, random byte edits of them, and random bytes.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/io/scene_reader.h"
#include "core/model/imperfection.h"
#include "core/model/scene_error.h"
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
// else escapes and fails the test.
bool Parses(const std::string& text) {
  try {
    ParseScene(text, test::ScenesDir());
    return true;
  } catch (const SceneError&) {
    return false;
  }
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
  const std::string alphabet = "{}[],:\"0123456789.-eE \\tnull/x\xff\x00";
  int parsed = 0, rejected = 0;
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
      (Parses(text) ? parsed : rejected)++;
    }
  }
  // Most edits break the document; some land in strings and keep it valid.
  EXPECT_GT(rejected, 0);
  std::cout << "parsed " << parsed << ", rejected " << rejected << "\n";
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
