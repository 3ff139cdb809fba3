#include "ui/widgets/selection_rule.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>

#include "core/model/overloaded.h"

namespace drape {

QString DescribeSelection(const Selection& selection) {
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
      selection.shape);
}

SelectionRuleEditor::SelectionRuleEditor(QFormLayout* form, const QString& label, QWidget* parent)
    : QObject(parent) {
  rule_ = new QComboBox(parent);
  rule_->addItems({"left", "right", "bottom", "top", "corners", "point", "picked"});
  rule_->setToolTip(
      "an edge, the corners, the node nearest a point, or the nodes picked in the "
      "view (Pick nodes, then click the fabric)");
  x_ = new QDoubleSpinBox(parent);
  y_ = new QDoubleSpinBox(parent);
  for (QDoubleSpinBox* s : {x_, y_}) {
    s->setRange(-100, 100);
    s->setDecimals(4);
    s->setSuffix(" m");
  }
  picked_label_ = new QLabel("no nodes picked", parent);
  form->addRow(label, rule_);
  form->addRow("point x", x_);
  form->addRow("point y", y_);
  form->addRow("picked", picked_label_);
}

void SelectionRuleEditor::setPicked(const std::vector<int>& nodes,
                                    const std::vector<std::array<double, 2>>& at) {
  picked_ = nodes;
  picked_at_ = at;
  picked_label_->setText(nodes.empty() ? "no nodes picked"
                                       : QString("%1 nodes picked").arg(nodes.size()));
}

std::optional<Selection> SelectionRuleEditor::picked(QString* problem) const {
  if (picked_.empty()) {
    if (problem) *problem = "no nodes picked: turn on Pick nodes and click the fabric";
    return std::nullopt;
  }
  if (picked_.size() == 1 && picked_at_.size() == 1)
    return Selection{PointSelection{picked_at_[0]}, std::nullopt};
  return Selection{NodesSelection{picked_}, std::nullopt};
}

std::optional<Selection> SelectionRuleEditor::current(QString* problem) const {
  return selection(rule_->currentText(), x_->value(), y_->value(), problem);
}

std::optional<Selection> SelectionRuleEditor::selection(const QString& rule,
                                                        double x,
                                                        double y,
                                                        QString* problem) const {
  if (rule == "corners") return Selection{CornersSelection{}, std::nullopt};
  if (rule == "point") return Selection{PointSelection{{x, y}}, std::nullopt};
  if (rule == "picked") return picked(problem);
  const QStringList sides = {"left", "right", "bottom", "top"};
  if (!sides.contains(rule)) {
    if (problem) *problem = "no such rule: " + rule;
    return std::nullopt;
  }
  return Selection{EdgeSelection{static_cast<Side>(sides.indexOf(rule))}, std::nullopt};
}

}  // namespace drape
