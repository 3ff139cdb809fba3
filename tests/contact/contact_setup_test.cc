// When contact alone must hold the fabric (and is stabilised): the rigid
// motions the held nodes leave free, counted by hand for small cases.
#include <gtest/gtest.h>

#include <array>

#include "core/contact/contact_setup.h"
#include "support/strip_scene.h"

namespace drape {
namespace {

// A 4 × 2-element sheet: nodes 0…4 along y = 0, 5…9 along the middle, 10…14
// along the top (structured numbering, x fastest).
ShellModel Sheet() {
  test::StripSpec spec;
  Scene scene = test::CantileverStrip(spec);
  scene.fabric.mesh.elements = std::array<int, 2>{4, 2};
  return BuildShellModel(scene);
}

bool Restrained(const ShellModel& model, std::initializer_list<std::pair<int, Fixity>> held) {
  DofMap dofs(model.NodeCount());
  for (auto [node, fixity] : held) dofs.FixNode(node, fixity);
  return HoldsRestrainRigidMotion(model, dofs);
}

TEST(ContactSetup, HeldNodesRestrainRigidMotionOnlyOffOneLine) {
  const ShellModel model = Sheet();
  ASSERT_EQ(model.NodeCount(), 15);
  // Nothing held, or one pinned node: translations or rotations free.
  EXPECT_FALSE(Restrained(model, {}));
  EXPECT_FALSE(Restrained(model, {{7, Fixity::kPosition}}));
  // Pins on one line leave the rotation about it.
  EXPECT_FALSE(Restrained(model, {{0, Fixity::kPosition}, {4, Fixity::kPosition}}));
  EXPECT_FALSE(
      Restrained(model, {{0, Fixity::kPosition}, {2, Fixity::kPosition}, {4, Fixity::kPosition}}));
  // A third pin off that line stops them all.
  EXPECT_TRUE(
      Restrained(model, {{0, Fixity::kPosition}, {4, Fixity::kPosition}, {12, Fixity::kPosition}}));
  // A clamp also fixes the director: with a second held node, the rotation
  // about the line through both would turn the clamped director.
  EXPECT_TRUE(Restrained(model, {{0, Fixity::kClamp}, {4, Fixity::kPosition}}));
  // One clamped node alone still turns freely about its own director (no
  // drilling DOF).
  EXPECT_FALSE(Restrained(model, {{0, Fixity::kClamp}}));
}

}  // namespace
}  // namespace drape
