// The Plan dock (docs/workbench.md "Plan"): the search of `drape plan` from
// the workbench. Choose path numbers to vary (the keys the path handles
// edit) with their bounds, a probe and where it should land, start; each
// evaluation appears as it ends (a `drape run` process, as on the command
// line); accept the best path, an edit that undoes. No physics here: the
// plan is written as a plan file, read by core's reader, searched by core.
#pragma once

#include <QWidget>

#include <atomic>
#include <filesystem>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

#include "core/plan/path_parameters.h"
#include "core/plan/plan_file.h"
#include "core/plan/plan_search.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace drape {

class SceneDocument;

class PlanDock : public QWidget {
  Q_OBJECT
 public:
  explicit PlanDock(SceneDocument* document, QWidget* parent = nullptr);
  ~PlanDock() override;  // stops the search and waits for it

  // The `drape` program the evaluations run; by default the one beside
  // this program.
  void setProgram(const QString& program) { program_ = program; }

  QComboBox* candidates() const { return candidates_; }
  QTableWidget* parameters() const { return parameters_; }
  QComboBox* probe() const { return probe_; }
  QLineEdit* target() const { return target_; }
  QSpinBox* evaluations() const { return evaluations_; }
  QTableWidget* results() const { return results_; }
  QPushButton* runButton() const { return run_; }
  QPushButton* stopButton() const { return stop_button_; }
  QPushButton* acceptButton() const { return accept_; }
  QString message() const;

  // Adds the candidate path number at `index` with bounds a tenth of its
  // size (at least 1 cm, or 10 degrees) either side of its value.
  bool addParameter(int index);
  // Writes the plan, reads it with core's reader and starts the search;
  // false with the reader's message when the plan is wrong.
  bool start();
  void stop();
  bool isRunning() const { return worker_.joinable() && !done_; }
  // The best feasible evaluation so far.
  const std::optional<PlanEvaluation>& best() const { return best_; }
  // The best path's values set in the scene: one undoable edit.
  bool acceptBest();

 signals:
  void evaluated(int count);
  void finished();

 public slots:
  void refresh();

 private:
  void Evaluated(const PlanEvaluation& e);
  void Finished(const QString& summary);
  void Join();

  SceneDocument* document_;
  QString program_;
  std::vector<PathParameter> candidate_list_;
  QComboBox* candidates_;
  QTableWidget* parameters_;
  QComboBox* probe_;
  QLineEdit* target_;
  QSpinBox* evaluations_;
  QPushButton *run_, *stop_button_, *accept_;
  QTableWidget* results_;
  QLabel* message_;

  std::filesystem::path dir_;
  std::unique_ptr<Plan> plan_;
  std::thread worker_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> done_{false};
  std::optional<PlanEvaluation> best_;
};

}  // namespace drape
