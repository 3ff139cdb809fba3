// `drape`: Drape Studio's command line.
#include <CLI/CLI.hpp>

#include <iostream>

#include "app/commands.h"
#include "app/render_program.h"

int main(int argc, char** argv) {
  CLI::App app{"Drape Studio: nonlinear shell simulation of fabric parts", "drape"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "drape 0.1.0");

  drape::app::RememberCommandLine(argc, argv);
  drape::app::CommandRunner runner;
  drape::app::AddValidateCommand(app, runner);
  drape::app::AddRunCommand(app, runner);
  drape::app::AddDragCommand(app, runner);
  drape::app::AddMaterialCommand(app, runner);
  drape::app::AddMeasureCommand(app, runner);
  drape::app::AddPatternCommand(app, runner);
  drape::app::AddStudyCommand(app, runner);
  drape::app::AddPlanCommand(app, runner);
  // Its DXF outline needs no VTK; its surfaces run in drape-vtk.
  drape::app::AddExportCommand(app, runner);
#if defined(DRAPE_WITH_RENDER) || defined(DRAPE_RENDER_PROGRAM)
  drape::app::AddRenderCommands(app, runner);
  drape::app::AddFrontCommand(app, runner);
  drape::app::AddPlanChartCommand(app, runner);
#endif

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 1;  // bad command line = invalid input
  }
  return runner();
}
