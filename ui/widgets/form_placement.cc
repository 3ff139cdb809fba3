#include "ui/widgets/form_placement.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>

#include "core/io/resource_dir.h"
#include "core/model/elevation_above.h"
#include "core/model/obstacle_geometry.h"
#include "ui/widgets/edit_feedback.h"

namespace drape {
namespace {

std::vector<Eigen::Vector2d> FlatPoints(const Mesh& mesh) {
  const MeshPart first = PartsOf(mesh).front();
  std::vector<Eigen::Vector2d> points;
  for (int i = first.first_node; i < first.first_node + first.nodes; ++i)
    points.emplace_back(mesh.positions(i, 0), mesh.positions(i, 1));
  return points;
}

}  // namespace

std::vector<FormChoice> FormCatalogue() {
  const QDir forms(QString::fromStdString((ResourceDir() / "forms").string()));
  QFile in(forms.filePath("forms.json"));
  if (!in.open(QIODevice::ReadOnly))
    throw std::runtime_error("cannot read " + in.fileName().toStdString());
  const QJsonArray list = QJsonDocument::fromJson(in.readAll()).object().value("forms").toArray();
  std::vector<FormChoice> out;
  for (const QJsonValue& entry : list) {
    const QJsonObject o = entry.toObject();
    const QString file = forms.absoluteFilePath(o.value("file").toString());
    if (o.value("name").toString().isEmpty() || !QFile::exists(file))
      throw std::runtime_error(in.fileName().toStdString() + ": a form without a name or file");
    out.push_back({o.value("name").toString(),
                   file,
                   QString("bust %1, waist %2, hip %3, %4 tall")
                       .arg(o.value("bust").toString(),
                            o.value("waist").toString(),
                            o.value("hip").toString(),
                            o.value("height").toString())});
  }
  if (out.empty()) throw std::runtime_error(in.fileName().toStdString() + ": no forms");
  return out;
}

double StartClearance(const Scene& scene) {
  const double h = scene.material.thickness;
  const double amplitude = scene.fabric.imperfection ? scene.fabric.imperfection->amplitude : 0.0;
  return 0.5 * h + std::max(1e-3, h) + amplitude;
}

std::optional<Scene> FabricAbove(const Scene& scene,
                                 const Mesh& mesh,
                                 int index,
                                 const std::filesystem::path& scene_dir,
                                 QString* why) {
  const Obstacle& obstacle = scene.obstacles.at(index);
  std::optional<double> elevation;
  try {
    const auto geometry = MakeObstacleGeometry(obstacle, scene_dir);
    elevation = ElevationAbove(FlatPoints(mesh), *geometry, StartClearance(scene));
  } catch (const std::exception& e) {
    *why = QString::fromStdString(e.what());
    return std::nullopt;
  }
  if (!elevation) {
    *why = QString("the fabric is not over '%1', or it has no top to lie on")
               .arg(QString::fromStdString(obstacle.name));
    return std::nullopt;
  }
  Scene after = scene;
  after.fabric.elevation = *elevation;
  return after;
}

Scene FollowingTheForm(const Scene& before,
                       const Scene& after,
                       const Mesh& mesh,
                       int index,
                       const std::filesystem::path& scene_dir) {
  QString ignored;
  const auto was = FabricAbove(before, mesh, index, scene_dir, &ignored);
  if (!was || std::abs(was->fabric.elevation - before.fabric.elevation) > 1e-6) return after;
  return FabricAbove(after, mesh, index, scene_dir, &ignored).value_or(after);
}

Scene WithForm(const Scene& scene, const Mesh& mesh, const FormChoice& form) {
  // The middle of the fabric's extent: exact for a symmetric part.
  Eigen::AlignedBox2d extent;
  for (const Eigen::Vector2d& p : FlatPoints(mesh)) extent.extend(p);
  const Eigen::Vector2d middle = extent.center();
  MeshShape shape{form.file.toStdString(), form.file.toStdString()};
  shape.at = {middle.x(), middle.y(), 0.0};
  Scene after = scene;
  after.obstacles.push_back({FreeName("form", after.obstacles), shape});
  return after;
}

}  // namespace drape
