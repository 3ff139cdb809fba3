// Which scenes mesh sequencing serves, and the factor `solver.sequencing:
// auto` chooses: off below 2 500 elements and wherever the end depends on the
// path; otherwise the coarse mesh's shorter side nearest 20 elements.
#include "core/model/sequencing_check.h"

#include <gtest/gtest.h>

#include "core/model/scene_error.h"

namespace drape {
namespace {

Scene Drape(int nx, int ny) {
  Scene scene;
  scene.fabric.outline = RectangleOutline{{0.5, 0.5}, {0, 0}};
  scene.fabric.mesh.elements = std::array<int, 2>{nx, ny};
  scene.stages = {Stage{.name = "weight", .kind = StageKind::kGravity}};
  return scene;
}

TEST(AutoSequencing, TakesTheCoarseMeshNearestTwentyElementsAcross) {
  EXPECT_EQ(AutoSequencing(Drape(100, 100)), 5);   // 20 × 20
  EXPECT_EQ(AutoSequencing(Drape(200, 200)), 10);  // 20 × 20
  EXPECT_EQ(AutoSequencing(Drape(50, 50)), 2);     // 25 × 25 (10 × 10 is further)
  EXPECT_EQ(AutoSequencing(Drape(120, 60)), 3);    // 40 × 20: the factor divides both
  EXPECT_EQ(AutoSequencing(Drape(60, 48)), 2);     // 30 × 24 beats 20 × 16 (ties: the finer)
  // 53 is prime: no factor divides it.
  EXPECT_EQ(AutoSequencing(Drape(53, 100)), 1);
  // Coarse meshes below 10 elements across are not taken: 2 × 29 = 58.
  EXPECT_EQ(AutoSequencing(Drape(58, 58)), 2);
  EXPECT_EQ(AutoSequencing(Drape(300, 18)), 1);  // 5 400 elements, but 18 / 2 = 9 across
}

TEST(AutoSequencing, StaysOffBelowTwentyFiveHundredElements) {
  EXPECT_EQ(AutoSequencing(Drape(40, 40)), 1);
  EXPECT_EQ(AutoSequencing(Drape(49, 50)), 1);
}

TEST(AutoSequencing, StaysOffWhereTheEndDependsOnThePath) {
  Scene two_stages = Drape(100, 100);
  two_stages.stages.push_back(Stage{.name = "lift", .kind = StageKind::kMove});
  EXPECT_EQ(AutoSequencing(two_stages), 1);
  Scene friction = Drape(100, 100);
  friction.contact = Contact{};
  friction.contact->friction = 0.3;
  EXPECT_EQ(AutoSequencing(friction), 1);
  Scene frictionless = Drape(100, 100);
  frictionless.contact = Contact{};
  EXPECT_EQ(AutoSequencing(frictionless), 5);
  Scene disk = Drape(100, 100);
  disk.fabric.outline = DiskOutline{0.15, {0, 0}};
  disk.fabric.mesh.elements.reset();
  EXPECT_EQ(AutoSequencing(disk), 1);
}

TEST(SequencingCheck, NamesTheKeyAndTheReason) {
  EXPECT_NO_THROW(CheckSequencing(Drape(8, 4), 2));
  EXPECT_NO_THROW(CheckSequencing(Drape(7, 5), kAutoSequencing));
  try {
    CheckSequencing(Drape(8, 4), 3);
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(),
                 "solver.sequencing: 3 must divide the mesh's 8 × 4 elements and leave at least "
                 "2 each way");
  }
  EXPECT_EQ(ChosenSequencing(Drape(100, 100), kAutoSequencing), 5);
  EXPECT_EQ(ChosenSequencing(Drape(100, 100), 1), 1);
}

}  // namespace
}  // namespace drape
