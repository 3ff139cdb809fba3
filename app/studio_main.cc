// `drape-studio [SCENE] [--run] [--select PART[:INDEX[:MOVE]]] [--units
// SYSTEM] [--screenshot FILE] [--window-screenshot FILE] [--quit]`: the
// workbench. The flags are for scripts and CI: open a scene, choose what
// to edit and the units it is shown in, run it, save the window's 3-D
// view, quit.
#include <QApplication>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QImage>
#include <QMessageBox>
#include <QSurfaceFormat>
#include <QTimer>

#include <cstdio>

#include "ui/widgets/main_window.h"
#include "ui/widgets/model_tree.h"
#include "ui/widgets/unit_settings.h"
#include "ui/widgets/vtk_viewport.h"

namespace {

// The screenshots and the quit, once the view shows what was asked for.
void Finish(drape::MainWindow& window,
            const QString& screenshot,
            const QString& window_shot,
            bool quit) {
  // Let the last step reach the screen before grabbing it.
  QTimer::singleShot(200, &window, [&window, screenshot, window_shot, quit] {
    int status = 0;
    if (!screenshot.isEmpty()) {
      const QImage image = window.viewport()->grabFramebuffer();
      if (image.isNull() || !image.save(screenshot)) {
        std::fprintf(
            stderr, "drape-studio: cannot write the screenshot %s\n", qPrintable(screenshot));
        status = 1;
      }
    }
    if (!window_shot.isEmpty() && !window.grab().save(window_shot)) {
      std::fprintf(
          stderr, "drape-studio: cannot write the screenshot %s\n", qPrintable(window_shot));
      status = 1;
    }
    if (quit) QApplication::exit(status);
  });
}

// "stages:1:0" → the tree's item for stage 1's move 0 (0-based), chosen.
bool Select(drape::MainWindow& window, const QString& spec) {
  using Part = drape::ModelTree::Part;
  const QStringList parts = spec.split(':');
  const QStringList names = {"fabric",
                             "material",
                             "supports",
                             "grippers",
                             "obstacles",
                             "stages",
                             "probes",
                             "solver",
                             "loads"};
  const int part = static_cast<int>(names.indexOf(parts[0]));
  bool ok = part >= 0 && parts.size() <= 3;
  const int index = parts.size() > 1 ? parts[1].toInt(&ok) : -1;
  if (!ok) return false;
  const int move = parts.size() > 2 ? parts[2].toInt(&ok) : -1;
  QTreeWidgetItem* item = ok ? window.tree()->item(static_cast<Part>(part), index, move) : nullptr;
  if (!item) return false;
  window.tree()->setCurrentItem(item);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(drape::VtkViewport::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setApplicationName("Drape Studio");
  QApplication::setOrganizationName("Drape Studio");
  QApplication::setApplicationVersion(DRAPE_VERSION);

  QCommandLineParser parser;
  parser.setApplicationDescription("Drape Studio: simulate, fold and drape fabric parts");
  parser.addHelpOption();
  parser.addPositionalArgument("scene", "Scene file to open");
  const QCommandLineOption run("run", "Run the scene once it is open");
  const QCommandLineOption screenshot("screenshot", "Save the 3-D view to FILE (PNG)", "FILE");
  const QCommandLineOption window_shot(
      "window-screenshot", "Save the whole window to FILE", "FILE");
  const QCommandLineOption quit("quit",
                                "Quit when the run (if any) is done and the screenshot saved");
  const QCommandLineOption select(
      "select",
      "Choose what to edit, as in the scene tree: fabric, material, supports, grippers, "
      "loads, obstacles, stages, probes or solver, with an index and a move (0-based), e.g. "
      "stages:1:0",
      "PART[:INDEX[:MOVE]]");
  const QCommandLineOption units(
      "units",
      "Show quantities in si, textile (cm, gf), imperial (in, oz) or the scene's own units, "
      "for this session (the Units menu's choice stays as saved)",
      "SYSTEM");
  parser.addOptions({run, select, units, screenshot, window_shot, quit});
  parser.process(app);
  const QString units_name = parser.value(units);
  const auto system = drape::UnitSystemNamed(units_name.toStdString());
  if (parser.isSet(units) && !system && units_name != "scene") {
    std::fprintf(stderr,
                 "drape-studio: --units %s: one of si, textile, imperial, scene\n",
                 qPrintable(units_name));
    return 1;
  }

  drape::MainWindow window;
  if (parser.isSet(units)) window.units()->useChoice(system);
  window.show();
  // An autosave left behind is a crash's: offer it back (not to scripts).
  if (!parser.isSet(quit) && QFileInfo::exists(drape::MainWindow::autosavePath()) &&
      QMessageBox::question(&window,
                            "Recover",
                            "Drape Studio did not close cleanly last time. "
                            "Recover the autosaved scene?") == QMessageBox::Yes)
    window.recoverAutosave();
  const QStringList scenes = parser.positionalArguments();
  if (!scenes.isEmpty() && !window.openScene(scenes.front())) {
    std::fprintf(stderr, "drape-studio: cannot open %s\n", qPrintable(scenes.front()));
    if (parser.isSet(quit)) return 1;
  }
  if (parser.isSet(select) && !Select(window, parser.value(select))) {
    std::fprintf(stderr,
                 "drape-studio: --select %s: no such part of the scene\n",
                 qPrintable(parser.value(select)));
    if (parser.isSet(quit)) return 1;
  }
  const QString shot = parser.value(screenshot);
  const QString whole = parser.value(window_shot);
  const bool quitting = parser.isSet(quit);
  if (parser.isSet(run) && !scenes.isEmpty()) {
    QObject::connect(&window,
                     &drape::MainWindow::runFinished,
                     &window,
                     [&window, shot, whole, quitting](const drape::SolveSummary& summary) {
                       std::fprintf(stderr, "%s\n", summary.BriefReport().c_str());
                       Finish(window, shot, whole, quitting);
                     });
    QTimer::singleShot(0, &window, [&window] { window.run(); });
  } else if (!shot.isEmpty() || !whole.isEmpty() || quitting) {
    Finish(window, shot, whole, quitting);
  }
  return app.exec();
}
