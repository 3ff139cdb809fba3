// The workbench's exports without the window (ui/widgets/export_controller):
// what each refuses before there is anything to write, and what each writes
// of a run solved here — a picture of the step asked for at the view's size,
// a frame per state, a VTU per state.
#include "ui/widgets/export_controller.h"

#include <QImage>

#include <unistd.h>
#include <filesystem>

#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"
#include "gui_test.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

TEST_F(Widgets, ExportsRefuseWhatTheyCannotWriteAndWriteEveryState) {
  const Scene scene = ReadScene(test::ScenesDir() / "strip-convergence-20.json");
  const ShellModel model = BuildShellModel(scene);
  std::vector<std::shared_ptr<const StepState>> steps;
  ExportController exports(nullptr);
  RenderOptions view;
  view.width = 320;
  view.height = 200;
  const fs::path dir = fs::temp_directory_path() / ("drape-exports-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);

  // Nothing open, nothing run, or a run still going: one reason, no file.
  ExportOutcome none = exports.Image({&scene, nullptr, &steps, 0, false}, view, "x.png");
  EXPECT_FALSE(none.written);
  EXPECT_EQ(none.message.toStdString(), "nothing to draw: open a scene first");
  const ExportedRun unsolved{&scene, &model, &steps, 0, false};
  EXPECT_EQ(exports.Animation(unsolved, view, QString::fromStdString((dir / "a").string()), 25)
                .message.toStdString(),
            "nothing to animate: run the scene first");
  EXPECT_EQ(
      exports.Vtu(unsolved, QString::fromStdString((dir / "v").string())).message.toStdString(),
      "nothing to export: run the scene first");
  EXPECT_FALSE(fs::exists(dir / "a"));
  EXPECT_FALSE(fs::exists(dir / "v"));

  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  ASSERT_TRUE(solver
                  .Solve({[&](const StepState& s) {
                    steps.push_back(std::make_shared<const StepState>(s));
                    return StepDecision::kContinue;
                  }})
                  .IsComplete());
  const int count = static_cast<int>(steps.size());
  EXPECT_FALSE(exports.Vtu({&scene, &model, &steps, count, true}, "v").written);  // running

  const ExportedRun run{&scene, &model, &steps, count / 2, false};
  const QString png = QString::fromStdString((dir / "half.png").string());
  const ExportOutcome image = exports.Image(run, view, png);
  ASSERT_TRUE(image.written) << image.message.toStdString();
  EXPECT_EQ(image.message, "wrote " + png);
  const QImage picture(png);
  EXPECT_EQ(picture.size(), QSize(320, 200));
  EXPECT_GT(CountFabric(picture), 200);

  const ExportOutcome frames =
      exports.Animation(run, view, QString::fromStdString((dir / "frames").string()), 25);
  ASSERT_TRUE(frames.written) << frames.message.toStdString();
  int pngs = 0;
  for (const auto& f : fs::directory_iterator(dir / "frames"))
    pngs += f.path().extension() == ".png";
  EXPECT_EQ(pngs, count + 1);  // the reference state and every step

  const ExportOutcome vtu = exports.Vtu(run, QString::fromStdString((dir / "vtu").string()));
  ASSERT_TRUE(vtu.written) << vtu.message.toStdString();
  int vtus = 0;
  for (const auto& f : fs::directory_iterator(dir / "vtu")) vtus += f.path().extension() == ".vtu";
  EXPECT_EQ(vtus, count + 1);
  EXPECT_TRUE(fs::exists(dir / "vtu" / "run.pvd"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace drape
