// A whole text file read for a reader that names what it is reading (a
// study file, a plan file, the scene either refers to).
#pragma once

#include <filesystem>
#include <string>

namespace drape {

// Throws SceneError "cannot open <what> '<file>'" when the file cannot be
// read (missing, unreadable, a folder).
std::string ReadTextFile(const std::filesystem::path& file, const std::string& what);

}  // namespace drape
