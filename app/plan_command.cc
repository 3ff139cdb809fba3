// `drape plan PLAN.json -o DIR [--jobs N] [--emit slurm|parallel]`: search
// for the gripper path that lays the part where the plan wants it
// (docs/plan.md). Every evaluation is a `drape run` process in
// DIR/evals/; a rerun finds the evaluations already made and goes on where
// the last one stopped.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "app/commands.h"
#include "core/io/text_file.h"
#include "core/model/scene_error.h"
#include "core/plan/child_process.h"
#include "core/plan/plan_file.h"
#include "core/plan/plan_runner.h"
#include "core/plan/plan_search.h"
#include "core/plan/plan_table.h"

namespace drape::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct PlanArgs {
  std::string input, output, emit;
  int jobs = 1;
  bool quiet = false;
};

std::atomic<bool> g_stop{false};
extern "C" void OnPlanInterrupt(int) {
  g_stop = true;
}

// The plan kept in its folder with its scene made absolute, so that a
// rerun (and the workbench) reads it from there.
void KeepPlan(const Plan& plan, const fs::path& dir) {
  nlohmann::ordered_json document =
      nlohmann::ordered_json::parse(ReadTextFile(plan.file, "plan file"));
  document["scene"] = plan.scene_file.string();
  const fs::path kept = dir / "plan.json";
  if (fs::exists(kept) && fs::equivalent(kept, plan.file)) return;
  std::ofstream(kept) << document.dump(2) << "\n";
}

std::string Millimetres(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g mm", metres * 1e3);
  return text;
}

// DIR/best: the best evaluation's scene and result, replaced as it changes.
void KeepBest(const fs::path& dir, const PlanEvaluation& best) {
  const fs::path from = EvaluationFolder(dir, best.start, best.index), to = dir / "best";
  fs::remove_all(to);
  fs::create_directories(to);
  fs::copy_file(from / "scene.json", to / "scene.json");
  fs::copy(from / "result", to / "result", fs::copy_options::recursive);
}

class PlanProgressLine {
 public:
  PlanProgressLine(const Plan& plan, const fs::path& dir, bool quiet)
      : plan_(plan), dir_(dir), quiet_(quiet), terminal_(!quiet && isatty(STDERR_FILENO)) {}

  void operator()(const PlanEvaluation& e) {
    evaluations_.push_back(e);
    const bool better =
        e.outcome.Feasible() && (!best_ || *e.outcome.objective < *best_->outcome.objective);
    if (better) best_ = e;
    try {
      WritePlanCsv(plan_, evaluations_, dir_ / "plan.csv");
      if (better) KeepBest(dir_, e);
    } catch (const std::exception& error) {
      std::cerr << "\ndrape plan: " << error.what() << "\n";
    }
    if (quiet_) return;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    const int n = static_cast<int>(evaluations_.size()), total = plan_.search.max_evaluations;
    const std::string best =
        best_ ? "best " + Millimetres(*best_->outcome.objective) : std::string("none feasible yet");
    const std::string left =
        n < total ? ", at most " + Duration(elapsed / n * (total - n)) + " left" : "";
    char line[256];
    std::snprintf(line,
                  sizeof line,
                  "plan: %d/%d evaluations, %s, %s%s",
                  n,
                  total,
                  best.c_str(),
                  Duration(elapsed).c_str(),
                  left.c_str());
    if (terminal_) {
      std::fprintf(stderr, "\r\033[K  %s", line);
    } else {
      std::cerr << "  evaluation " << e.start + 1 << "." << e.index << ": " << e.outcome.status
                << (e.outcome.Feasible() ? ", feasible" : ", not feasible")
                << (e.outcome.objective ? ", objective " + Millimetres(*e.outcome.objective) : "")
                << " (" << line << ")\n";
    }
  }
  void End() {
    if (terminal_) std::fputs("\r\033[K", stderr);
  }

 private:
  const Plan& plan_;
  fs::path dir_;
  bool quiet_, terminal_;
  std::vector<PlanEvaluation> evaluations_;
  std::optional<PlanEvaluation> best_;
  Clock::time_point start_ = Clock::now();
};

// --emit: the whole plan as one job for a scheduler (the search is
// sequential; its N starts run side by side on N cores of one node).
int Emit(const PlanArgs& args, const fs::path& dir) {
  std::vector<std::string> command = {SelfExecutable().string(),
                                      "plan",
                                      (dir / "plan.json").string(),
                                      "-o",
                                      dir.string(),
                                      "--jobs",
                                      std::to_string(args.jobs)};
  const fs::path file = dir / (args.emit == "slurm" ? "jobs.slurm" : "jobs.txt");
  std::ofstream out(file);
  if (args.emit == "slurm")
    out << "#!/bin/bash\n# Written by drape plan: the plan as one job; a rerun resumes it.\n"
        << "#SBATCH --job-name=drape-plan\n#SBATCH --cpus-per-task=" << args.jobs << "\n"
        << "#SBATCH --output=" << (dir / "slurm.log").string() << "\nexec";
  for (const std::string& a : command) out << " " << ShellQuoted(a);
  out << (args.emit == "slurm" ? "\n"
                               : " > " + ShellQuoted((dir / "plan.log").string()) + " 2>&1\n");
  if (!out) {
    std::cerr << "drape plan: cannot write '" << file.string() << "'\n";
    return 1;
  }
  std::cerr << "drape plan: the plan in " << file.string() << "\n"
            << (args.emit == "slurm" ? "  submit: sbatch " : "  run: parallel < ")
            << ShellQuoted(file.string()) << "\n";
  return 0;
}

// Runs `drape ARGUMENTS` (a drawing command, handed to drape-vtk) and
// returns "<what>: <file>", or why it was not drawn.
std::string Draw(const std::string& what, const std::string& arguments, const fs::path& file) {
  const std::string command = ShellQuoted(SelfExecutable().string()) + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return what + ": not drawn (cannot start drape)";
  std::string output;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = pclose(pipe);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return what + ": " + file.string();
  return what + ": not drawn: " + output.substr(0, output.find('\n'));
}

int RunPlan(const PlanArgs& args) {
  Plan plan;
  const fs::path dir = args.output;
  try {
    plan = ReadPlan(args.input);
    fs::create_directories(dir);
    KeepPlan(plan, dir);
  } catch (const SceneError& e) {
    std::cerr << "drape plan: " << args.input << ": " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "drape plan: " << e.what() << "\n";
    return 1;
  }
  if (!args.emit.empty()) return Emit(args, dir);

  struct sigaction action {};
  action.sa_handler = OnPlanInterrupt;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  PlanProgressLine progress(plan, dir, args.quiet);
  PlanSearchOptions options;
  options.starts = args.jobs;
  options.stop = &g_stop;
  const PlanSearchSummary summary = RunPlanSearch(
      plan,
      PlanRunner(plan, dir, SelfExecutable(), &g_stop),
      [&](const PlanEvaluation& e) { progress(e); },
      options);
  progress.End();
  signal(SIGINT, SIG_DFL);
  signal(SIGTERM, SIG_DFL);

  const int code = summary.interrupted ? 130 : summary.best ? 0 : 2;
  // The search, and the best path over the part (drape render draws the
  // grippers' paths).
  std::vector<std::string> pictures;
  if (!summary.evaluations.empty())
    pictures.push_back(Draw("chart", "plan-chart " + ShellQuoted(dir.string()), dir / "plan.png"));
  if (summary.best)
    pictures.push_back(Draw("best path",
                            "render " + ShellQuoted((dir / "best" / "result").string()) + " -o " +
                                ShellQuoted((dir / "best.png").string()) + " --step last",
                            dir / "best.png"));
  if (args.quiet) return code;
  std::cerr << "drape plan: " << (summary.interrupted ? "interrupted after " : "")
            << summary.evaluations.size() << " evaluations (" << summary.stop_reason << ")\n";
  if (summary.best) {
    const PlanEvaluation& best = summary.evaluations[*summary.best];
    std::cerr << "  best: objective " << Millimetres(*best.outcome.objective) << " at "
              << DescribePoint(plan, best.x)
              << "\n  scene: " << (dir / "best" / "scene.json").string() << "\n";
  } else {
    std::cerr << "  no feasible path: " << InfeasibilityReport(plan, summary) << "\n";
  }
  std::cerr << "  table: " << (dir / "plan.csv").string() << "\n";
  for (const std::string& line : pictures) std::cerr << "  " << line << "\n";
  return code;
}

}  // namespace

void AddPlanCommand(CLI::App& app, CommandRunner& runner) {
  auto args = std::make_shared<PlanArgs>();
  CLI::App* cmd = app.add_subcommand(
      "plan", "Search for the gripper path that lays the part where a plan wants it");
  cmd->add_option("plan", args->input, "Plan file (JSON)")->required();
  cmd->add_option("-o,--output", args->output, "The plan's folder (created if missing)")
      ->required();
  cmd->add_option("-j,--jobs",
                  args->jobs,
                  "Searches side by side, each from its own starting point (default 1)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--emit",
                  args->emit,
                  "Write the plan as a job for a scheduler instead of running it: slurm "
                  "(DIR/jobs.slurm) or parallel (DIR/jobs.txt)")
      ->check(CLI::IsMember({"slurm", "parallel"}));
  cmd->add_flag("-q,--quiet", args->quiet, "No progress and no summary");
  cmd->callback([args, &runner] { runner = [args] { return RunPlan(*args); }; });
}

}  // namespace drape::app
