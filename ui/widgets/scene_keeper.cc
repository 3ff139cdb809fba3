#include "ui/widgets/scene_keeper.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

#include <exception>

#include "core/io/scene_reader.h"
#include "core/io/scene_writer.h"
#include "ui/widgets/scene_document.h"

namespace drape {

QString SceneKeeper::AutosavePath() {
  const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
  QDir().mkpath(dir);
  return dir + "/autosave.json";
}

KeeperOutcome SceneKeeper::Autosave(const SceneDocument& document) {
  if (!document.isModified()) return {false, "nothing to autosave: no unsaved edits"};
  try {
    WriteScene(document.scene(), AutosavePath().toStdString());
    QSettings().setValue("autosave/source", document.file());
    return {true, "autosaved to " + AutosavePath()};
  } catch (const std::exception& e) {
    return {false, QString("autosave failed: ") + e.what()};
  }
}

KeeperOutcome SceneKeeper::Recover(SceneDocument& document) {
  const QString file = AutosavePath();
  if (!QFileInfo::exists(file)) return {false, "no autosaved scene"};
  const QString source = QSettings().value("autosave/source").toString();
  try {
    const Scene recovered = ReadScene(file.toStdString());
    if (!source.isEmpty() && QFileInfo::exists(source)) document.open(source);
    document.apply("recovered edits", recovered);
    return {true, "recovered the autosaved scene; save it to keep it"};
  } catch (const std::exception& e) {
    return {false, QString::fromStdString(e.what())};
  }
}

void SceneKeeper::ForgetAutosave() {
  QFile::remove(AutosavePath());
}

QStringList SceneKeeper::RecentFiles() {
  return QSettings().value("recent").toStringList();
}

void SceneKeeper::Remember(const QString& file) {
  QStringList recent = RecentFiles();
  const QString absolute = QFileInfo(file).absoluteFilePath();
  recent.removeAll(absolute);
  recent.prepend(absolute);
  while (recent.size() > kRecentFiles) recent.removeLast();
  QSettings().setValue("recent", recent);
}

}  // namespace drape
