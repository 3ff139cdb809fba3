#include "ui/widgets/plan_dock.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/io/scene_key.h"
#include "core/model/scene_error.h"
#include "core/plan/plan_runner.h"
#include "ui/widgets/scene_document.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A bound as the plan file takes it: centimetres for a length, the plain
// number for a key such as angle_deg.
QString BoundText(double value, const Dimension& dimension) {
  char text[64];
  if (dimension == dim::kLength)
    std::snprintf(text, sizeof text, "%.6g cm", value * 100);
  else
    std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

// "11 cm, 0, 0.07 cm" → ["11 cm", 0, "0.07 cm"]: each part a number or a
// quantity, for the plan reader to judge.
json TargetJson(const QString& text) {
  json target = json::array();
  for (const QString& part : text.split(',')) {
    const std::string s = part.trimmed().toStdString();
    char* end = nullptr;
    const double number = std::strtod(s.c_str(), &end);
    if (!s.empty() && end && *end == '\0')
      target.push_back(number);
    else
      target.push_back(s);
  }
  return target;
}

int NextPlanFolder() {
  static int count = 0;
  return ++count;
}

}  // namespace

PlanDock::PlanDock(SceneDocument* document, QWidget* parent)
    : QWidget(parent),
      document_(document),
      program_(QCoreApplication::applicationDirPath() + "/drape"),
      candidates_(new QComboBox),
      parameters_(new QTableWidget(0, 3)),
      probe_(new QComboBox),
      target_(new QLineEdit),
      evaluations_(new QSpinBox),
      run_(new QPushButton("Search")),
      stop_button_(new QPushButton("Stop")),
      accept_(new QPushButton("Accept best path")),
      results_(new QTableWidget(0, 4)),
      message_(new QLabel) {
  setObjectName("plan.dock");
  auto* add = new QPushButton("Add");
  auto* remove = new QPushButton("Remove");
  parameters_->setHorizontalHeaderLabels({"path number", "min", "max"});
  parameters_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  target_->setPlaceholderText("x, y, z (e.g. 11 cm, 0, 0.07 cm)");
  target_->setToolTip("Where the probe should be at the end of the last stage");
  evaluations_->setRange(4, 1000);
  evaluations_->setValue(40);
  results_->setHorizontalHeaderLabels({"evaluation", "objective [mm]", "feasible", "status"});
  results_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  message_->setWordWrap(true);
  stop_button_->setEnabled(false);
  accept_->setEnabled(false);

  auto* choose = new QHBoxLayout;
  choose->addWidget(candidates_, 1);
  choose->addWidget(add);
  choose->addWidget(remove);
  auto* form = new QFormLayout;
  form->addRow("probe", probe_);
  form->addRow("should land at", target_);
  form->addRow("at most evaluations", evaluations_);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(run_);
  buttons->addWidget(stop_button_);
  buttons->addWidget(accept_);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(new QLabel("Vary these path numbers:"));
  layout->addLayout(choose);
  layout->addWidget(parameters_);
  layout->addLayout(form);
  layout->addLayout(buttons);
  layout->addWidget(message_);
  layout->addWidget(results_, 1);

  connect(add, &QPushButton::clicked, this, [this] { addParameter(candidates_->currentIndex()); });
  connect(remove, &QPushButton::clicked, this, [this] {
    if (parameters_->currentRow() >= 0) parameters_->removeRow(parameters_->currentRow());
  });
  connect(run_, &QPushButton::clicked, this, [this] { start(); });
  connect(stop_button_, &QPushButton::clicked, this, &PlanDock::stop);
  connect(accept_, &QPushButton::clicked, this, [this] { acceptBest(); });
  connect(document_, &SceneDocument::changed, this, &PlanDock::refresh);
  refresh();
}

PlanDock::~PlanDock() {
  stop();
  Join();
  if (!dir_.empty()) {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
}

QString PlanDock::message() const {
  return message_->text();
}

void PlanDock::refresh() {
  candidate_list_ = PathParameters(document_->scene());
  candidates_->clear();
  for (const PathParameter& p : candidate_list_)
    candidates_->addItem(QString::fromStdString(p.label), QString::fromStdString(p.key));
  const QString probe = probe_->currentText();
  probe_->clear();
  for (const Probe& p : document_->scene().probes) probe_->addItem(QString::fromStdString(p.name));
  if (const int i = probe_->findText(probe); i >= 0) probe_->setCurrentIndex(i);
}

bool PlanDock::addParameter(int index) {
  if (index < 0 || index >= static_cast<int>(candidate_list_.size())) return false;
  const PathParameter& p = candidate_list_[index];
  for (int r = 0; r < parameters_->rowCount(); ++r)
    if (parameters_->item(r, 0)->data(Qt::UserRole).toString().toStdString() == p.key) return false;
  const double half = p.dimension == dim::kLength ? std::max(0.1 * std::abs(p.value), 0.01) : 10.0;
  const int row = parameters_->rowCount();
  parameters_->insertRow(row);
  auto* name = new QTableWidgetItem(QString::fromStdString(p.label));
  name->setData(Qt::UserRole, QString::fromStdString(p.key));
  name->setToolTip(QString::fromStdString(p.key));
  name->setFlags(name->flags() & ~Qt::ItemIsEditable);
  parameters_->setItem(row, 0, name);
  parameters_->setItem(row, 1, new QTableWidgetItem(BoundText(p.value - half, p.dimension)));
  parameters_->setItem(row, 2, new QTableWidgetItem(BoundText(p.value + half, p.dimension)));
  return true;
}

bool PlanDock::start() {
  if (isRunning()) return false;
  Join();
  if (dir_.empty())
    dir_ = fs::temp_directory_path() / ("drape-studio-plan-" + std::to_string(getpid()) + "-" +
                                        std::to_string(NextPlanFolder()));
  fs::remove_all(dir_);
  fs::create_directories(dir_);
  nlohmann::ordered_json scene = nlohmann::ordered_json::parse(document_->json().dump());
  MakeFilesAbsolute(scene, document_->directory());
  std::ofstream(dir_ / "scene.json") << scene.dump(2) << "\n";
  json plan = {{"drape_plan", 1}, {"scene", "scene.json"}};
  plan["parameters"] = json::array();
  for (int r = 0; r < parameters_->rowCount(); ++r)
    plan["parameters"].push_back(
        {{"key", parameters_->item(r, 0)->data(Qt::UserRole).toString().toStdString()},
         {"min", TargetJson(parameters_->item(r, 1)->text())[0]},
         {"max", TargetJson(parameters_->item(r, 2)->text())[0]}});
  plan["objective"] = {{"probes",
                        {{{"probe", probe_->currentText().toStdString()},
                          {"target", TargetJson(target_->text())}}}}};
  plan["optimizer"] = {{"max_evaluations", evaluations_->value()}};
  std::ofstream(dir_ / "plan.json") << plan.dump(2) << "\n";
  try {
    plan_ = std::make_unique<Plan>(ReadPlan(dir_ / "plan.json"));
  } catch (const SceneError& e) {
    message_->setText(QString("The plan cannot start — %1").arg(e.what()));
    return false;
  }
  results_->setRowCount(0);
  results_->setColumnCount(4);
  best_.reset();
  accept_->setEnabled(false);
  stop_ = false;
  done_ = false;
  run_->setEnabled(false);
  stop_button_->setEnabled(true);
  message_->setText("Searching…");
  const fs::path dir = dir_, program = program_.toStdString();
  const Plan* searched = plan_.get();
  worker_ = std::thread([this, searched, dir, program] {
    QString summary;
    try {
      PlanSearchOptions options;
      options.stop = &stop_;
      const PlanSearchSummary s = RunPlanSearch(
          *searched,
          PlanRunner(*searched, dir, program, &stop_),
          [this](const PlanEvaluation& e) {
            QMetaObject::invokeMethod(
                this, [this, e] { Evaluated(e); }, Qt::QueuedConnection);
          },
          options);
      summary = QString("%1 evaluations (%2)")
                    .arg(s.evaluations.size())
                    .arg(QString::fromStdString(s.stop_reason));
      if (!s.best)
        summary += QString("; no feasible path: ") +
                   QString::fromStdString(InfeasibilityReport(*searched, s));
    } catch (const std::exception& e) {
      summary = QString("The search failed: %1").arg(e.what());
    }
    done_ = true;
    QMetaObject::invokeMethod(
        this, [this, summary] { Finished(summary); }, Qt::QueuedConnection);
  });
  return true;
}

void PlanDock::stop() {
  stop_ = true;
}

void PlanDock::Join() {
  if (worker_.joinable()) worker_.join();
}

void PlanDock::Evaluated(const PlanEvaluation& e) {
  const int row = results_->rowCount();
  results_->insertRow(row);
  char objective[32] = "";
  if (e.outcome.objective)
    std::snprintf(objective, sizeof objective, "%.4g", *e.outcome.objective * 1e3);
  results_->setItem(row, 0, new QTableWidgetItem(QString::number(row + 1)));
  results_->setItem(row, 1, new QTableWidgetItem(objective));
  results_->setItem(row, 2, new QTableWidgetItem(e.outcome.Feasible() ? "yes" : "no"));
  results_->setItem(row, 3, new QTableWidgetItem(QString::fromStdString(e.outcome.status)));
  results_->item(row, 0)->setToolTip(QString::fromStdString(DescribePoint(*plan_, e.x)));
  if (e.outcome.Feasible() && (!best_ || *e.outcome.objective < *best_->outcome.objective)) {
    best_ = e;
    accept_->setEnabled(true);
  }
  if (best_)
    message_->setText(QString("Best so far: the probe lands %1 mm from its target (%2)")
                          .arg(*best_->outcome.objective * 1e3, 0, 'g', 4)
                          .arg(QString::fromStdString(DescribePoint(*plan_, best_->x))));
  emit evaluated(row + 1);
}

void PlanDock::Finished(const QString& summary) {
  Join();
  run_->setEnabled(true);
  stop_button_->setEnabled(false);
  message_->setText(message_->text() + "\n" + summary);
  emit finished();
}

bool PlanDock::acceptBest() {
  if (!best_ || !plan_) return false;
  // The values as the best run's scene holds them (in the plan's units).
  std::ifstream in(EvaluationFolder(dir_, best_->start, best_->index) / "scene.json");
  const nlohmann::ordered_json best_scene = nlohmann::ordered_json::parse(in);
  nlohmann::ordered_json scene = nlohmann::ordered_json::parse(document_->json().dump());
  for (const PlanParameter& p : plan_->parameters)
    SetSceneKey(scene, p.key, json::parse(SceneKeyValue(best_scene, p.key, "").dump()), "");
  QString problem;
  if (!document_->tryApplyJson("plan: best path", json::parse(scene.dump()), &problem)) {
    message_->setText("The best path cannot be applied — " + problem);
    return false;
  }
  return true;
}

}  // namespace drape
