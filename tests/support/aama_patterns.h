// Pattern files written and read by ezdxf, an independent DXF program
// (tests/data/patterns/make_aama_dxf.py and describe_dxf.py), for the tests
// of the DXF-AAMA reader, writer and their users.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "support/drape_command.h"
#include "support/test_paths.h"

namespace drape::test {

inline std::string QuotedPath(const std::filesystem::path& p) {
  return "'" + p.string() + "'";
}

inline std::filesystem::path PatternScript(const char* name) {
  return SourceDir() / "tests" / "data" / "patterns" / name;
}

// Writes the script's two-piece file (FRONT with a cut-out, four notches and
// a grain line at 30°; BACK a trapezoid) in `units`; `variant` names a
// broken file. Returns `out`; a failed script is a test failure.
inline std::filesystem::path MakeAamaPattern(const std::filesystem::path& out,
                                             const std::string& units = "mm",
                                             const std::string& variant = "good") {
  const CommandResult r =
      RunCommand("/usr/bin/python3 " + QuotedPath(PatternScript("make_aama_dxf.py")) + " " +
                 QuotedPath(out) + " --units " + units + " --variant " + variant);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return out;
}

// ezdxf's reading of a DXF file: units, and per piece its cut line's points
// and area, notches and grain.
inline nlohmann::json DescribedByEzdxf(const std::filesystem::path& file) {
  const CommandResult r = RunCommand(
      "/usr/bin/python3 " + QuotedPath(PatternScript("describe_dxf.py")) + " " + QuotedPath(file),
      Captured::kStdout);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return nlohmann::json::parse(r.output);
}

}  // namespace drape::test
