// `drape study STUDY.json -o DIR [--jobs N] [--emit slurm|parallel]` and
// `drape study DIR --collect`: run a study's scenes as parallel `drape run`
// processes (or write the job list for a cluster), then tabulate them in
// DIR/study.csv (docs/format.md §6).
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "core/plan/child_process.h"
#include "app/commands.h"
#include "core/io/study_file.h"
#include "core/io/study_table.h"
#include "core/model/scene_error.h"

namespace drape::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct StudyArgs {
  std::string input;  // the study file, or with --collect its folder
  std::string output;
  int jobs = 0;
  std::string emit;
  bool collect = false;
  bool quiet = false;
};

std::atomic<bool> g_interrupted{false};
extern "C" void OnStudyInterrupt(int) {
  g_interrupted = true;
}

// The study kept in its folder, its scene path made absolute, so that
// `--collect` (and a rerun from elsewhere) reads it without the original.
void KeepStudy(const Study& study, const fs::path& dir) {
  std::ifstream in(study.file);
  nlohmann::ordered_json document = nlohmann::ordered_json::parse(in);
  document["scene"] = study.scene_file.string();
  const fs::path kept = dir / "study.json";
  if (fs::exists(kept) && fs::equivalent(kept, study.file)) return;
  std::ofstream out(kept);
  out << document.dump(2) << "\n";
}

// The reference first: usually the longest run, it should not start last.
std::vector<StudyRun> AllRuns(const Study& study) {
  std::vector<StudyRun> runs;
  if (study.reference) runs.push_back(*study.reference);
  runs.insert(runs.end(), study.runs.begin(), study.runs.end());
  return runs;
}

// Writes each run's scene; a result made from a different scene (the study
// was edited) is stale and removed, so that the run is made again.
void WriteRunScenes(const Study& study, const fs::path& dir) {
  for (const StudyRun& run : AllRuns(study)) {
    const std::string text = SceneTextOf(study, run) + "\n";
    const fs::path file = RunSceneFile(dir, run.name);
    std::string old;
    if (std::ifstream in{file}) old.assign(std::istreambuf_iterator<char>(in), {});
    if (old == text) continue;
    fs::create_directories(file.parent_path());
    fs::remove_all(RunResultFolder(dir, run.name));
    std::ofstream(file) << text;
  }
}

std::vector<std::string> RunArguments(const Study& study,
                                      const fs::path& dir,
                                      const std::string& name) {
  std::vector<std::string> args = {SelfExecutable().string(),
                                   "run",
                                   RunSceneFile(dir, name).string(),
                                   "-o",
                                   RunResultFolder(dir, name).string(),
                                   "--quiet",
                                   "--threads",
                                   "1"};
  if (study.time_limit_s) {
    args.push_back("--time-limit");
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g", *study.time_limit_s);
    args.push_back(seconds);
  }
  return args;
}

std::vector<std::string> PendingRuns(const Study& study, const fs::path& dir) {
  std::vector<std::string> pending;
  for (const StudyRun& run : AllRuns(study))
    if (!RunEnded(dir, run.name)) pending.push_back(run.name);
  return pending;
}

// --emit: the pending runs for an engine that already schedules jobs.
int Emit(const Study& study, const fs::path& dir, const std::string& engine) {
  const std::vector<std::string> pending = PendingRuns(study, dir);
  const fs::path file = dir / (engine == "slurm" ? "jobs.slurm" : "jobs.txt");
  if (pending.empty()) {
    // An empty job array is not a job array.
    fs::remove(file);
    if (engine == "parallel") std::ofstream{file};
    std::cerr << "drape study: every run is done; tabulate them with drape study "
              << ShellQuoted(dir.string()) << " --collect\n";
    return 0;
  }
  std::ofstream out(file);
  if (engine == "slurm") {
    out << "#!/bin/bash\n"
        << "# Written by drape study: one drape run per array task. When they are done:\n"
        << "#   " << SelfExecutable().string() << " study " << ShellQuoted(dir.string())
        << " --collect\n"
        << "#SBATCH --job-name=drape-study\n"
        << "#SBATCH --array=0-" << pending.size() - 1 << "\n"
        << "#SBATCH --cpus-per-task=1\n"
        << "#SBATCH --output=" << (dir / "runs" / "slurm-%a.log").string() << "\n"
        << "runs=(";
    for (const std::string& name : pending) out << " " << name;
    out << " )\n"
        << "name=${runs[$SLURM_ARRAY_TASK_ID]}\n"
        << "exec";
    std::vector<std::string> args = RunArguments(study, dir, "NAME");
    for (std::string arg : args) {
      const size_t at = arg.find("/runs/NAME/");
      if (at != std::string::npos) {
        out << " " << ShellQuoted(arg.substr(0, at) + "/runs/") << "\"$name\""
            << ShellQuoted(arg.substr(at + 10));
      } else {
        out << " " << ShellQuoted(arg);
      }
    }
    out << "\n";
  } else {
    for (const std::string& name : pending) {
      for (const std::string& arg : RunArguments(study, dir, name)) out << ShellQuoted(arg) << " ";
      out << "> " << ShellQuoted((RunFolder(dir, name) / "drape.log").string()) << " 2>&1\n";
    }
  }
  if (!out) {
    std::cerr << "drape study: cannot write '" << file.string() << "'\n";
    return 1;
  }
  std::cerr << "drape study: " << pending.size() << " runs in " << file.string() << "\n"
            << (engine == "slurm" ? "  submit: sbatch " : "  run: parallel < ")
            << ShellQuoted(file.string()) << "\n  then: drape study " << ShellQuoted(dir.string())
            << " --collect\n";
  return 0;
}

struct Child {
  std::string name;
  Clock::time_point start;
};

// Runs the pending runs, `jobs` at a time; false when interrupted.
bool RunPending(const Study& study, const fs::path& dir, int jobs, bool quiet) {
  std::deque<std::string> queue;
  for (const std::string& name : PendingRuns(study, dir)) queue.push_back(name);
  const size_t total = AllRuns(study).size(), skipped = total - queue.size();
  if (!quiet && skipped > 0)
    std::cerr << "drape study: " << skipped << " of " << total << " runs already done, kept\n";
  const bool terminal = !quiet && isatty(STDERR_FILENO);
  std::map<pid_t, Child> running;
  size_t done = skipped, failed = 0, finished_here = 0;
  double busy_s = 0;
  const auto start = Clock::now();
  auto show = [&] {
    if (!terminal) return;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    std::string eta = "";
    if (finished_here > 0) {
      const double per_run = busy_s / finished_here;
      eta = ", about " + Duration(per_run * (total - done) / std::max(1, jobs)) + " left";
    }
    std::string failures;
    if (failed) failures.append(" (").append(std::to_string(failed)).append(" failed)");
    std::fprintf(stderr,
                 "\r\033[K  study: %zu/%zu done%s, %zu running, %s%s",
                 done,
                 total,
                 failures.c_str(),
                 running.size(),
                 Duration(elapsed).c_str(),
                 eta.c_str());
  };
  while (!queue.empty() || !running.empty()) {
    while (!g_interrupted && !queue.empty() && static_cast<int>(running.size()) < jobs) {
      const std::string name = queue.front();
      queue.pop_front();
      const pid_t pid = Spawn(RunArguments(study, dir, name), RunFolder(dir, name) / "drape.log");
      if (pid < 0) {
        std::cerr << "\ndrape study: cannot start " << SelfExecutable().string() << "\n";
        g_interrupted = true;
        break;
      }
      running[pid] = {name, Clock::now()};
    }
    show();
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR) {
        // Ctrl-C: every run stops where it is and keeps its steps (its
        // result says cancelled, so a rerun makes it again).
        for (const auto& [child, _] : running) kill(child, SIGINT);
        continue;
      }
      break;
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const double seconds = std::chrono::duration<double>(Clock::now() - it->second.start).count();
    const std::string name = it->second.name;
    running.erase(it);
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (code == 130) continue;  // cancelled: not done
    ++done;
    ++finished_here;
    busy_s += seconds;
    if (code != 0) ++failed;
    if (!quiet && !terminal)
      std::cerr << "  " << name << ": "
                << (code == 0   ? "converged"
                    : code == 2 ? "failed"
                                : "error")
                << " in " << Duration(seconds) << " (" << done << "/" << total << ")\n";
  }
  if (terminal) std::fputs("\r\033[K", stderr);
  return !g_interrupted;
}

// "drape coefficient 0.905 ± 0.004, nodes 4.0 ± 0.0 (4 to 4), 3 specimens".
std::string DrapeSpreadText(const DrapeSpread& s) {
  char text[192];
  std::snprintf(text,
                sizeof text,
                "drape coefficient %.3f ± %.3f, nodes %.1f ± %.1f (%d to %d), %d %s (mean ± "
                "standard deviation)",
                s.mean_coefficient,
                s.sd_coefficient,
                s.mean_nodes,
                s.sd_nodes,
                s.fewest_nodes,
                s.most_nodes,
                s.specimens,
                s.specimens == 1 ? "specimen" : "specimens");
  return text;
}

// Draws DIR/front.png with `drape front` (a program with VTK); returns the
// line that says where it is, or why it is not.
std::string DrawFront(const Study& study, const fs::path& dir) {
  if (!study.reference) return "front: none (no reference run to measure errors against)";
  const std::string command =
      ShellQuoted(SelfExecutable().string()) + " front " + ShellQuoted(dir.string()) + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return "front: not drawn (cannot start drape front)";
  std::string output;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = pclose(pipe);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0)
    return "front: " + (dir / "front.png").string();
  const std::string first = output.substr(0, output.find('\n'));
  return "front: not drawn: " + first;
}

int RunStudy(const StudyArgs& args) {
  Study study;
  fs::path dir;
  try {
    if (args.collect) {
      dir = args.input;
      study = ReadStudy(dir / "study.json");
    } else {
      if (args.output.empty()) {
        std::cerr << "drape study: --output is required (the study's folder)\n";
        return 1;
      }
      dir = args.output;
      study = ReadStudy(args.input);
      fs::create_directories(dir);
      KeepStudy(study, dir);
      WriteRunScenes(study, dir);
    }
  } catch (const SceneError& e) {
    std::cerr << "drape study: "
              << (args.collect ? (fs::path(args.input) / "study.json").string() : args.input)
              << ": " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "drape study: " << e.what() << "\n";
    return 1;
  }
  if (!args.emit.empty()) return Emit(study, dir, args.emit);

  bool complete = true;
  if (!args.collect) {
    const int jobs = args.jobs > 0 ? args.jobs : std::max(1u, std::thread::hardware_concurrency());
    struct sigaction action {};
    action.sa_handler = OnStudyInterrupt;  // no SA_RESTART: waitpid returns EINTR
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    complete = RunPending(study, dir, jobs, args.quiet);
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
  }
  const std::vector<StudyRow> rows = CollectStudy(study, dir);
  try {
    WriteStudyCsv(study, rows, dir / "study.csv");
  } catch (const std::exception& e) {
    std::cerr << "drape study: " << e.what() << "\n";
    return 1;
  }
  const std::string front = DrawFront(study, dir);
  std::map<std::string, int> counts;
  for (const StudyRow& row : rows) ++counts[row.status];
  if (!args.quiet) {
    std::cerr << (complete ? "drape study: " : "drape study: interrupted: ") << rows.size()
              << " runs:";
    for (const auto& [status, n] : counts) std::cerr << " " << n << " " << status;
    std::cerr << "\n  table: " << (dir / "study.csv").string() << "\n  " << front << "\n";
    // The specimens of a Cusick test, as a lab reports them (the reference aside).
    const std::vector<StudyRow> specimens(rows.begin(), rows.end() - (study.reference ? 1 : 0));
    if (const auto spread = SpreadOfDrape(specimens))
      std::cerr << "  " << DrapeSpreadText(*spread) << "\n";
  }
  return complete ? 0 : 130;
}

}  // namespace

void AddStudyCommand(CLI::App& app, CommandRunner& runner) {
  auto args = std::make_shared<StudyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "study", "Run a study (a scene over a grid or list of settings) and tabulate it");
  cmd->add_option("input", args->input, "Study file (JSON), or with --collect the study's folder")
      ->required();
  cmd->add_option("-o,--output", args->output, "The study's folder (created if missing)");
  cmd->add_option("-j,--jobs", args->jobs, "Runs at a time (default: one per core)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--emit",
                  args->emit,
                  "Write the pending runs for a scheduler instead of running them: slurm "
                  "(DIR/jobs.slurm, a job array) or parallel (DIR/jobs.txt, for GNU parallel)")
      ->check(CLI::IsMember({"slurm", "parallel"}));
  cmd->add_flag("--collect", args->collect, "Tabulate the runs found in the folder (no run)");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress and no summary");
  cmd->callback([args, &runner] { runner = [args] { return RunStudy(*args); }; });
}

}  // namespace drape::app
