// The path numbers a plan can vary, read off the shipped scenes: their keys
// lead to the same numbers in the scene file.
#include "core/plan/path_parameters.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/io/scene_key.h"
#include "core/io/scene_reader.h"
#include "core/model/units.h"
#include "support/test_paths.h"

namespace drape {
namespace {

TEST(PathParameters, TheStripFoldsArcAndLine) {
  const Scene scene = ReadScene(test::ScenesDir() / "strip-fold.json");
  const auto parameters = PathParameters(scene);
  ASSERT_EQ(parameters.size(), 7u);  // R's centre (3) and angle, T's line (3)
  EXPECT_EQ(parameters[0].key, "stages[1].moves[0].path.arc.center[0]");
  EXPECT_EQ(parameters[0].label, "R: end, arc centre x");
  EXPECT_DOUBLE_EQ(parameters[2].value, 0.035175e-2);
  EXPECT_EQ(parameters[3].key, "stages[1].moves[0].path.arc.angle_deg");
  EXPECT_EQ(parameters[3].value, 180);
  EXPECT_EQ(parameters[3].dimension, dim::kNone);
  EXPECT_EQ(parameters[4].key, "stages[2].moves[0].path.line.by[0]");
  EXPECT_DOUBLE_EQ(parameters[4].value, 0.01);
}

TEST(PathParameters, EachKeyLeadsToItsNumberInTheFile) {
  for (const char* name : {"strip-fold.json", "ply-lay-down.json", "diagonal-fold.json"}) {
    std::ifstream in(test::ScenesDir() / name);
    const nlohmann::ordered_json file = nlohmann::ordered_json::parse(in);
    const Scene scene = ReadScene(test::ScenesDir() / name);
    const auto parameters = PathParameters(scene);
    EXPECT_FALSE(parameters.empty()) << name;
    for (const PathParameter& p : parameters) {
      const nlohmann::ordered_json value = SceneKeyValue(file, p.key, "");
      ASSERT_FALSE(value.is_null()) << name << " " << p.key;
      const double read = value.is_number() ? value.get<double>()
                                            : ParseQuantity(value.get<std::string>()).value_si;
      EXPECT_NEAR(read, p.value, 1e-15) << name << " " << p.key;
    }
  }
}

}  // namespace
}  // namespace drape
