// The templates beyond "Start here" (the paper's experiments, more
// examples): each opens untitled from its menu item, runs and converges on
// a stable rest state. Slow tier: together they take minutes.
#include "widgets/template_run.h"

namespace drape {
namespace {

class ExampleTemplate : public Widgets, public ::testing::WithParamInterface<SceneTemplate> {};

// The skirt on the dress form runs at the draft preset (36 s instead of
// 114 s): its full run is checked from the command line (SkirtOnForm,
// tests/verification), and this test is about the workbench opening and
// running the template.
TEST_P(ExampleTemplate, OpensRunsAndConverges) {
  const bool skirt = GetParam().title.contains("Skirt");
  test::OpenAndRun(GetParam(), skirt ? "draft" : nullptr);
}

INSTANTIATE_TEST_SUITE_P(Templates,
                         ExampleTemplate,
                         ::testing::ValuesIn(test::TemplatesOf(1, 99)),
                         test::TemplateName);

}  // namespace
}  // namespace drape
