#include "ui/widgets/unit_settings.h"

#include <QActionGroup>
#include <QFile>
#include <QMenu>
#include <QSettings>

#include "ui/widgets/scene_document.h"

namespace drape {
namespace {

constexpr char kKey[] = "units";
constexpr char kScene[] = "scene";  // saved for "the scene's own"

QString Saved(std::optional<UnitSystem> choice) {
  return choice ? ToString(*choice) : kScene;
}

}  // namespace

UnitSettings::UnitSettings(QObject* parent) : QObject(parent) {
  const QString saved = QSettings().value(kKey, kScene).toString();
  choice_ = UnitSystemNamed(saved.toStdString());
}

void UnitSettings::Set(std::optional<UnitSystem> choice, UnitSystem scene) {
  const UnitSystem before = system();
  choice_ = choice;
  scene_ = scene;
  if (group_) {
    for (QAction* action : group_->actions())
      action->setChecked(action->data().toString() == Saved(choice_));
  }
  if (system() != before) emit changed(system());
}

void UnitSettings::setChoice(std::optional<UnitSystem> choice) {
  QSettings().setValue(kKey, Saved(choice));
  Set(choice, scene_);
}

void UnitSettings::useChoice(std::optional<UnitSystem> choice) {
  Set(choice, scene_);
}

void UnitSettings::setSceneSystem(UnitSystem system) {
  Set(choice_, system);
}

void UnitSettings::followSceneFile(const QString& file) {
  QFile in(file);
  if (file.isEmpty() || !in.open(QIODevice::ReadOnly)) return;
  setSceneSystem(GuessUnitSystem(in.readAll().toStdString()));
}

void UnitSettings::followScene(const SceneDocument* document) {
  followSceneFile(document->file());
}

QMenu* UnitSettings::menu(QWidget* parent) {
  auto* menu = new QMenu("&Units", parent);
  group_ = new QActionGroup(menu);
  const struct {
    const char* text;
    std::optional<UnitSystem> choice;
    const char* tip;
  } items[] = {
      {"&Scene's own", std::nullopt, "the units the scene file is written in"},
      {"S&I", UnitSystem::kSI, "m, N, Pa, 1/m"},
      {"&Textile", UnitSystem::kTextile, "cm, mm, gf, gf/cm², g/m², gf·cm²/cm, 1/cm"},
      {"I&mperial", UnitSystem::kImperial, "in, oz, oz/in², 1/in"},
  };
  for (const auto& item : items) {
    QAction* action = menu->addAction(item.text);
    action->setCheckable(true);
    action->setData(Saved(item.choice));
    action->setToolTip(item.tip);
    action->setStatusTip(item.tip);
    action->setChecked(item.choice == choice_);
    group_->addAction(action);
    const std::optional<UnitSystem> choice = item.choice;
    connect(action, &QAction::triggered, this, [this, choice] { setChoice(choice); });
  }
  menu->setToolTipsVisible(true);
  return menu;
}

}  // namespace drape
