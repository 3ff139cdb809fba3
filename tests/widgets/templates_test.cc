// The templates a user starts from (File ▸ New from template, "Start here":
// the blank scene, fabric over the dress form, the Cusick test, a fold on a
// table): each opens untitled, runs and converges on a stable rest state.
// The other groups' templates: templates_slow_test.cc.
#include "widgets/template_run.h"

namespace drape {
namespace {

class StartTemplate : public Widgets, public ::testing::WithParamInterface<SceneTemplate> {};

TEST_P(StartTemplate, OpensRunsAndConverges) {
  test::OpenAndRun(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Templates,
                         StartTemplate,
                         ::testing::ValuesIn(test::TemplatesOf(0, 0)),
                         test::TemplateName);

}  // namespace
}  // namespace drape
