#include "ui/widgets/scene_document.h"

#include <QFileInfo>
#include <QUndoCommand>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/fe/shell_model.h"
#include "core/io/scene_reader.h"
#include "core/io/scene_writer.h"

namespace drape {

// One edit: the whole scene before and after (scenes are small next to
// their meshes and states, and this cannot get an inverse wrong).
class SceneEdit : public QUndoCommand {
 public:
  SceneEdit(SceneDocument* document, const QString& what, Scene before, Scene after)
      : QUndoCommand(what),
        document_(document),
        before_(std::move(before)),
        after_(std::move(after)) {}
  void redo() override { document_->set(after_); }
  void undo() override { document_->set(before_); }

 private:
  SceneDocument* document_;
  Scene before_, after_;
};

namespace {

long long model_builds = 0;

std::shared_ptr<const ShellModel> Build(const Scene& scene) {
  ++model_builds;
  return std::make_shared<const ShellModel>(BuildShellModel(scene));
}

}  // namespace

SceneDocument::SceneDocument(QObject* parent) : QObject(parent) {}

const char* SceneDocument::key(Part part) {
  switch (part) {
    case Part::kName:
      return "name";
    case Part::kDescription:
      return "description";
    case Part::kFabric:
      return "fabric";
    case Part::kMaterial:
      return "material";
    case Part::kSupports:
      return "supports";
    case Part::kGrippers:
      return "grippers";
    case Part::kLoads:
      return "loads";
    case Part::kObstacles:
      return "obstacles";
    case Part::kContact:
      return "contact";
    case Part::kGravity:
      return "gravity";
    case Part::kStages:
      return "stages";
    case Part::kSolver:
      return "solver";
    case Part::kProbes:
      return "probes";
  }
  return "";
}

SceneDocument::Parts SceneDocument::differences(const Scene& a, const Scene& b) {
  Parts parts;
  parts.setFlag(Part::kName, a.name != b.name);
  parts.setFlag(Part::kDescription, a.description != b.description);
  parts.setFlag(Part::kFabric, a.fabric != b.fabric);
  parts.setFlag(Part::kMaterial, a.material != b.material);
  parts.setFlag(Part::kSupports, a.supports != b.supports);
  parts.setFlag(Part::kGrippers, a.grippers != b.grippers);
  parts.setFlag(Part::kLoads, a.loads != b.loads);
  parts.setFlag(Part::kObstacles, a.obstacles != b.obstacles);
  parts.setFlag(Part::kContact, a.contact != b.contact);
  parts.setFlag(Part::kGravity, a.gravity_direction != b.gravity_direction);
  parts.setFlag(Part::kStages, a.stages != b.stages);
  parts.setFlag(Part::kSolver, a.solver != b.solver);
  parts.setFlag(Part::kProbes, a.probes != b.probes);
  return parts;
}

long long SceneDocument::modelBuilds() {
  return model_builds;
}

void SceneDocument::open(const QString& file) {
  Scene scene = ReadScene(file.toStdString());
  // Modelled before it replaces what is open: a scene the engine refuses
  // is refused with its message.
  model_ = Build(scene);
  model_problem_.clear();
  checked_.reset();
  checked_model_.reset();
  scene_ = std::move(scene);
  file_ = file;
  origin_ = QFileInfo(file).absolutePath();
  undo_.clear();
  undo_.setClean();
  emit changed();
  emit partsChanged(kAllParts);
}

void SceneDocument::openTemplate(const QString& file) {
  open(file);
  file_.clear();
}

void SceneDocument::saveAs(const QString& file) {
  // Saved into another folder, relative references would no longer resolve.
  const Scene out = !origin_.isEmpty() && QFileInfo(file).absolutePath() != origin_
                        ? WithAbsoluteReferences(scene_, origin_.toStdString())
                        : scene_;
  WriteScene(out, file.toStdString());
  scene_ = out;
  file_ = file;
  origin_ = QFileInfo(file).absolutePath();
  undo_.setClean();
}

void SceneDocument::apply(const QString& what, const Scene& after) {
  if (locked_ || after == scene_) return;
  undo_.push(new SceneEdit(this, what, scene_, after));
}

std::filesystem::path SceneDocument::directory() const {
  return origin_.isEmpty() ? std::filesystem::current_path()
                           : std::filesystem::path(origin_.toStdString());
}

Scene SceneDocument::parse(const nlohmann::json& document) const {
  return SceneFromJson(document, directory());
}

nlohmann::json SceneDocument::json() const {
  return nlohmann::json::parse(SceneToJson(scene_).dump());
}

bool SceneDocument::tryApplyJson(const QString& what,
                                 const nlohmann::json& document,
                                 QString* problem) {
  Scene after;
  try {
    after = parse(document);
  } catch (const std::exception& e) {
    if (problem) *problem = QString::fromStdString(e.what());
    return false;
  }
  return tryApply(what, after, problem);
}

QString SceneDocument::check(const Scene& after) const {
  checked_.reset();
  checked_model_.reset();
  try {
    checked_model_ = Build(parse(nlohmann::json::parse(SceneToJson(after).dump())));
    checked_ = after;
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

bool SceneDocument::tryApply(const QString& what, const Scene& after, QString* problem) {
  const QString wrong =
      locked_ ? QString("a run is working on the scene: stop it or let it finish to edit")
              : check(after);
  if (problem) *problem = wrong;
  if (!wrong.isEmpty()) return false;
  apply(what, after);
  return true;
}

void SceneDocument::Model(const Scene& scene) {
  model_problem_.clear();
  if (checked_ && *checked_ == scene) {
    model_ = std::move(checked_model_);
  } else {
    try {
      model_ = Build(scene);
    } catch (const std::exception& e) {
      model_.reset();
      model_problem_ = QString::fromStdString(e.what());
    }
  }
  checked_.reset();
  checked_model_.reset();
}

void SceneDocument::set(const Scene& scene) {
  // From the scenes themselves, so an undo names what its edit named.
  const Parts parts = differences(scene_, scene);
  Model(scene);
  scene_ = scene;
  emit changed();
  emit partsChanged(parts);
}

}  // namespace drape
