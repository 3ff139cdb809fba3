// The Qt 6 ↔ VTK viewport under Xvfb: the fabric's pixels must reach the
// widget's framebuffer (a naive bridge renders black), and the workbench
// shows a run's steps as they arrive. Qt's QTest waits for the window.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRendererCollection.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTest>
#include <QUndoStack>

#include "core/io/scene_reader.h"
#include "core/measure/drape_test_setup.h"
#include "core/solve/shell_solver.h"
#include "support/strip_scene.h"
#include "support/test_paths.h"
#include "ui/render/display.h"
#include "ui/render/frame_renderer.h"
#include "ui/widgets/holds_panel.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/material_dialog.h"
#include "ui/widgets/property_panel.h"
#include "ui/widgets/run_plot.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/stages_panel.h"
#include "ui/widgets/view_controller.h"
#include "ui/widgets/vtk_viewport.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

TEST_F(Widgets, ViewportShowsTheFabricNotBlack) {
  test::StripSpec spec;
  spec.width = 0.1;
  Scene scene = test::CantileverStrip(spec);
  scene.fabric.mesh.elements = std::array<int, 2>{20, 10};
  const ShellModel model = BuildShellModel(scene);
  VtkViewport viewport;
  viewport.resize(480, 320);
  viewport.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&viewport));
  ShellState state = model.reference;
  RenderOptions options;
  options.camera.view = "top";
  viewport.makeCurrent();
  FrameRenderer renderer(
      scene, model, options, RunBounds(scene, {&state}), std::nullopt, viewport.renderWindow());
  viewport.doneCurrent();
  Frame frame;
  frame.state = &state;
  renderer.Update(frame);
  viewport.requestRender();
  QTest::qWait(100);
  const QImage image = viewport.grabFramebuffer();
  ASSERT_FALSE(image.isNull());
  EXPECT_EQ(image.width(), 480);
  int black = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) black += qGray(image.pixel(x, y)) < 10;
  const int fabric = CountFabric(image);
  std::printf("viewport 480 x 320: %d fabric pixels, %d black\n", fabric, black);
  // The 20 × 10 cm sheet fills about half the width from the top: tens of
  // thousands of pixels; the background is light, never black.
  EXPECT_GT(fabric, 10000);
  EXPECT_LT(black, 480 * 320 / 100);
  viewport.makeCurrent();
}

TEST_F(Widgets, WorkbenchShowsEveryStepOfARunInOrder) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.openScene(
      QString::fromStdString((test::ScenesDir() / "strip-convergence-20.json").string())));
  QSignalSpy finished(&window, &MainWindow::runFinished);
  window.run();
  ASSERT_TRUE(finished.wait(60000));
  const auto summary = finished.takeFirst().at(0).value<SolveSummary>();
  EXPECT_TRUE(summary.IsComplete()) << summary.message;
  EXPECT_EQ(window.stepCount(), summary.steps);
  // The live plot has every step and a mark per stability change.
  EXPECT_EQ(window.plot()->points(), summary.steps);
  EXPECT_EQ(window.plot()->stabilityMarks(), static_cast<int>(summary.stability_events.size()));
  QTest::qWait(100);
  const QImage shown = window.viewport()->grabFramebuffer();
  // A screenshot looks like the screen: every pixel opaque (VTK clears
  // alpha to 0 unless told; 94 % of a screenshot was once transparent).
  int transparent = 0;
  for (int y = 0; y < shown.height(); ++y)
    for (int x = 0; x < shown.width(); ++x) transparent += qAlpha(shown.pixel(x, y)) != 255;
  EXPECT_EQ(transparent, 0) << "of " << shown.width() * shown.height() << " pixels";
  // The viewport draws what the offscreen renderer draws of the last step
  // (the same builder, camera and size): the same fabric, to a few pixels
  // of rasterisation.
  const Scene scene = ReadScene(test::ScenesDir() / "strip-convergence-20.json");
  const ShellModel model = BuildShellModel(scene);
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  StepState last;
  solver.Solve({[&](const StepState& s) {
    last = s;
    return StepDecision::kContinue;
  }});
  Eigen::AlignedBox3d bounds = RunBounds(scene, {&model.reference});
  for (const auto& p : GripperPathPoints(scene, model)) bounds.extend(p);
  RenderOptions options;
  options.width = shown.width();
  options.height = shown.height();
  FrameRenderer offscreen(scene, model, options, bounds);
  Frame frame;
  frame.state = &last.state;
  frame.step = last.step;
  frame.stage_name = last.stage_name;
  frame.lambda = last.lambda;
  offscreen.Show(frame);
  const std::vector<unsigned char> rgb = offscreen.CaptureRgb();
  int expected = 0;
  for (size_t i = 0; i + 2 < rgb.size(); i += 3)
    expected += IsFabric(qRgb(rgb[i], rgb[i + 1], rgb[i + 2]));
  const int fabric = CountFabric(shown);
  std::printf("fabric pixels: viewport %d, offscreen %d\n", fabric, expected);
  if (getenv("DRAPE_COMPARE_SHOT")) {  // to look at both
    shown.save(QString(getenv("DRAPE_COMPARE_SHOT")) + "-viewport.png");
    offscreen.WritePng(std::string(getenv("DRAPE_COMPARE_SHOT")) + "-offscreen.png");
  }
  EXPECT_GT(expected, 2000);
  EXPECT_NEAR(fabric, expected, 0.01 * expected);
}

// The Cusick test in the workbench: every step shown says its drape
// coefficient and node count under the view, as `drape measure` computes
// them for that state; the shadow is drawn under the part; a scene that is
// no drape test shows no such label.
TEST_F(Widgets, TheCusickTestShowsItsDrapeCoefficientForTheStepShown) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  const auto file = test::ScenesDir() / "cusick-drape.json";
  ASSERT_TRUE(window.openScene(QString::fromStdString(file.string())));
  ViewController* view = window.view();
  EXPECT_TRUE(view->drapeLabel()->isVisibleTo(&window));
  EXPECT_EQ(view->drapeLabel()->text().toStdString(), "drape coefficient 1.000 · 0 nodes");
  QSignalSpy finished(&window, &MainWindow::runFinished);
  window.run();
  ASSERT_TRUE(finished.wait(60000));
  ASSERT_GT(window.stepCount(), 1);
  const Scene scene = ReadScene(file);
  for (int shown : {1, window.stepCount()}) {
    view->timeline()->setValue(shown);
    const DrapeMeasurement m =
        MeasureDrape(view->step(shown).state.positions,
                     view->model()->mesh.quads,
                     DrapeTestFor(scene, view->model()->mesh, std::nullopt, std::nullopt));
    char expected[96];
    std::snprintf(expected,
                  sizeof expected,
                  "drape coefficient %.3f · %zu %s",
                  m.drape_coefficient,
                  m.nodes.size(),
                  m.nodes.size() == 1 ? "node" : "nodes");
    EXPECT_EQ(view->drapeLabel()->text().toStdString(), expected) << "step " << shown;
  }
  EXPECT_LT(std::stod(view->drapeLabel()->text().mid(18, 5).toStdString()), 0.95);
  // The shadow: dark slate pixels under the part in the default view.
  QTest::qWait(100);
  const QImage shown = window.viewport()->grabFramebuffer();
  int slate = 0;
  for (int y = 0; y < shown.height(); ++y)
    for (int x = 0; x < shown.width(); ++x) {
      const QRgb p = shown.pixel(x, y);
      slate += qBlue(p) > qRed(p) + 15 && qRed(p) < 90;
    }
  EXPECT_GT(slate, 500) << "of " << shown.width() * shown.height() << " pixels";

  ASSERT_TRUE(window.openScene(
      QString::fromStdString((test::ScenesDir() / "strip-convergence-20.json").string())));
  EXPECT_FALSE(window.view()->drapeLabel()->isVisibleTo(&window));
}

// "ffprobe" of a movie: "width,height,frames".
std::string Probe(const std::string& movie) {
  FILE* pipe = popen(("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                      "stream=width,height,nb_read_frames -of csv=p=0 '" +
                      movie + "' 2>&1")
                         .c_str(),
                     "r");
  std::string out;
  char buf[256];
  while (fgets(buf, sizeof buf, pipe)) out += buf;
  pclose(pipe);
  while (!out.empty() && (out.back() == '\n' || out.back() == ',')) out.pop_back();
  return out;
}

// Run controls answer while the solver works: paused, no step arrives;
// Step lets exactly one through; Stop ends the run keeping every step, in
// order. Then the timeline scrubs and the run exports a PNG and an MP4.
TEST_F(Widgets, RunPausesStepsStopsScrubsAndExports) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(
      window.openScene(QString::fromStdString((test::ScenesDir() / "strip-fold.json").string())));
  QSignalSpy finished(&window, &MainWindow::runFinished);
  // Paused at once: the solver runs the whole fold in a fifth of a second,
  // so waiting for steps first would race it to the end.
  window.run();
  window.pauseOrResume();
  ASSERT_TRUE(window.isPaused());
  QTest::qWait(300);  // a step that converged as the pause came still arrives
  const int paused_at = window.stepCount();
  for (int k = 0; k < 2; ++k) {
    window.stepOnce();
    ASSERT_TRUE(QTest::qWaitFor([&] { return window.stepCount() == paused_at + k + 1; }, 10000));
  }
  QTest::qWait(300);
  ASSERT_EQ(window.stepCount(), paused_at + 2) << "Step let more than one step through";
  QTest::qWait(500);
  EXPECT_EQ(window.stepCount(), paused_at + 2) << "steps arrived while paused";
  window.stepOnce();
  ASSERT_TRUE(QTest::qWaitFor([&] { return window.stepCount() == paused_at + 3; }, 10000));
  QTest::qWait(300);
  EXPECT_EQ(window.stepCount(), paused_at + 3) << "Step let more than one step through";
  // Resume and pause again at once (the solver runs the whole fold in a
  // fifth of a second: waiting for steps to show would let it finish), then
  // stop from the pause.
  window.pauseOrResume();
  window.pauseOrResume();
  ASSERT_TRUE(window.isPaused());
  QTest::qWait(300);
  window.stop();
  // (A signal already caught counts: wait() only sees new ones.)
  ASSERT_TRUE(finished.count() > 0 || finished.wait(30000));
  const auto summary = finished.takeFirst().at(0).value<SolveSummary>();
  EXPECT_EQ(summary.termination, Termination::kCancelled) << summary.message;
  ASSERT_EQ(window.stepCount(), summary.steps);
  for (int i = 1; i <= window.stepCount(); ++i) EXPECT_EQ(window.step(i).step, i);
  EXPECT_LT(summary.steps, 58);  // stopped before the end

  window.showStep(2);
  EXPECT_EQ(window.currentStep(), 2);
  // One renderer in the view, however often the view was rebuilt (a field
  // chosen rebuilds it).
  ASSERT_TRUE(window.setField("curvature"));
  ASSERT_TRUE(window.setField(""));
  EXPECT_EQ(window.viewport()->renderWindow()->GetRenderers()->GetNumberOfItems(), 1);
  const std::string dir =
      (std::filesystem::temp_directory_path() / ("drape-gui-" + std::to_string(getpid()))).string();
  std::filesystem::create_directories(dir);
  QString error;
  ASSERT_TRUE(window.exportImage(QString::fromStdString(dir + "/step2.png"), &error))
      << error.toStdString();
  const QImage png(QString::fromStdString(dir + "/step2.png"));
  EXPECT_EQ(png.size(), window.viewport()->size());
  EXPECT_GT(CountFabric(png), 1000);
  ASSERT_TRUE(window.setField("curvature"));
  ASSERT_TRUE(window.exportAnimation(QString::fromStdString(dir + "/run.mp4"), 25, &error))
      << error.toStdString();
  const QSize size = window.viewport()->size();
  EXPECT_EQ(Probe(dir + "/run.mp4"),
            std::to_string(size.width() + size.width() % 2) + "," +
                std::to_string(size.height() + size.height() % 2) + "," +
                std::to_string(window.stepCount() + 1));

  // VTU of every state, as `drape export` writes them: the last file holds
  // the last step's nodes where the run put them.
  ASSERT_TRUE(window.exportVtu(QString::fromStdString(dir + "/vtu"), &error))
      << error.toStdString();
  int vtu = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir + "/vtu"))
    vtu += entry.path().extension() == ".vtu";
  EXPECT_EQ(vtu, window.stepCount() + 1);
  EXPECT_TRUE(std::filesystem::exists(dir + "/vtu/run.pvd"));
  char last[64];
  std::snprintf(last, sizeof last, "/vtu/step_%04d.vtu", window.stepCount());
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName((dir + last).c_str());
  reader->Update();
  const auto& x = window.step(window.stepCount()).state.positions;
  ASSERT_EQ(reader->GetOutput()->GetNumberOfPoints(), x.rows());
  double worst = 0;
  for (vtkIdType i = 0; i < x.rows(); ++i) {
    const double* p = reader->GetOutput()->GetPoint(i);
    worst = std::max(worst, (Eigen::Vector3d(p[0], p[1], p[2]) - x.row(i).transpose()).norm());
  }
  EXPECT_LT(worst, 1e-15);  // written as doubles
  std::filesystem::remove_all(dir);
}

// Edits through the property panel: each accepted value is one undoable
// edit; a bad one shows why and keeps the last valid value; the scene saved
// and read back is the edited scene.
TEST_F(Widgets, EditsUndoRedoAndSurviveSaveAndReopen) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(
      window.openScene(QString::fromStdString((test::ScenesDir() / "strip-fold.json").string())));
  SceneDocument* doc = window.document();
  PropertyPanel* panel = window.properties();
  const Scene original = doc->scene();

  panel->elementsX()->setValue(40);
  emit panel->elementsX()->editingFinished();
  ASSERT_TRUE(doc->scene().fabric.mesh.elements);
  EXPECT_EQ((*doc->scene().fabric.mesh.elements)[0], 40);
  EXPECT_EQ(panel->meshInfo()->text().toStdString(), "123 nodes, 80 elements, 615 DOFs");

  QLineEdit* h = panel->thickness()->edit();
  h->setText("0.6 mm");
  emit h->editingFinished();
  EXPECT_DOUBLE_EQ(doc->scene().material.thickness, 0.6e-3);

  // Bad input: a message, the last valid value back, the scene unchanged.
  h->setText("0.6 kg");
  emit h->editingFinished();
  EXPECT_NE(panel->thickness()->message().toStdString().find("length"), std::string::npos)
      << panel->thickness()->message().toStdString();
  EXPECT_EQ(h->text().toStdString(), "0.6 mm");
  h->setText("-1 mm");
  emit h->editingFinished();
  EXPECT_EQ(panel->thickness()->message().toStdString(), "must be > 0");
  EXPECT_DOUBLE_EQ(doc->scene().material.thickness, 0.6e-3);

  QUndoStack* undo = doc->undoStack();
  EXPECT_EQ(undo->count(), 2);
  undo->undo();
  EXPECT_EQ(doc->scene().material.thickness, original.material.thickness);
  undo->undo();
  EXPECT_EQ(doc->scene(), original);
  undo->redo();
  undo->redo();
  EXPECT_DOUBLE_EQ(doc->scene().material.thickness, 0.6e-3);
  EXPECT_EQ((*doc->scene().fabric.mesh.elements)[0], 40);

  // Saved (the strip fold names no files) and read back: equal.
  const std::string file =
      (std::filesystem::temp_directory_path() / ("edited-" + std::to_string(getpid()) + ".json"))
          .string();
  ASSERT_TRUE(window.saveScene(QString::fromStdString(file)));
  const Scene reread = ReadScene(file);
  std::filesystem::remove(file);
  EXPECT_EQ(reread, doc->scene());
  EXPECT_FALSE(doc->isModified());
}

// The material dialog: a Kawabata file read with the scene reader's code,
// drawn with its law, applied as one undoable edit; a bad file says which
// line; a library material replaces the material.
TEST_F(Widgets, MaterialDialogImportsKawabataDataAndLibraryMaterials) {
  MainWindow window;
  ASSERT_TRUE(
      window.openScene(QString::fromStdString((test::ScenesDir() / "strip-fold.json").string())));
  SceneDocument* doc = window.document();
  const Scene original = doc->scene();
  MaterialDialog dialog(doc);
  const std::string csv =
      (test::SourceDir() / "resources/materials/kawabata/cotton-twill-warp.csv").string();
  dialog.file()->setText(QString::fromStdString(csv));
  ASSERT_TRUE(dialog.preview()) << dialog.message().toStdString();
  EXPECT_EQ(dialog.measuredPoints(), 51);  // −2.5 … 2.5 1/cm, branches averaged
  // The dialog says which columns it read, in which units.
  EXPECT_NE(dialog.message().toStdString().find("in 1/cm"), std::string::npos)
      << dialog.message().toStdString();
  ASSERT_TRUE(dialog.applyBending());
  const auto& curve = std::get<CurveBending>(doc->scene().material.bending.warp);
  ASSERT_EQ(curve.points.size(), 51u);
  // At K = 1 1/cm the averaged data are the paper's law, Σ cₖ gf·cm/cm.
  EXPECT_NEAR(
      curve.points[35][1], (1.33387 - 2.23070 + 2.36510 - 1.08471 + 0.17876) * 9.80665e-3, 1e-12);
  // The polynomial fit of the same data: the paper's coefficients back (SI).
  dialog.law()->setCurrentIndex(dialog.law()->findData("polynomial"));
  ASSERT_TRUE(dialog.preview());
  if (getenv("DRAPE_DIALOG_SHOT")) {
    dialog.show();
    QTest::qWait(200);
    dialog.grab().save(getenv("DRAPE_DIALOG_SHOT"));
  }
  ASSERT_TRUE(dialog.applyBending());
  const auto& poly = std::get<PolynomialBending>(doc->scene().material.bending.warp);
  EXPECT_NEAR(poly.coefficients[0], 1.33387 * 9.80665e-5, 1e-9);
  // The polynomial for the weft only: the warp keeps it, the weft is new.
  dialog.law()->setCurrentIndex(dialog.law()->findData("curve"));
  ASSERT_TRUE(dialog.preview());
  dialog.direction()->setCurrentIndex(dialog.direction()->findData("weft"));
  ASSERT_TRUE(dialog.applyBending()) << dialog.message().toStdString();
  const Bending& both = doc->scene().material.bending;
  EXPECT_TRUE(std::holds_alternative<PolynomialBending>(both.warp));
  ASSERT_TRUE(both.weft.has_value());
  EXPECT_TRUE(std::holds_alternative<CurveBending>(*both.weft));
  // And for the warp only: the weft's curve stays.
  dialog.direction()->setCurrentIndex(dialog.direction()->findData("warp"));
  ASSERT_TRUE(dialog.applyBending());
  EXPECT_TRUE(std::holds_alternative<CurveBending>(doc->scene().material.bending.warp));
  EXPECT_TRUE(std::holds_alternative<CurveBending>(*doc->scene().material.bending.weft));
  doc->undoStack()->undo();
  doc->undoStack()->undo();
  dialog.direction()->setCurrentIndex(dialog.direction()->findData("both"));
  doc->undoStack()->undo();
  doc->undoStack()->undo();
  EXPECT_EQ(doc->scene(), original);
  doc->undoStack()->redo();  // the measured curve again
  ASSERT_TRUE(std::holds_alternative<CurveBending>(doc->scene().material.bending.warp));
  // Saved and reopened: the same scene, the curve read again from its file.
  const std::string saved =
      (std::filesystem::temp_directory_path() / ("material-" + std::to_string(getpid()) + ".json"))
          .string();
  ASSERT_TRUE(window.saveScene(QString::fromStdString(saved)));
  const Scene reread = ReadScene(saved);
  std::filesystem::remove(saved);
  EXPECT_EQ(reread, doc->scene());

  const auto bad = std::filesystem::temp_directory_path() / "drape-dialog-bad.csv";
  std::ofstream(bad) << "curvature (1/cm),moment (gf*cm/cm)\n0,0\n0.1,x\n";
  dialog.file()->setText(QString::fromStdString(bad.string()));
  EXPECT_FALSE(dialog.preview());
  EXPECT_NE(dialog.message().toStdString().find("line 3"), std::string::npos)
      << dialog.message().toStdString();
  EXPECT_FALSE(dialog.applyBending());
  std::filesystem::remove(bad);

  ASSERT_TRUE(dialog.chooseLibrary("cotton-twill"));
  ASSERT_TRUE(dialog.applyLibrary()) << dialog.message().toStdString();
  EXPECT_DOUBLE_EQ(doc->scene().material.thickness, 0.0489e-2);
  EXPECT_TRUE(std::holds_alternative<PolynomialBending>(doc->scene().material.bending.warp));
}

// After a crash the edits come back: autosaved, then recovered by a new
// window as an undoable edit; opened files are remembered.
TEST_F(Widgets, AutosavedEditsAreRecoveredAndFilesRemembered) {
  const QString scene = QString::fromStdString((test::ScenesDir() / "strip-fold.json").string());
  Scene edited;
  {
    MainWindow window;
    ASSERT_TRUE(window.openScene(scene));
    EXPECT_EQ(window.recentFiles().value(0), QFileInfo(scene).absoluteFilePath());
    QLineEdit* h = window.properties()->thickness()->edit();
    h->setText("0.7 mm");
    emit h->editingFinished();
    edited = window.document()->scene();
    ASSERT_TRUE(window.autosave());
    ASSERT_TRUE(QFileInfo::exists(MainWindow::autosavePath()));
  }  // no close: as if it crashed
  MainWindow again;
  ASSERT_TRUE(again.recoverAutosave());
  EXPECT_EQ(again.document()->scene(), edited);
  EXPECT_TRUE(again.document()->isModified());
  again.document()->undoStack()->undo();
  EXPECT_DOUBLE_EQ(again.document()->scene().material.thickness, 0.0469e-2);
  QFile::remove(MainWindow::autosavePath());
}

// A template opens as a new scene; saved elsewhere it keeps finding the
// files it names (the dress form's mesh).
TEST_F(Widgets, TemplateSavedElsewhereStillFindsItsFiles) {
  MainWindow window;
  ASSERT_TRUE(window.newFromTemplate(
      QString::fromStdString((test::ScenesDir() / "dress-form-drape.json").string())));
  EXPECT_TRUE(window.document()->file().isEmpty());
  // Contact pressure has no values before a run: a message, no crash.
  EXPECT_TRUE(window.setField("pressure"));
  EXPECT_NE(window.statusBar()->currentMessage().toStdString().find("contact pressure"),
            std::string::npos)
      << window.statusBar()->currentMessage().toStdString();
  const std::string file =
      (std::filesystem::temp_directory_path() / ("scarf-" + std::to_string(getpid()) + ".json"))
          .string();
  ASSERT_TRUE(window.saveScene(QString::fromStdString(file)));
  const Scene reread = ReadScene(file);  // throws if the mesh is not found
  std::filesystem::remove(file);
  ASSERT_FALSE(reread.obstacles.empty());
  const auto& mesh = std::get<MeshShape>(reread.obstacles[0].shape);
  EXPECT_TRUE(std::filesystem::path(mesh.file).is_absolute()) << mesh.file;
  EXPECT_TRUE(std::filesystem::exists(mesh.file));
}

// Stages: Δλ₀ and control edited, order changed, each undoable; an order
// the scene reader refuses is refused with its message.
TEST_F(Widgets, StagesEditAndReorderWithTheReadersRules) {
  MainWindow window;
  ASSERT_TRUE(
      window.openScene(QString::fromStdString((test::ScenesDir() / "strip-fold.json").string())));
  SceneDocument* doc = window.document();
  StagesPanel* panel = window.stages();
  const Scene original = doc->scene();
  ASSERT_EQ(panel->list()->count(), 3);  // SW, R, T
  panel->list()->setCurrentRow(1);
  ASSERT_TRUE(panel->setIncrement(0.02));
  EXPECT_DOUBLE_EQ(doc->scene().stages[1].initial_increment, 0.02);
  ASSERT_TRUE(panel->setControl(1));
  EXPECT_EQ(doc->scene().stages[1].control, StepControl::kLoad);
  panel->list()->setCurrentRow(2);
  ASSERT_TRUE(panel->moveSelected(-1));  // T before R: a valid order
  EXPECT_EQ(doc->scene().stages[1].name, "T");
  EXPECT_EQ(panel->list()->currentRow(), 1);
  doc->undoStack()->undo();
  doc->undoStack()->undo();
  doc->undoStack()->undo();
  EXPECT_EQ(doc->scene(), original);

  // A last stage that releases the gripper, moved before the arc that
  // moves it: the reader refuses that order, and so does the panel.
  Scene released = original;
  released.stages[2].kind = StageKind::kHold;
  released.stages[2].moves.clear();
  released.stages[2].release = {"end"};
  doc->apply("release the end", released);
  panel->list()->setCurrentRow(2);
  EXPECT_FALSE(panel->moveSelected(-1));
  EXPECT_NE(panel->message().toStdString().find("released"), std::string::npos)
      << panel->message().toStdString();
  EXPECT_EQ(doc->scene(), released);
}

// Supports by selection rules: added, changed, removed as undoable edits;
// a rule that holds no node is refused with the engine's message.
TEST_F(Widgets, SupportsAreEditedByRulesAndCheckedOnTheMesh) {
  MainWindow window;
  ASSERT_TRUE(
      window.openScene(QString::fromStdString((test::ScenesDir() / "strip-fold.json").string())));
  SceneDocument* doc = window.document();
  HoldsPanel* panel = window.supports();
  const size_t before = doc->scene().supports.size();
  ASSERT_TRUE(panel->add("top", 1)) << panel->message().toStdString();
  ASSERT_EQ(doc->scene().supports.size(), before + 1);
  EXPECT_EQ(doc->scene().supports.back().fix, Fixity::kClamp);
  EXPECT_TRUE(std::holds_alternative<EdgeSelection>(doc->scene().supports.back().select.shape));
  ASSERT_TRUE(panel->setFixity(0));
  EXPECT_EQ(doc->scene().supports.back().fix, Fixity::kPosition);
  // A point 1 m off a 20 cm strip: no node is there.
  EXPECT_FALSE(panel->add("point", 0, 1.0, 1.0));
  EXPECT_FALSE(panel->message().isEmpty());
  EXPECT_EQ(doc->scene().supports.size(), before + 1);
  ASSERT_TRUE(panel->removeSelected());
  EXPECT_EQ(doc->scene().supports.size(), before);
  doc->undoStack()->undo();  // the removal
  EXPECT_EQ(doc->scene().supports.size(), before + 1);
}

// The automation CI uses: open, run, screenshot, quit.
TEST_F(Widgets, StudioRunsAScriptAndWritesANonBlackScreenshot) {
  const std::string shot = (std::filesystem::temp_directory_path() /
                            ("drape-studio-" + std::to_string(getpid()) + ".png"))
                               .string();
  const std::string command = std::string(test::DrapeStudio()) + " '" +
                              (test::ScenesDir() / "strip-fold.json").string() +
                              "' --run --screenshot '" + shot + "' --quit 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  char buf[512];
  while (fgets(buf, sizeof buf, pipe)) out += buf;
  const int status = pclose(pipe);
  ASSERT_EQ(status, 0) << out;
  // The same count of steps as the engine run directly.
  const Scene scene = ReadScene(test::ScenesDir() / "strip-fold.json");
  const SolveSummary direct = ShellSolver(scene, SolverOptions::FromScene(scene.solver)).Solve({});
  EXPECT_NE(out.find("converged: " + std::to_string(direct.steps) + " steps"), std::string::npos)
      << out;
  const QImage image(QString::fromStdString(shot));
  ASSERT_FALSE(image.isNull()) << shot;
  const int fabric = CountFabric(image);
  std::printf("screenshot %d x %d: %d fabric pixels\n", image.width(), image.height(), fabric);
  EXPECT_GT(fabric, 2000);
  std::filesystem::remove(shot);
}

}  // namespace
}  // namespace drape

namespace drape {
namespace {

// The view's colour map: viridis by default, the rainbow on request, and
// the exported picture in the one chosen. On the flat reference state every
// node's curvature is 0, the low end of the map: viridis's dark violet (hue
// 289°) or the rainbow's blue (240°).
TEST_F(Widgets, TheColourMapIsViridisOrTheRainbowAsChosen) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.openScene(
      QString::fromStdString((test::ScenesDir() / "strip-convergence-20.json").string())));
  ASSERT_TRUE(window.setField("curvature"));
  const std::string dir =
      (std::filesystem::temp_directory_path() / ("drape-colour-map-" + std::to_string(getpid())))
          .string();
  std::filesystem::create_directories(dir);
  auto low_end = [&](const char* name, int low_hue, int high_hue) {
    const QString file = QString::fromStdString(dir + "/" + name + ".png");
    QString error;
    EXPECT_TRUE(window.exportImage(file, &error)) << error.toStdString();
    const QImage image(file);
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) {
        const QColor c(image.pixel(x, y));
        n += c.hsvSaturation() > 120 && c.hsvHue() >= low_hue && c.hsvHue() <= high_hue;
      }
    return n;
  };
  const int viridis = low_end("viridis", 275, 305);
  EXPECT_TRUE(window.setColourMap("rainbow"));
  const int rainbow_in_violet = low_end("rainbow-violet", 275, 305);
  const int rainbow = low_end("rainbow", 225, 255);
  std::printf(
      "low-end pixels: viridis %d; rainbow %d (violet %d)\n", viridis, rainbow, rainbow_in_violet);
  EXPECT_GT(viridis, 500);
  EXPECT_GT(rainbow, 500);
  EXPECT_LT(rainbow_in_violet, viridis / 10);
  EXPECT_FALSE(window.setColourMap("jet"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace drape
