#include "ui/widgets/supports_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>
#include <nlohmann/json.hpp>

#include "core/io/scene_reader.h"
#include "core/io/scene_writer.h"
#include "core/model/overloaded.h"
#include "core/model/scene_error.h"
#include "core/solve/shell_model.h"
#include "ui/widgets/scene_document.h"

namespace drape {
namespace {

QString Describe(const Selection& s) {
  return std::visit(
      Overloaded{
          [](const PointSelection& p) {
            return QString("point (%1, %2) m").arg(p.at[0]).arg(p.at[1]);
          },
          [](const LineSelection&) { return QString("line"); },
          [](const BoxSelection&) { return QString("box"); },
          [](const CornersSelection&) { return QString("corners"); },
          [](const EdgeSelection& e) {
            const char* names[] = {
                "left edge", "right edge", "bottom edge", "top edge", "boundary"};
            return QString(names[static_cast<int>(e.side)]);
          },
          [](const NodesSelection& n) { return QString("%1 nodes").arg(n.nodes.size()); },
      },
      s.shape);
}

}  // namespace

SupportsPanel::SupportsPanel(SceneDocument* document, QWidget* parent)
    : QWidget(parent), document_(document) {
  auto* layout = new QVBoxLayout(this);
  list_ = new QListWidget(this);
  layout->addWidget(list_, 1);
  auto* form = new QFormLayout;
  rule_ = new QComboBox(this);
  rule_->addItems({"left", "right", "bottom", "top", "corners", "point"});
  fixity_ = new QComboBox(this);
  fixity_->addItems({"position (pinned)", "clamp (position and director)"});
  x_ = new QDoubleSpinBox(this);
  y_ = new QDoubleSpinBox(this);
  for (QDoubleSpinBox* s : {x_, y_}) {
    s->setRange(-100, 100);
    s->setDecimals(4);
    s->setSuffix(" m");
  }
  form->addRow("holds", rule_);
  form->addRow("point x", x_);
  form->addRow("point y", y_);
  form->addRow("fixity", fixity_);
  layout->addLayout(form);
  auto* buttons = new QHBoxLayout;
  auto* add = new QPushButton("Add support", this);
  auto* remove = new QPushButton("Remove", this);
  buttons->addWidget(add);
  buttons->addWidget(remove);
  layout->addLayout(buttons);
  message_ = new QLabel(this);
  message_->setWordWrap(true);
  message_->setStyleSheet("color: #b00020");
  layout->addWidget(message_);
  connect(add, &QPushButton::clicked, this, [this] {
    addSupport(rule_->currentText(), fixity_->currentIndex(), x_->value(), y_->value());
  });
  connect(remove, &QPushButton::clicked, this, &SupportsPanel::removeSelected);
  connect(fixity_, &QComboBox::activated, this, &SupportsPanel::setFixity);
  connect(list_, &QListWidget::currentRowChanged, this, [this](int i) {
    const Scene& s = document_->scene();
    if (i < 0 || i >= static_cast<int>(s.supports.size())) return;
    const QSignalBlocker block(fixity_);
    fixity_->setCurrentIndex(s.supports[i].fix == Fixity::kClamp ? 1 : 0);
  });
  connect(document_, &SceneDocument::changed, this, &SupportsPanel::refresh);
  refresh();
}

QString SupportsPanel::message() const {
  return message_->text();
}

bool SupportsPanel::Apply(const QString& what, const Scene& after) {
  // The reader's rules, then the engine's: the selection must match nodes
  // on the meshed part.
  try {
    BuildShellModel(SceneFromJson(nlohmann::json::parse(SceneToJson(after).dump())));
  } catch (const SceneError& e) {
    message_->setText(QString::fromStdString(e.what()));
    return false;
  }
  message_->clear();
  document_->apply(what, after);
  return true;
}

bool SupportsPanel::addSupport(const QString& rule, int fixity, double x, double y) {
  Scene after = document_->scene();
  Support s;
  int n = static_cast<int>(after.supports.size()) + 1;
  auto taken = [&](const std::string& name) {
    for (const auto& o : after.supports)
      if (o.name == name) return true;
    for (const auto& g : after.grippers)
      if (g.name == name) return true;
    return false;
  };
  while (taken("support " + std::to_string(n))) ++n;
  s.name = "support " + std::to_string(n);
  if (rule == "corners")
    s.select.shape = CornersSelection{};
  else if (rule == "point")
    s.select.shape = PointSelection{{x, y}};
  else {
    const QStringList sides = {"left", "right", "bottom", "top"};
    if (!sides.contains(rule)) return false;
    s.select.shape = EdgeSelection{static_cast<Side>(sides.indexOf(rule))};
  }
  s.fix = fixity == 1 ? Fixity::kClamp : Fixity::kPosition;
  after.supports.push_back(s);
  if (!Apply(QString("add %1 (%2)").arg(QString::fromStdString(s.name)).arg(rule), after))
    return false;
  list_->setCurrentRow(list_->count() - 1);
  return true;
}

bool SupportsPanel::setFixity(int fixity) {
  const int i = list_->currentRow();
  Scene after = document_->scene();
  if (refreshing_ || i < 0 || i >= static_cast<int>(after.supports.size())) return false;
  after.supports[i].fix = fixity == 1 ? Fixity::kClamp : Fixity::kPosition;
  return Apply(QString("fixity of %1").arg(QString::fromStdString(after.supports[i].name)), after);
}

bool SupportsPanel::removeSelected() {
  const int i = list_->currentRow();
  Scene after = document_->scene();
  if (i < 0 || i >= static_cast<int>(after.supports.size())) return false;
  const QString name = QString::fromStdString(after.supports[i].name);
  after.supports.erase(after.supports.begin() + i);
  return Apply("remove " + name, after);
}

void SupportsPanel::refresh() {
  refreshing_ = true;
  const Scene& s = document_->scene();
  const int row = list_->currentRow();
  const QSignalBlocker block(list_);  // rebuilding the list is not a selection
  list_->clear();
  for (const Support& support : s.supports)
    list_->addItem(QString("%1: %2, %3")
                       .arg(QString::fromStdString(support.name))
                       .arg(Describe(support.select))
                       .arg(support.fix == Fixity::kClamp ? "clamped" : "pinned"));
  if (!s.supports.empty()) {
    const int i = std::clamp(row, 0, static_cast<int>(s.supports.size()) - 1);
    list_->setCurrentRow(i);
    fixity_->setCurrentIndex(s.supports[i].fix == Fixity::kClamp ? 1 : 0);
  }
  refreshing_ = false;
}

}  // namespace drape
