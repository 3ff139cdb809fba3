// `drape drag`: the messages for what cannot be dragged (frames.csv, the
// dragged scene and its released run: drag_cli_slow_test.cc).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/drape_command.h"
#include "support/temp_dir.h"
#include "support/test_paths.h"

namespace drape {
namespace {

std::string CornerLift() {
  return (test::SourceDir() / "tests" / "data" / "corner-lift-20x20.json").string();
}

TEST(DragCli, SaysWhatIsWrongWithItsArguments) {
  test::TempDir dir("drag-bad");
  const std::string out = " -o " + (dir / "out").string();
  auto r = test::RunDrape("drag " + CornerLift() + " --gripper corner --by 0,1" + out);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("--by: '0,1' is not three lengths"), std::string::npos) << r.output;
  r = test::RunDrape("drag " + CornerLift() + " --gripper corner --by '0,0,3 kg'" + out);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("is not a length"), std::string::npos) << r.output;
  r = test::RunDrape("drag " + CornerLift() + " --gripper hand --by 0,0,0.01" + out);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("--gripper: the scene has no gripper 'hand' (it has 'corner')"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "frames.csv"));
  r = test::RunDrape("drag " + CornerLift() + " --gripper corner --by 0,0,0.01 --frames 0" + out);
  EXPECT_EQ(r.exit_code, 1);
}

}  // namespace
}  // namespace drape
