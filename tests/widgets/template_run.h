// A template opened from File ▸ New from template and run in the
// workbench, as a user does: it must open as an untitled scene, run to its
// end and converge on a state a real part can rest in (no negative pivot).
#pragma once

#include <gtest/gtest.h>

#include <QAction>
#include <QElapsedTimer>
#include <QMenu>
#include <QSignalSpy>
#include <QTest>

#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/solve/solve_summary.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_templates.h"
#include "widgets/gui_test.h"

namespace drape {
// How a failing case names its template.
inline void PrintTo(const SceneTemplate& t, std::ostream* out) {
  *out << t.title.toStdString();
}
}  // namespace drape

namespace drape::test {

// The templates of the catalogue's groups `first`…`last` (0: start here).
inline std::vector<SceneTemplate> TemplatesOf(int first, int last) {
  std::vector<SceneTemplate> out;
  const std::vector<TemplateGroup> groups = SceneTemplates();
  for (int g = first; g <= last && g < static_cast<int>(groups.size()); ++g)
    out.insert(out.end(), groups[g].templates.begin(), groups[g].templates.end());
  return out;
}

inline std::string TemplateName(const ::testing::TestParamInfo<SceneTemplate>& info) {
  std::string name;
  for (QChar c : info.param.title)
    if (c.isLetterOrNumber()) name += c.toLatin1();
  return name;
}

// Opens `entry` by its menu item and runs it to its end; with `preset`,
// after choosing that solver preset (as the Solver group's combo does).
inline void OpenAndRun(const SceneTemplate& entry, const char* preset = nullptr) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  QAction* item = nullptr;
  for (QAction* a : window.findChild<QMenu*>("file.templates")->actions())
    if (a->text() == entry.title) item = a;
  ASSERT_NE(item, nullptr) << entry.title.toStdString();
  item->trigger();
  ASSERT_NE(window.document()->model(), nullptr) << window.document()->modelProblem().toStdString();
  EXPECT_TRUE(window.document()->file().isEmpty()) << "a template opens untitled";
  EXPECT_TRUE(window.windowTitle().startsWith("untitled"));
  if (preset) {
    auto document = window.document()->json();
    document["solver"]["preset"] = preset;
    QString problem;
    ASSERT_TRUE(window.document()->tryApplyJson(preset, document, &problem))
        << problem.toStdString();
  }
  QSignalSpy finished(&window, &MainWindow::runFinished);
  QElapsedTimer clock;
  clock.start();
  window.run();
  ASSERT_TRUE(finished.wait(900000)) << "no end in 15 minutes";
  const auto summary = finished.takeFirst().at(0).value<SolveSummary>();
  std::fprintf(stderr,
               "%s: %s (%.1f s)\n",
               qPrintable(entry.title),
               summary.BriefReport().c_str(),
               clock.elapsed() / 1000.0);
  EXPECT_TRUE(summary.IsComplete()) << summary.message;
  EXPECT_EQ(summary.final_negative_pivots, 0);
  EXPECT_GT(window.stepCount(), 0);
}

}  // namespace drape::test
