// printf-style formatting into a std::string of whatever length it needs:
// messages are built whole, never cut to a fixed buffer.
#pragma once

#include <string>

namespace drape {

std::string Format(const char* format, ...) __attribute__((format(printf, 1, 2)));

}  // namespace drape
