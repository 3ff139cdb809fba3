#include "core/io/text_file.h"

#include <fstream>
#include <sstream>

#include "core/model/scene_error.h"

namespace drape {

std::string ReadTextFile(const std::filesystem::path& file, const std::string& what) {
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  if (!in || std::filesystem::is_directory(file, ec))
    throw SceneError("", "cannot open " + what + " '" + file.string() + "'");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

}  // namespace drape
