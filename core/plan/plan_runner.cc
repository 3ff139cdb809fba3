#include "core/plan/plan_runner.h"

#include <signal.h>
#include <sys/wait.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <thread>

#include "core/plan/child_process.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

std::string ReadAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return in ? std::string(std::istreambuf_iterator<char>(in), {}) : std::string();
}

// A run that converged or failed is done; a cancelled or killed one is made
// again.
bool Ended(const fs::path& result) {
  try {
    const auto r = nlohmann::json::parse(ReadAll(result / "result.json"));
    const std::string status = r.value("status", "");
    return status == "converged" || status == "failed";
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

fs::path EvaluationFolder(const fs::path& dir, int start, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "s%d-e%04d", start + 1, index);
  return dir / "evals" / name;
}

// Waits by polling, so that a stop reaches the child from any thread.
void PlanRunner::Run(const fs::path& folder) const {
  std::vector<std::string> args = {program_.string(),
                                   "run",
                                   (folder / "scene.json").string(),
                                   "-o",
                                   (folder / "result").string(),
                                   "--quiet",
                                   "--threads",
                                   "1"};
  if (plan_.time_limit_s) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g", *plan_.time_limit_s);
    args.insert(args.end(), {"--time-limit", seconds});
  }
  const pid_t pid = Spawn(args, folder / "drape.log");
  if (pid < 0) throw std::runtime_error("cannot start " + program_.string());
  bool signalled = false;
  for (;;) {
    int status = 0;
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid || (done < 0 && errno != EINTR)) return;
    if (stop_ && stop_->load() && !signalled) {
      kill(pid, SIGINT);  // the run stops where it is and says cancelled
      signalled = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

EvaluationOutcome PlanRunner::operator()(int start, int index, const std::vector<double>& x) const {
  const fs::path folder = EvaluationFolder(dir_, start, index);
  const std::string scene = PlanSceneText(plan_, x) + "\n";
  const bool kept = ReadAll(folder / "scene.json") == scene && Ended(folder / "result");
  if (!kept) {
    fs::create_directories(folder);
    fs::remove_all(folder / "result");
    std::ofstream(folder / "scene.json") << scene;
    Run(folder);
  }
  return MeasureEvaluation(plan_, folder / "result");
}

}  // namespace drape
