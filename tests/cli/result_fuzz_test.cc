// ReadRunRecord must answer any result folder with a record or a
// std::runtime_error naming the folder: never a crash, a hang, a sanitizer
// report, another exception, or a number that is not finite. Seeds: two
// small runs of `drape run` (block drape on 2 × 2 quads; the same with a
// floor a second stage lowers, so that steps carry obstacle placements and
// the result a contact pressure). Each input mutates result.json (bytes, or
// one value or key of the document) and/or states.bin (bytes, words) in a
// copy of a seed folder. Inputs: DRAPE_FUZZ_INPUTS (default 2000); a long run
//   DRAPE_FUZZ_INPUTS=100000 ./cli_tests --gtest_filter='ReaderFuzz*'
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/io/result_reader.h"
#include "support/drape_command.h"
#include "support/fuzz_input.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::FuzzAlphabet;
using test::Mutator;

std::string ReadBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void WriteBytes(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary).write(bytes.data(), std::ssize(bytes));
}

json BlockDrape() {
  std::ifstream in(test::ScenesDir() / "block-drape.json");
  json scene = json::parse(in);
  scene["fabric"]["mesh"] = {{"elements", {2, 2}}};
  return scene;
}

json WithMovingFloor(json scene) {
  scene["obstacles"] = {
      {{"name", "floor"}, {"plane", {{"point", {0, 0, "-5 cm"}}, {"normal", {0, 0, 1}}}}}};
  scene["stages"].push_back(
      {{"name", "L"},
       {"kind", "move"},
       {"initial_increment", 0.5},
       {"moves", {{{"obstacle", "floor"}, {"path", {{"line", {{"by", {0, 0, "-1 cm"}}}}}}}}}});
  return scene;
}

struct SeedFolder {
  std::string result, states;
};

class ReaderFuzzResult : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ =
        new fs::path(fs::temp_directory_path() / ("drape-result-fuzz-" + std::to_string(getpid())));
    fs::remove_all(*dir_);
    fs::create_directories(*dir_);
    seeds_ = new std::vector<SeedFolder>;
    for (const auto& [name, scene] :
         {std::pair{"plain", BlockDrape()}, std::pair{"floor", WithMovingFloor(BlockDrape())}}) {
      const fs::path scene_file = *dir_ / (std::string(name) + ".json");
      std::ofstream(scene_file) << scene.dump(1);
      const fs::path out = *dir_ / name;
      const test::CommandResult run =
          test::RunDrape("run '" + scene_file.string() + "' -o '" + out.string() + "' --quiet");
      if (run.exit_code != 0) {
        setup_error_ = new std::string(run.output);
        return;
      }
      seeds_->push_back({ReadBytes(out / "result.json"), ReadBytes(out / "states.bin")});
    }
  }
  static void TearDownTestSuite() {
    std::error_code ec;
    fs::remove_all(*dir_, ec);
    delete dir_;
    delete seeds_;
    delete setup_error_;
    dir_ = nullptr;
    seeds_ = nullptr;
    setup_error_ = nullptr;
  }
  void SetUp() override {
    ASSERT_EQ(setup_error_, nullptr) << *setup_error_;
    ASSERT_EQ(seeds_->size(), 2u);
  }

  static fs::path* dir_;
  static std::vector<SeedFolder>* seeds_;
  static std::string* setup_error_;
};

fs::path* ReaderFuzzResult::dir_ = nullptr;
std::vector<SeedFolder>* ReaderFuzzResult::seeds_ = nullptr;
std::string* ReaderFuzzResult::setup_error_ = nullptr;

// Raw JSON put in place of one value: the edges of each type, numbers
// JSON can spell but a double cannot hold, and the wrong types.
const std::vector<std::string>& Replacements() {
  static const std::vector<std::string> values = {"1e999",
                                                  "-1e999",
                                                  "1e308",
                                                  "-1e308",
                                                  "1e-400",
                                                  "0",
                                                  "-1",
                                                  "1.5",
                                                  "2147483648",
                                                  "-2147483649",
                                                  "4294967296",
                                                  "1e10",
                                                  "99999999999999999999999",
                                                  "true",
                                                  "null",
                                                  "\"\"",
                                                  "\"x\"",
                                                  "[]",
                                                  "{}",
                                                  "[1]",
                                                  "[[1,2,3]]",
                                                  "{\"a\":1}",
                                                  "-0",
                                                  "3",
                                                  "100000"};
  return values;
}

// One value of the document replaced, or one member or element removed.
std::string EditedDocument(const std::string& text, Mutator& mutator) {
  // A first edit may have left no JSON (nlohmann refuses 1e999).
  json doc = json::parse(text, nullptr, false);
  if (doc.is_discarded()) return text;
  const json flat = doc.flatten();
  auto it = flat.begin();
  std::advance(it, static_cast<long>(mutator.Below(flat.size())));
  json::json_pointer pointer(it.key());
  // Sometimes a container above the leaf, so whole arrays and objects go too.
  for (std::size_t up = mutator.Below(4); up > 0 && !pointer.empty(); --up)
    pointer = pointer.parent_pointer();
  if (pointer.empty()) return text;
  if (mutator.Below(4) == 0) {
    json& parent = doc[pointer.parent_pointer()];
    if (parent.is_object()) {
      parent.erase(pointer.back());
    } else if (parent.is_array()) {
      parent.erase(std::stoul(pointer.back()));
    }
    return doc.dump(mutator.Below(2) == 0 ? -1 : 1);
  }
  static const std::string kMark = "\u0001fuzz";
  doc[pointer] = kMark;
  std::string out = doc.dump(mutator.Below(2) == 0 ? -1 : 1);
  const std::string quoted = json(kMark).dump();
  out.replace(
      out.find(quoted), quoted.size(), Replacements()[mutator.Below(Replacements().size())]);
  return out;
}

template <class Derived>
bool AllFinite(const Eigen::MatrixBase<Derived>& m) {
  return m.allFinite();
}

void ExpectSoundRecord(const RunRecord& r, const std::string& input) {
  const int nodes = r.mesh.NodeCount();
  ASSERT_TRUE(AllFinite(r.mesh.positions)) << input;
  if (r.mesh.ElementCount() > 0) {
    ASSERT_GE(r.mesh.quads.minCoeff(), 0) << input;
    ASSERT_LT(r.mesh.quads.maxCoeff(), nodes) << input;
  }
  ASSERT_EQ(r.states.size(), r.steps.size()) << input;
  for (std::size_t i = 0; i < r.states.size(); ++i) {
    const StoredStep& s = r.states[i];
    ASSERT_EQ(s.positions.rows(), nodes) << input;
    ASSERT_EQ(s.directors.rows(), nodes) << input;
    ASSERT_TRUE(std::isfinite(s.lambda) && AllFinite(s.positions) && AllFinite(s.directors))
        << "state " << i << " of\n"
        << input;
    ASSERT_TRUE(std::isfinite(r.steps[i].lambda)) << "step " << i << " of\n" << input;
    for (const ObstaclePlacement& p : r.steps[i].obstacles)
      ASSERT_TRUE(AllFinite(p.rotation) && AllFinite(p.translation)) << input;
    for (const NamedVector& f : r.steps[i].reactions) ASSERT_TRUE(AllFinite(f.value)) << input;
    const ShellState state = StateOf(r, i);
    ASSERT_TRUE(AllFinite(state.positions)) << input;
    for (const auto& rotation : state.rotations) ASSERT_TRUE(AllFinite(rotation)) << input;
  }
  for (const double p : r.final_contact_pressure) ASSERT_TRUE(std::isfinite(p)) << input;
}

TEST_F(ReaderFuzzResult, MutatedFoldersGiveARecordOrANamedError) {
  Mutator text_mutator(
      9001, {"{}[],:\"0123456789.-eE \\tnul/x", {"1e999", "-1e999", "\"steps\"", "null"}});
  Mutator binary_mutator(9002, {test::Bytes("\x00\x01\xff\x7f\x80"), {"DRAPESTA"}, true});
  const fs::path folder = *dir_ / "fuzz";
  fs::create_directories(folder);
  test::FuzzTally tally{"result folders (result.json, states.bin)"};
  const int inputs = test::FuzzInputs();
  for (int i = 0; i < inputs; ++i) {
    const SeedFolder& seed = (*seeds_)[text_mutator.Below(seeds_->size())];
    std::string result = seed.result, states = seed.states;
    const std::size_t kind = text_mutator.Below(20);
    if (kind < 8) {
      result = text_mutator.Edited(result, 1 + static_cast<int>(text_mutator.Below(3)));
    } else if (kind < 16) {
      result = EditedDocument(result, text_mutator);
      if (text_mutator.Below(4) == 0) result = EditedDocument(result, text_mutator);
    }
    if (kind >= 14)
      states = binary_mutator.Edited(states, 1 + static_cast<int>(binary_mutator.Below(3)));
    WriteBytes(folder / "result.json", result);
    WriteBytes(folder / "states.bin", states);
    const std::string input =
        "result.json:\n" + result.substr(0, 4000) +
        (states == seed.states ? "\n(states.bin as seeded)" : "\n(states.bin mutated)");
    try {
      ExpectSoundRecord(ReadRunRecord(folder), input);
      ++tally.accepted;
    } catch (const std::runtime_error& e) {
      ASSERT_NE(std::string(e.what()).find(folder.string()), std::string::npos) << e.what();
      ++tally.rejected;
    }
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.accepted, 0);
  EXPECT_GT(tally.rejected, 0);
}

// A float where an integer belongs was cast to int: undefined behaviour
// for 1e10 (GCC's UBSan does not check it), and a made-up step number.
TEST_F(ReaderFuzzResult, RegressionStepNumbersMustBeIntegers) {
  json doc = json::parse((*seeds_)[0].result);
  doc["steps"][1]["stage"] = 1e10;
  const fs::path folder = *dir_ / "float-stage";
  fs::create_directories(folder);
  WriteBytes(folder / "result.json", doc.dump());
  WriteBytes(folder / "states.bin", (*seeds_)[0].states);
  try {
    ReadRunRecord(folder);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find((folder / "result.json").string() +
                                         ": steps[1].stage: 10000000000.0 is not an integer"),
              std::string::npos)
        << e.what();
  }
  doc["steps"][1]["stage"] = 0;
  doc["steps"][0]["step"] = 2.5;
  WriteBytes(folder / "result.json", doc.dump());
  EXPECT_THROW(ReadRunRecord(folder), std::runtime_error);
}

// steps[].reactions: each step's forces, by name, in the scene's order
// (supports, then grippers) and any other name after them, not
// result.json's sorted one; anything but three finite numbers is refused,
// naming the key (null is how a NaN is written).
TEST_F(ReaderFuzzResult, ReactionsAreReadPerStep) {
  json doc = json::parse((*seeds_)[0].result);
  const fs::path folder = *dir_ / "reactions";
  fs::create_directories(folder);
  WriteBytes(folder / "states.bin", (*seeds_)[0].states);
  auto read = [&] {
    WriteBytes(folder / "result.json", doc.dump());
    return ReadRunRecord(folder);
  };
  const RunRecord record = read();
  ASSERT_EQ(record.steps.size(), doc["steps"].size());
  ASSERT_GT(record.steps.size(), 1u);
  for (size_t i = 0; i < record.steps.size(); ++i) {
    ASSERT_EQ(record.steps[i].reactions.size(), 1u) << i;
    EXPECT_EQ(record.steps[i].reactions[0].name, "corners");
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(record.steps[i].reactions[0].value(c),
                doc["steps"][i]["reactions"]["corners"][c].get<double>());
  }
  EXPECT_GT(record.steps.back().reactions[0].value.z(), 0);  // the corners carry the sheet

  doc["steps"][0]["reactions"]["aaa"] = {1.0, 2.0, 3.0};  // before "corners" alphabetically
  const RunRecord extra = read();
  ASSERT_EQ(extra.steps[0].reactions.size(), 2u);
  EXPECT_EQ(extra.steps[0].reactions[0].name, "corners");
  EXPECT_EQ(extra.steps[0].reactions[1].name, "aaa");
  EXPECT_EQ(extra.steps[0].reactions[1].value, Eigen::Vector3d(1, 2, 3));
  doc["steps"][0]["reactions"].erase("aaa");

  doc["steps"][1].erase("reactions");
  EXPECT_TRUE(read().steps[1].reactions.empty());

  const std::string prefix = (folder / "result.json").string() + ": steps[1].reactions";
  for (const json& bad : {json{0.0, nullptr, 1.0}, json{0.0, 1.0}, json("x"), json{0, 1, "2"}}) {
    doc["steps"][1]["reactions"]["corners"] = bad;
    try {
      read();
      ADD_FAILURE() << "read " << bad.dump();
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(prefix + ".corners: " + bad.dump() +
                                           " is not a force [Fx, Fy, Fz] in N"),
                std::string::npos)
          << e.what();
    }
  }
  doc["steps"][1]["reactions"] = 3;
  try {
    read();
    ADD_FAILURE() << "read reactions: 3";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(prefix + ": 3 is not an object of forces"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace drape
