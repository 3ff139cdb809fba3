// What the workbench's tests share: one QApplication for the process (made
// on the first test, under a display), settings kept apart from the user's,
// and how to tell the fabric's pixels in a picture.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

#include <QApplication>
#include <QColor>
#include <QImage>
#include <QSettings>
#include <QStandardPaths>
#include <QSurfaceFormat>

#include "support/display_required.h"
#include "ui/render/display.h"
#include "ui/widgets/vtk_viewport.h"

namespace drape {

// The fabric's face colour (0.93, 0.62, 0.33) or its back (0.47, 0.36,
// 0.62), shaded: saturated orange or violet.
inline bool IsFabric(QRgb p) {
  const QColor c(p);
  const int h = c.hsvHue(), s = c.hsvSaturation();
  return s > 80 && ((h >= 18 && h <= 40) || (h >= 250 && h <= 290));
}

inline int CountFabric(const QImage& image) {
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) n += IsFabric(image.pixel(x, y));
  return n;
}

class Widgets : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!DisplayProblem().empty()) return;
    QSurfaceFormat::setDefaultFormat(VtkViewport::defaultFormat());
    static int argc = 1;
    static char name[] = "widgets_tests";
    static char* argv[] = {name, nullptr};
    // Never destroyed: at exit Qt Charts' statics go before a static
    // QApplication would, and its destructor then crashed the process.
    static QApplication* app = new QApplication(argc, argv);
    (void)app;
    // Settings and autosaves of the tests stay out of the user's own, and
    // out of each other's: ctest runs test processes side by side, and one
    // process's Units choice once turned another's scene to SI mid-test.
    QStandardPaths::setTestModeEnabled(true);
    QApplication::setOrganizationName("Drape Studio tests");
    QApplication::setApplicationName("widgets_tests-" +
                                     QString::number(QCoreApplication::applicationPid()));
    static const std::string settings = QSettings().fileName().toStdString();
    static const std::string data =
        QStandardPaths::writableLocation(QStandardPaths::AppDataLocation).toStdString();
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove(settings, ignored);
      std::filesystem::remove_all(data, ignored);
    });
  }
  void SetUp() override { DRAPE_REQUIRE_DISPLAY(); }
};

}  // namespace drape
