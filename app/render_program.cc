#include "app/render_program.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <vector>

namespace drape::app {
namespace {

namespace fs = std::filesystem;

std::vector<char*> g_arguments;

fs::path RenderProgram() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  for (const fs::path& candidate : {self.parent_path() / "drape-vtk",
                                    self.parent_path() / ".." / "libexec" / "drape" / "drape-vtk"})
    if (fs::exists(candidate, ec)) return candidate.lexically_normal();
  return {};
}

}  // namespace

void RememberCommandLine(int argc, char** argv) {
  g_arguments.assign(argv, argv + argc);
  g_arguments.push_back(nullptr);
}

int RunInRenderProgram(const char* command) {
  const fs::path program = RenderProgram();
  if (program.empty()) {
    std::cerr << "drape " << command
              << ": this installation has no renderer (drape-vtk is not next to drape nor in "
                 "../libexec/drape)\n";
    return 1;
  }
  if (g_arguments.empty()) {
    std::cerr << "drape " << command << ": internal error: the command line was not kept\n";
    return 1;
  }
  std::cout.flush();
  std::cerr.flush();
  execv(program.c_str(), g_arguments.data());
  std::cerr << "drape " << command << ": cannot start " << program.string() << ": "
            << std::strerror(errno) << "\n";
  return 1;
}

}  // namespace drape::app
