// A VTK window's back buffer written as an RGB PNG: the one way pictures,
// frames and charts reach a file.
#pragma once

#include <filesystem>

class vtkRenderWindow;

namespace drape {

// Throws std::runtime_error naming `png` when the file is not there after.
void WriteWindowPng(vtkRenderWindow* window, const std::filesystem::path& png);

}  // namespace drape
