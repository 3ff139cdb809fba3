// The Plan dock: path numbers chosen from the scene's paths, a plan the
// reader refuses said in its words, a search whose evaluations appear as
// they end (drape run processes), the best path accepted as one edit that
// undoes, and a search stopped midway.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <nlohmann/json.hpp>
#include <variant>

#include "support/test_paths.h"
#include "ui/widgets/editor_docks.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/plan_dock.h"
#include "ui/widgets/scene_document.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

double ArcAngle(const SceneDocument& doc) {
  return std::get<ArcPath>(doc.scene().stages[1].moves[0].path).angle_deg;
}

TEST_F(Widgets, PlanDockSearchesAcceptsTheBestPathAndUndoes) {
  MainWindow window;
  ASSERT_TRUE(
      window.openScene(QString::fromStdString((test::ScenesDir() / "strip-fold.json").string())));
  SceneDocument* doc = window.document();
  PlanDock* dock = window.docks()->plan();
  ASSERT_NE(dock, nullptr);
  dock->setProgram(test::DrapeCli());

  // The strip fold's paths: R's arc (centre x, y, z, angle), T's line.
  ASSERT_EQ(dock->candidates()->count(), 7);
  const int angle = dock->candidates()->findText("R: end, arc angle (deg)");
  ASSERT_GE(angle, 0);
  // Nothing to vary yet: the reader's message, naming the key.
  EXPECT_FALSE(dock->start());
  EXPECT_NE(dock->message().indexOf("parameters: expected at least one parameter"), -1)
      << dock->message().toStdString();

  // The arc 4 degrees short: the end lands 7 mm high.
  auto json = doc->json();
  json["stages"][1]["moves"][0]["path"]["arc"]["angle_deg"] = 176;
  ASSERT_TRUE(doc->tryApplyJson("arc 176 degrees", json));
  ASSERT_TRUE(dock->addParameter(angle));
  EXPECT_FALSE(dock->addParameter(angle));  // once
  EXPECT_EQ(dock->parameters()->item(0, 1)->text(), "166");
  EXPECT_EQ(dock->parameters()->item(0, 2)->text(), "186");
  // Past 180 the end is driven into the table: such runs fail, slowly.
  dock->parameters()->item(0, 2)->setText("180");
  dock->probe()->setCurrentText("end");
  dock->target()->setText("11 cm, 0, 0.07035 cm");
  dock->evaluations()->setValue(8);

  QSignalSpy finished(dock, &PlanDock::finished);
  ASSERT_TRUE(dock->start()) << dock->message().toStdString();
  EXPECT_FALSE(dock->runButton()->isEnabled());
  ASSERT_TRUE(finished.wait(120000));
  const int rows = dock->results()->rowCount();
  EXPECT_GE(rows, 4);
  EXPECT_LE(rows, 8);
  ASSERT_TRUE(dock->best());
  // The first evaluation is the scene as it is: 176 degrees.
  const double first = dock->results()->item(0, 1)->text().toDouble();
  const double best = *dock->best()->outcome.objective * 1e3;
  // 180° lands the end on its target (the bound: COBYLA ends there).
  EXPECT_LT(best, 0.1) << dock->message().toStdString();
  EXPECT_GT(first, 5);
  EXPECT_TRUE(dock->acceptButton()->isEnabled());

  // Accepted: the scene's arc turns by the best angle; undo puts 176 back.
  ASSERT_TRUE(dock->acceptBest()) << dock->message().toStdString();
  EXPECT_NEAR(ArcAngle(*doc), dock->best()->x[0], 1e-9);
  EXPECT_NE(ArcAngle(*doc), 176);
  doc->undoStack()->undo();
  EXPECT_EQ(ArcAngle(*doc), 176);

  // Stopped midway: the search ends, saying so.
  dock->evaluations()->setValue(40);
  ASSERT_TRUE(dock->start());
  dock->stop();
  ASSERT_TRUE(finished.wait(60000));
  EXPECT_NE(dock->message().indexOf("interrupted"), -1) << dock->message().toStdString();
  EXPECT_TRUE(dock->runButton()->isEnabled());
}

}  // namespace
}  // namespace drape
