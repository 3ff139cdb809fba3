// The colour bar in the user's units: its title names the unit and its
// range is the SI range over the unit's factor, for each system. Runs under
// xvfb-run -a.
#include "ui/render/field_units.h"

#include <gtest/gtest.h>
#include <vtkPropCollection.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkScalarsToColors.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "core/mechanics/director.h"
#include "support/bent_strip.h"
#include "support/display_required.h"
#include "support/strip_scene.h"
#include "ui/render/display.h"
#include "ui/render/frame_renderer.h"

namespace drape {
namespace {

class FieldUnitsTest : public ::testing::Test {
 protected:
  void SetUp() override { DRAPE_REQUIRE_DISPLAY(); }
};

vtkScalarBarActor* ScalarBar(FrameRenderer& renderer) {
  vtkPropCollection* props = renderer.renderer()->GetViewProps();
  props->InitTraversal();
  while (vtkProp* p = props->GetNextProp())
    if (auto* bar = vtkScalarBarActor::SafeDownCast(p)) return bar;
  return nullptr;
}

TEST(FieldUnits, TitlesNameTheSystemsUnit) {
  EXPECT_EQ(FieldTitle(FieldKind::kCurvature, UnitSystem::kSI), "curvature [1/m]");
  EXPECT_EQ(FieldTitle(FieldKind::kCurvature, UnitSystem::kTextile), "curvature [1/cm]");
  EXPECT_EQ(FieldTitle(FieldKind::kDisplacement, UnitSystem::kImperial), "displacement [in]");
  EXPECT_EQ(FieldTitle(FieldKind::kBendingMoment, UnitSystem::kTextile),
            "bending moment [gf·cm/cm]");
  EXPECT_EQ(FieldTitle(FieldKind::kMembraneStrain, UnitSystem::kTextile), "membrane strain [-]");
}

// Curvature over the bent strip, SI range [lo, hi] 1/m measured first: the
// bar shows [lo, hi]/100 in 1/cm and [lo, hi] × 0.0254 in 1/in.
TEST_F(FieldUnitsTest, ColourBarShowsTheFieldInTheChosenUnits) {
  test::StripSpec spec;
  Scene scene = test::CantileverStrip(spec);
  scene.probes.clear();
  const ShellModel model = BuildShellModel(scene);
  const ShellState state = test::BentStrip(spec, model);
  const std::array<double, 2> si = FieldRange(FieldKind::kCurvature, model, {&state});
  ASSERT_GT(si[1], 25);  // near the tip's 30 1/m
  const struct {
    UnitSystem system;
    const char* title;
    double per_si;  // shown value per SI value
  } cases[] = {{UnitSystem::kSI, "curvature [1/m]", 1.0},
               {UnitSystem::kTextile, "curvature [1/cm]", 0.01},
               {UnitSystem::kImperial, "curvature [1/in]", 0.0254}};
  for (const auto& c : cases) {
    SCOPED_TRACE(ToString(c.system));
    RenderOptions options;
    options.width = 800;
    options.height = 500;
    options.field = FieldKind::kCurvature;
    options.units = c.system;
    options.camera.view = "top";
    FrameRenderer renderer(scene, model, options, RunBounds(scene, {&state}));
    Frame frame;
    frame.state = &state;
    renderer.Show(frame);
    vtkScalarBarActor* bar = ScalarBar(renderer);
    ASSERT_NE(bar, nullptr);
    EXPECT_EQ(std::string(bar->GetTitle()), c.title);
    const double* range = bar->GetLookupTable()->GetRange();
    EXPECT_NEAR(range[0], si[0] * c.per_si, 1e-9 * si[1]);
    EXPECT_NEAR(range[1], si[1] * c.per_si, 1e-9 * si[1]);
    // A fixed range (an animation's) is given in SI and shown scaled too.
    FrameRenderer fixed(scene, model, options, RunBounds(scene, {&state}), {{0.0, 40.0}});
    fixed.Show(frame);
    EXPECT_NEAR(ScalarBar(fixed)->GetLookupTable()->GetRange()[1], 40.0 * c.per_si, 1e-9);
    if (const char* dir = std::getenv("DRAPE_UNITS_SHOTS"))
      renderer.WritePng(std::string(dir) + "/colour-bar-" + ToString(c.system) + ".png");
  }
}

}  // namespace
}  // namespace drape
