#include "ui/widgets/holds_panel.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

#include "core/model/overloaded.h"
#include "core/model/scene.h"
#include "ui/widgets/edit_feedback.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_part_watch.h"
#include "ui/widgets/selection_rule.h"

namespace drape {
namespace {

// Supports and grippers alike: a name, the nodes and how they are held.
struct Hold {
  std::string name;
  Selection select;
  Fixity fixity = Fixity::kPosition;
};

std::vector<Hold> HoldsOf(const Scene& s, HoldsPanel::Role role) {
  std::vector<Hold> holds;
  if (role == HoldsPanel::Role::kSupports)
    for (const Support& h : s.supports) holds.push_back({h.name, h.select, h.fix});
  else
    for (const Gripper& h : s.grippers) holds.push_back({h.name, h.select, h.hold});
  return holds;
}

void SetHolds(Scene& s, HoldsPanel::Role role, const std::vector<Hold>& holds) {
  if (role == HoldsPanel::Role::kSupports) {
    s.supports.clear();
    for (const Hold& h : holds) s.supports.push_back({h.name, h.select, h.fixity});
  } else {
    s.grippers.clear();
    for (const Hold& h : holds) s.grippers.push_back({h.name, h.select, h.fixity});
  }
}

}  // namespace

HoldsPanel::HoldsPanel(Role role, SceneDocument* document, QWidget* parent)
    : QWidget(parent), role_(role), document_(document) {
  const QString noun = role == Role::kSupports ? "support" : "gripper";
  auto* layout = new QVBoxLayout(this);
  list_ = new QListWidget(this);
  layout->addWidget(list_, 1);
  auto* form = new QFormLayout;
  rule_ = new SelectionRuleEditor(form, "holds", this);
  fixity_ = new QComboBox(this);
  fixity_->addItems(
      {"pinned (held in place, free to turn)", "clamped (held and kept from turning)"});
  fixity_->setToolTip(
      "pinned: the nodes keep their place (fix: position); clamped: they keep their place and "
      "the fabric's direction there, as between the jaws of a clamp (fix: clamp, the director "
      "held)");
  form->addRow("holds by", fixity_);
  layout->addLayout(form);
  auto* buttons = new QHBoxLayout;
  auto* add = new QPushButton("Add " + noun, this);
  auto* hold_picked = new QPushButton("Hold picked", this);
  hold_picked->setToolTip("the selected " + noun + " holds the picked nodes instead");
  auto* remove = new QPushButton("Remove", this);
  buttons->addWidget(add);
  buttons->addWidget(hold_picked);
  buttons->addWidget(remove);
  layout->addLayout(buttons);
  message_ = MakeMessageLabel(this);
  layout->addWidget(message_);
  connect(add, &QPushButton::clicked, this, [this] {
    QString problem;
    if (const auto s = rule_->current(&problem))
      AddHold(*s, fixity_->currentIndex());
    else
      message_->setText(problem);
  });
  connect(hold_picked, &QPushButton::clicked, this, &HoldsPanel::holdPicked);
  connect(remove, &QPushButton::clicked, this, &HoldsPanel::removeSelected);
  connect(fixity_, &QComboBox::activated, this, &HoldsPanel::setFixity);
  connect(list_, &QListWidget::currentRowChanged, this, [this](int i) {
    const auto holds = HoldsOf(document_->scene(), role_);
    if (i < 0 || i >= static_cast<int>(holds.size())) return;
    const QSignalBlocker block(fixity_);
    fixity_->setCurrentIndex(holds[i].fixity == Fixity::kClamp ? 1 : 0);
    rule_->show(holds[i].select);
  });
  new ScenePartWatch(
      document_,
      role == Role::kSupports ? SceneDocument::Part::kSupports : SceneDocument::Part::kGrippers,
      [this] { refresh(); },
      this);
  rule_->followFabric(document_);
  refresh();
}

QString HoldsPanel::message() const {
  return message_->text();
}

void HoldsPanel::setPickedNodes(const std::vector<int>& nodes,
                                const std::vector<std::array<double, 2>>& at) {
  rule_->setPicked(nodes, at);
}

bool HoldsPanel::Apply(const QString& what, const Scene& after) {
  return ApplyOrSay(document_, message_, what, after);
}

bool HoldsPanel::add(const QString& rule, int fixity, double x, double y) {
  QString problem;
  const auto selection = rule_->selection(rule, x, y, &problem);
  if (!selection) {
    message_->setText(problem);
    return false;
  }
  return AddHold(*selection, fixity);
}

bool HoldsPanel::AddHold(const Selection& selection, int fixity) {
  Scene after = document_->scene();
  auto holds = HoldsOf(after, role_);
  // Names are unique over supports and grippers (stages name grippers).
  Hold h;
  h.name = FreeName(role_ == Role::kSupports ? "support" : "gripper",
                    static_cast<int>(holds.size()) + 1,
                    [&](const std::string& name) {
                      return std::any_of(after.supports.begin(),
                                         after.supports.end(),
                                         [&](const Support& o) { return o.name == name; }) ||
                             std::any_of(after.grippers.begin(),
                                         after.grippers.end(),
                                         [&](const Gripper& g) { return g.name == name; });
                    });
  h.select = selection;
  h.fixity = fixity == 1 ? Fixity::kClamp : Fixity::kPosition;
  holds.push_back(h);
  SetHolds(after, role_, holds);
  if (!Apply(QString("add %1 (%2)")
                 .arg(QString::fromStdString(h.name))
                 .arg(DescribeSelection(selection, units_)),
             after))
    return false;
  list_->setCurrentRow(list_->count() - 1);
  return true;
}

bool HoldsPanel::setFixity(int fixity) {
  const int i = list_->currentRow();
  Scene after = document_->scene();
  auto holds = HoldsOf(after, role_);
  if (refreshing_ || i < 0 || i >= static_cast<int>(holds.size())) return false;
  holds[i].fixity = fixity == 1 ? Fixity::kClamp : Fixity::kPosition;
  SetHolds(after, role_, holds);
  return Apply(QString("fixity of %1").arg(QString::fromStdString(holds[i].name)), after);
}

bool HoldsPanel::holdPicked() {
  const int i = list_->currentRow();
  Scene after = document_->scene();
  auto holds = HoldsOf(after, role_);
  if (i < 0 || i >= static_cast<int>(holds.size())) return false;
  QString problem;
  const auto picked = rule_->picked(&problem);
  if (!picked) {
    message_->setText(problem);
    return false;
  }
  holds[i].select = *picked;
  SetHolds(after, role_, holds);
  return Apply(QString("%1 holds %2")
                   .arg(QString::fromStdString(holds[i].name))
                   .arg(DescribeSelection(*picked, units_)),
               after);
}

bool HoldsPanel::removeSelected() {
  const int i = list_->currentRow();
  Scene after = document_->scene();
  auto holds = HoldsOf(after, role_);
  if (i < 0 || i >= static_cast<int>(holds.size())) return false;
  const QString name = QString::fromStdString(holds[i].name);
  holds.erase(holds.begin() + i);
  SetHolds(after, role_, holds);
  return Apply("remove " + name, after);
}

void HoldsPanel::refresh() {
  refreshing_ = true;
  const auto holds = HoldsOf(document_->scene(), role_);
  const int row = list_->currentRow();
  const QSignalBlocker block(list_);  // rebuilding the list is not a selection
  list_->clear();
  for (const Hold& h : holds)
    list_->addItem(QString("%1: %2, %3")
                       .arg(QString::fromStdString(h.name))
                       .arg(DescribeSelection(h.select, units_))
                       .arg(h.fixity == Fixity::kClamp ? "clamped" : "pinned"));
  if (!holds.empty()) {
    const int i = std::clamp(row, 0, static_cast<int>(holds.size()) - 1);
    list_->setCurrentRow(i);
    fixity_->setCurrentIndex(holds[i].fixity == Fixity::kClamp ? 1 : 0);
    rule_->show(holds[i].select);
  }
  refreshing_ = false;
}

void HoldsPanel::setUnitSystem(UnitSystem system) {
  units_ = system;
  rule_->setUnitSystem(system);
  refresh();
}

}  // namespace drape
