// Shared by the `drape run` tests (tests/cli/run_cli_test.cc,
// run_cli_failure_test.cc): the command, scene documents and what the
// result folder should hold.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/drape_command.h"
#include "support/test_paths.h"

// In a namespace of its own: test::RunCommand (drape_command.h) runs any
// shell command, this one `drape`.
namespace drape::test::run_cli {

// `drape ARGUMENTS`; with `stderr_only` stdout is discarded.
inline CommandResult RunCommand(const std::string& arguments, bool stderr_only = false) {
  return RunDrape(arguments, stderr_only ? Captured::kStderr : Captured::kBoth);
}

inline nlohmann::json ReadJson(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

inline std::filesystem::path WriteJson(const nlohmann::json& doc,
                                       const std::filesystem::path& file) {
  std::ofstream(file) << doc.dump(2);
  return file;
}

// For the shell: the temporary paths hold no quote.
inline std::string Quote(const std::filesystem::path& p) {
  std::string quoted(1, '\'');
  quoted += p.string();
  quoted += '\'';
  return quoted;
}

inline nlohmann::json SceneJson(const std::string& name) {
  return ReadJson(ScenesDir() / name);
}

// block-drape.json on an n × n mesh.
inline nlohmann::json BlockDrape(int n) {
  nlohmann::json doc = SceneJson("block-drape.json");
  doc["fabric"]["mesh"] = {{"elements", {n, n}}};
  return doc;
}

// Bytes of states.bin (state_file.h) up to and including `records` step
// records, for a mesh of `nodes` nodes and `elements` quads.
inline std::uintmax_t StateFileBytes(std::uintmax_t nodes,
                                     std::uintmax_t elements,
                                     std::uintmax_t records) {
  const std::uintmax_t header = 8 + 16;
  const std::uintmax_t mesh = 8 * 3 * nodes + 4 * 4 * elements + (elements % 2 ? 4 : 0);
  return header + mesh + records * (16 + 48 * nodes);
}

}  // namespace drape::test::run_cli
