#include "support/test_paths.h"

namespace drape::test {

std::filesystem::path SourceDir() {
  return DRAPE_SOURCE_DIR;
}

const char* DrapeCli() {
  return DRAPE_CLI;
}

const char* DrapeStudio() {
#ifdef DRAPE_STUDIO
  return DRAPE_STUDIO;
#else
  return "";
#endif
}

}  // namespace drape::test
