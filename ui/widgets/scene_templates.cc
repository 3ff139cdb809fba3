#include "ui/widgets/scene_templates.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <stdexcept>

#include "core/io/resource_dir.h"

namespace drape {
namespace {

QJsonObject ReadObject(const QString& file) {
  QFile in(file);
  if (!in.open(QIODevice::ReadOnly)) throw std::runtime_error("cannot read " + file.toStdString());
  QJsonParseError error;
  const QJsonDocument document = QJsonDocument::fromJson(in.readAll(), &error);
  if (error.error != QJsonParseError::NoError || !document.isObject())
    throw std::runtime_error(file.toStdString() + ": not a JSON object (" +
                             error.errorString().toStdString() + ")");
  return document.object();
}

QString Required(const QJsonObject& object, const char* key, const QString& where) {
  const QString value = object.value(key).toString();
  if (value.isEmpty())
    throw std::runtime_error(where.toStdString() + ": missing '" + key + "' (a text)");
  return value;
}

}  // namespace

std::vector<TemplateGroup> SceneTemplates() {
  const QDir resources(QString::fromStdString(ResourceDir().string()));
  const QString catalogue = resources.filePath("templates.json");
  std::vector<TemplateGroup> groups;
  const QJsonArray group_list = ReadObject(catalogue).value("groups").toArray();
  for (qsizetype g = 0; g < group_list.size(); ++g) {
    const QString where = QString("%1: groups[%2]").arg(catalogue).arg(g);
    const QJsonObject group = group_list[g].toObject();
    TemplateGroup out{Required(group, "title", where), {}};
    const QJsonArray entries = group.value("templates").toArray();
    for (qsizetype t = 0; t < entries.size(); ++t) {
      const QString entry_where = QString("%1.templates[%2]").arg(where).arg(t);
      const QJsonObject entry = entries[t].toObject();
      const QString file = resources.absoluteFilePath(Required(entry, "scene", entry_where));
      if (!QFileInfo::exists(file))
        throw std::runtime_error(entry_where.toStdString() + ": no scene " + file.toStdString());
      out.templates.push_back({Required(entry, "title", entry_where),
                               QDir::cleanPath(file),
                               ReadObject(file).value("description").toString()});
    }
    groups.push_back(std::move(out));
  }
  if (groups.empty() || groups.front().templates.empty())
    throw std::runtime_error(catalogue.toStdString() + ": no templates");
  return groups;
}

SceneTemplate BlankTemplate() {
  return SceneTemplates().front().templates.front();
}

}  // namespace drape
