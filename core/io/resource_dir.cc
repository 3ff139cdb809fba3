#include "core/io/resource_dir.h"

#include <cstdlib>
#include <system_error>

namespace drape {
namespace fs = std::filesystem;

fs::path ResourceDir() {
  std::error_code ec;
  if (const char* env = std::getenv("DRAPE_RESOURCES"); env && fs::is_directory(env, ec))
    return fs::path(env).lexically_normal();
  // The running program's own file (Linux), not the working directory.
  const fs::path program = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = program.parent_path() / ".." / "share" / "drape" / "resources";
    if (fs::is_directory(installed, ec)) return installed.lexically_normal();
  }
  return fs::path(DRAPE_RESOURCE_DIR);
}

}  // namespace drape
