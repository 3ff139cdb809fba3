#include "ui/render/display.h"

#include <X11/Xlib.h>

#include <chrono>
#include <cstdlib>
#include <thread>

namespace drape {
namespace {

bool CanOpenDisplay() {
  // Right after VTK closed a window's connection, Xvfb has been seen to
  // refuse one new connection: a few tries before saying there is none.
  for (int attempt = 0; attempt < 5; ++attempt) {
    if (Display* display = XOpenDisplay(nullptr)) {
      XCloseDisplay(display);
      return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

}  // namespace

std::string DisplayProblem() {
  // A display that was there stays there for the process.
  static bool found = false;
  if (found) return "";
  const char* name = std::getenv("DISPLAY");
  if (name && *name) {
    if (CanOpenDisplay()) {
      found = true;
      return "";
    }
    return std::string("cannot open the X display '") + name +
           "': rendering needs one. Headless, run under a virtual display: xvfb-run -a drape …";
  }
  return "no display (DISPLAY is not set): rendering needs one. Headless, run under a virtual "
         "display: xvfb-run -a drape …";
}

}  // namespace drape
