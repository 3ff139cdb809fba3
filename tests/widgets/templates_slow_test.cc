// The templates beyond "Start here" (the paper's experiments, more
// examples): each opens untitled from its menu item, runs and converges on
// a stable rest state. Slow tier: together they take minutes.
#include "widgets/template_run.h"

namespace drape {
namespace {

class ExampleTemplate : public Widgets, public ::testing::WithParamInterface<SceneTemplate> {};

TEST_P(ExampleTemplate, OpensRunsAndConverges) {
  test::OpenAndRun(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Templates,
                         ExampleTemplate,
                         ::testing::ValuesIn(test::TemplatesOf(1, 99)),
                         test::TemplateName);

}  // namespace
}  // namespace drape
