// Paths the tests need, fixed at configure time in test_paths.cc alone: a
// test file that named them in macros would differ between checkouts, and
// no compiler cache would reuse it.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace drape::test {

// The source tree.
std::filesystem::path SourceDir();
// The `drape` program under test.
const char* DrapeCli();
// The `drape-studio` program ("" when the workbench is not built).
const char* DrapeStudio();

inline std::filesystem::path ScenesDir() {
  return SourceDir() / "resources" / "scenes";
}

// Every example scene shipped in resources/scenes, sorted.
inline std::vector<std::filesystem::path> ExampleScenes() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(ScenesDir()))
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace drape::test
