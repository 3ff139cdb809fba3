// Where the files that ship with the program are (scene templates, the
// materials library): the first of
//  1. $DRAPE_RESOURCES, when it is a directory;
//  2. <program>/../share/drape/resources, as `cmake --install` lays it out;
//  3. the source tree's resources/ the program was built from.
#pragma once

#include <filesystem>

namespace drape {

std::filesystem::path ResourceDir();

}  // namespace drape
