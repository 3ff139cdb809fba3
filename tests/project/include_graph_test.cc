// The layering (docs/architecture.md): app → ui → core, core with neither Qt
// nor VTK, ui/render (the renderer the command line links) with no Qt, and
// inside core each folder including only the folders below it. Read from the sources' #include
// lines, so a forbidden include fails here with its file and line, not later as a link error
// elsewhere.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

// Every `#include` of the sources under `folder` that starts with one of
// `forbidden` ("ui/", "<Q", …), as "file:line: text".
std::vector<std::string> ForbiddenIncludes(const std::string& folder,
                                           const std::vector<std::string>& forbidden) {
  std::vector<std::string> found;
  const fs::path root = test::SourceDir() / folder;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".h" && ext != ".cc") continue;
    std::ifstream in(entry.path());
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      const auto at = line.find("#include");
      if (at == std::string::npos) continue;
      const auto target = line.find_first_of("\"<", at);
      if (target == std::string::npos) continue;
      const std::string included = line.substr(target);
      for (const std::string& f : forbidden)
        if (included.rfind(f, 0) == 0)
          found.push_back(fs::relative(entry.path(), test::SourceDir()).string() + ":" +
                          std::to_string(number) + ": " + line);
    }
  }
  return found;
}

std::string Lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

TEST(IncludeGraph, CoreHasNoQtNoVtkAndNothingAboveIt) {
  const auto found = ForbiddenIncludes("core", {"\"ui/", "\"app/", "<Q", "<vtk", "\"vtk"});
  EXPECT_TRUE(found.empty()) << Lines(found);
}

// core's folders, each with the folders it may include (besides itself), as
// core/CMakeLists.txt declares them: `drape_core_layer(folder below…)`, the
// libraries' link order. Read from there, so the layers are written once.
using Layers = std::vector<std::pair<std::string, std::vector<std::string>>>;

Layers CoreLayers() {
  Layers layers;
  std::ifstream in(test::SourceDir() / "core" / "CMakeLists.txt");
  const std::string call = "drape_core_layer(";
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(call, 0) != 0) continue;
    std::istringstream words(line.substr(call.size(), line.find(')') - call.size()));
    std::string folder, below;
    words >> folder;
    layers.push_back({folder, {}});
    while (words >> below) layers.back().second.push_back(below);
  }
  return layers;
}

TEST(IncludeGraph, TheLayersAreReadFromCoreCMakeLists) {
  const Layers layers = CoreLayers();
  ASSERT_GE(layers.size(), 8u);
  EXPECT_EQ(layers.front().first, "geometry");
  const auto fe =
      std::find_if(layers.begin(), layers.end(), [](const auto& l) { return l.first == "fe"; });
  ASSERT_NE(fe, layers.end());
  EXPECT_EQ(fe->second, (std::vector<std::string>{"model", "mechanics"}));
}

TEST(IncludeGraph, EachCoreFolderIncludesOnlyTheFoldersBelowIt) {
  std::vector<std::string> folders;
  const Layers layers = CoreLayers();
  for (const auto& [folder, below] : layers) folders.push_back(folder);
  for (const auto& [folder, below] : layers) {
    std::vector<std::string> forbidden;
    for (const std::string& other : folders)
      if (other != folder && std::find(below.begin(), below.end(), other) == below.end())
        forbidden.push_back("\"core/" + other + "/");
    const auto found = ForbiddenIncludes("core/" + folder, forbidden);
    EXPECT_TRUE(found.empty()) << "core/" << folder << " includes a folder above it:\n"
                               << Lines(found);
  }
}

TEST(IncludeGraph, EveryCoreFolderHasItsLayer) {
  for (const auto& entry : fs::directory_iterator(test::SourceDir() / "core")) {
    if (!entry.is_directory()) continue;
    const std::string name = entry.path().filename().string();
    const Layers layers = CoreLayers();
    const bool listed = std::any_of(
        layers.begin(), layers.end(), [&](const auto& layer) { return layer.first == name; });
    EXPECT_TRUE(listed) << "core/" << name
                        << " is in no layer: add a drape_core_layer() line to core/CMakeLists.txt";
  }
}

TEST(IncludeGraph, TheRendererHasNoQtAndTheWorkbenchNoApp) {
  const auto render = ForbiddenIncludes("ui/render", {"\"ui/widgets/", "\"app/", "<Q"});
  EXPECT_TRUE(render.empty()) << Lines(render);
  const auto widgets = ForbiddenIncludes("ui/widgets", {"\"app/"});
  EXPECT_TRUE(widgets.empty()) << Lines(widgets);
}

TEST(IncludeGraph, TheCheckFindsAForbiddenInclude) {
  // The reader itself: tests/project includes <gtest/…>, so asking for
  // "<gtest" there must find this very file.
  const auto found = ForbiddenIncludes("tests/project", {"<gtest"});
  ASSERT_FALSE(found.empty());
  // The line, counted here by plain search: where this file includes gtest.
  std::ifstream self(test::SourceDir() / "tests/project/include_graph_test.cc");
  std::string line;
  int number = 1;
  while (std::getline(self, line) && line != "#include <gtest/gtest.h>") ++number;
  const std::string expected = "include_graph_test.cc:" + std::to_string(number) + ": ";
  EXPECT_NE(
      std::find_if(found.begin(),
                   found.end(),
                   [&](const std::string& f) { return f.find(expected) != std::string::npos; }),
      found.end())
      << expected << " not in\n"
      << Lines(found);
}

}  // namespace
}  // namespace drape
