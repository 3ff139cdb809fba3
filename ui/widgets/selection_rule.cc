#include "ui/widgets/selection_rule.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>

#include <cmath>

#include "core/model/overloaded.h"
#include "core/model/units.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_part_watch.h"
#include "ui/widgets/typed_json.h"

namespace drape {

QString DescribeSelection(const Selection& selection, UnitSystem system) {
  return std::visit(
      Overloaded{
          [&](const PointSelection& p) {
            return QString("point (%1)").arg(ListText(p.at, system));
          },
          [&](const LineSelection& l) {
            return QString("line (%1) to (%2)")
                .arg(ListText(l.from, system), ListText(l.to, system));
          },
          [&](const BoxSelection& b) {
            return QString("box (%1) to (%2)")
                .arg(ListText(b.min, system), ListText(b.max, system));
          },
          [&](const CircleSelection& c) {
            return QString("circle (%1), radius %2")
                .arg(ListText(c.center, system), QuantityText(c.radius, Measure::kLength, system));
          },
          [](const CornersSelection&) { return QString("corners"); },
          [](const EdgeSelection& e) {
            const char* names[] = {
                "left edge", "right edge", "bottom edge", "top edge", "boundary"};
            return QString(names[static_cast<int>(e.side)]);
          },
          [](const NodesSelection& n) { return QString("%1 nodes").arg(n.nodes.size()); },
          [](const PatternMarkSelection& m) {
            return QString("%1 %2").arg(PatternMarkName(m.mark)).arg(m.index);
          },
      },
      selection.shape);
}

SelectionRuleEditor::SelectionRuleEditor(QFormLayout* form, const QString& label, QWidget* parent)
    : QObject(parent) {
  rule_ = new QComboBox(parent);
  rule_->addItems({"left",
                   "right",
                   "bottom",
                   "top",
                   "corners",
                   "point",
                   "circle",
                   "picked",
                   "notch",
                   "drill hole",
                   "internal line"});
  rule_->setToolTip(
      "an edge, the corners, the node nearest a point, every node within a radius of "
      "a point (a drape tester's disc), the nodes picked in the view (Pick nodes, "
      "then click the fabric), or a pattern piece's notch, drill hole or internal line "
      "(the mark row's number)");
  point_ = new QLineEdit("0, 0", parent);
  point_->setPlaceholderText("x, y (e.g. 5 cm, 0)");
  point_->setToolTip(
      "the point's reference x, y, or the circle's centre; units allowed (m, cm, in)");
  radius_ = new QLineEdit("9 cm", parent);
  radius_->setPlaceholderText("e.g. 9 cm");
  radius_->setToolTip("the circle's radius: every node within it is selected; units allowed");
  picked_label_ = new QLabel("no nodes picked", parent);
  mark_ = new QSpinBox(parent);
  mark_->setRange(1, 9999);
  mark_->setToolTip(
      "which notch, drill hole or internal line of the pattern piece, counted from 1 in "
      "the pattern file's order");
  marks_ = new QLabel("the fabric is not a pattern piece", parent);
  marks_->setWordWrap(true);
  form->addRow(label, rule_);
  form->addRow("point", point_);
  form->addRow("radius", radius_);
  form->addRow("picked", picked_label_);
  form->addRow("mark", mark_);
  form->addRow("marks", marks_);
}

void SelectionRuleEditor::show(const Selection& selection) {
  std::visit(Overloaded{
                 [&](const PointSelection& p) {
                   rule_->setCurrentText("point");
                   point_->setText(ListText(p.at, units_));
                 },
                 [&](const CircleSelection& c) {
                   rule_->setCurrentText("circle");
                   point_->setText(ListText(c.center, units_));
                   radius_->setText(QuantityText(c.radius, Measure::kLength, units_));
                 },
                 [&](const CornersSelection&) { rule_->setCurrentText("corners"); },
                 [&](const PatternMarkSelection& m) {
                   rule_->setCurrentText(PatternMarkName(m.mark));
                   mark_->setValue(m.index);
                 },
                 [&](const EdgeSelection& e) {
                   if (e.side != Side::kBoundary) rule_->setCurrentIndex(static_cast<int>(e.side));
                 },
                 [](const auto&) {},
             },
             selection.shape);
}

void SelectionRuleEditor::setUnitSystem(UnitSystem system) {
  units_ = system;
  try {
    point_->setText(ListText(TypedPoint(point_->text()), units_));
  } catch (const UnitError&) {
    // Text that does not read stays as typed: Add says what is wrong.
  }
  try {
    radius_->setText(
        QuantityText(TypedMeasure(radius_->text(), Measure::kLength), Measure::kLength, units_));
  } catch (const UnitError&) {
    // As the point: Add says what is wrong.
  }
}

void SelectionRuleEditor::setFabric(const Fabric& fabric) {
  const auto* pattern = std::get_if<PatternOutline>(&fabric.outline);
  if (!pattern) {
    marks_->setText("the fabric is not a pattern piece");
    return;
  }
  const PatternPiece& piece = pattern->shape;
  auto count = [](std::size_t n, const char* one, const char* many) {
    return QString("%1 %2").arg(n).arg(n == 1 ? one : many);
  };
  marks_->setText(QString("%1: %2, %3, %4")
                      .arg(QString::fromStdString(pattern->piece),
                           count(piece.notches.size(), "notch", "notches"),
                           count(piece.drills.size(), "drill hole", "drill holes"),
                           count(piece.internal_lines.size(), "internal line", "internal lines")));
}

void SelectionRuleEditor::followFabric(SceneDocument* document) {
  new ScenePartWatch(
      document,
      SceneDocument::Part::kFabric,
      [this, document] { setFabric(document->scene().fabric); },
      this);
  setFabric(document->scene().fabric);
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
  const QString rule = rule_->currentText();
  if (rule != "point" && rule != "circle") return selection(rule, 0, 0, problem);
  try {
    const Vec2 at = TypedPoint(point_->text());
    return selection(rule, at[0], at[1], problem);
  } catch (const UnitError& e) {
    if (problem) *problem = QString("point: %1").arg(e.what());
    return std::nullopt;
  }
}

std::optional<Selection> SelectionRuleEditor::selection(const QString& rule,
                                                        double x,
                                                        double y,
                                                        QString* problem) const {
  if (rule == "corners") return Selection{CornersSelection{}, std::nullopt};
  if (rule == "point") return Selection{PointSelection{{x, y}}, std::nullopt};
  if (rule == "circle") {
    double radius = 0;
    try {
      radius = TypedMeasure(radius_->text(), Measure::kLength);
    } catch (const UnitError& e) {
      if (problem) *problem = QString("radius: %1").arg(e.what());
      return std::nullopt;
    }
    if (!(radius > 0) || !std::isfinite(radius)) {
      if (problem) *problem = "radius: a circle's radius must be a length greater than zero";
      return std::nullopt;
    }
    return Selection{CircleSelection{{x, y}, radius}, std::nullopt};
  }
  if (rule == "picked") return picked(problem);
  for (PatternMark kind : {PatternMark::kNotch, PatternMark::kDrill, PatternMark::kInternalLine})
    if (rule == PatternMarkName(kind))
      return Selection{PatternMarkSelection{kind, mark_->value()}, std::nullopt};
  const QStringList sides = {"left", "right", "bottom", "top"};
  if (!sides.contains(rule)) {
    if (problem) *problem = "no such rule: " + rule;
    return std::nullopt;
  }
  return Selection{EdgeSelection{static_cast<Side>(sides.indexOf(rule))}, std::nullopt};
}

}  // namespace drape
