// Paths the tests need, fixed at configure time.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace drape::test {

inline std::filesystem::path SourceDir() {
  return DRAPE_SOURCE_DIR;
}
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
