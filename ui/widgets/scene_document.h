// The scene being edited: its file, every edit as an undoable command
// (QUndoStack) holding the scene before and after, save and open. Editors
// change the scene only through apply(), so every edit undoes. With the
// scene, its one shell model: built once per change of the scene (the
// model check() built for an accepted edit is the one kept), shared by the
// view, the panels and the run. Each change says which of the scene's
// top-level parts it changed, so an editor of one part redraws only when
// that part did.
#pragma once

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <filesystem>
#include <memory>
#include <optional>

#include <nlohmann/json_fwd.hpp>

#include "core/fe/shell_model.h"
#include "core/model/scene.h"

namespace drape {

class SceneDocument : public QObject {
  Q_OBJECT
 public:
  explicit SceneDocument(QObject* parent = nullptr);

  // The scene's top-level parts, each named by its key in the scene file.
  enum class Part {
    kName = 1 << 0,
    kDescription = 1 << 1,
    kFabric = 1 << 2,
    kMaterial = 1 << 3,
    kSupports = 1 << 4,
    kGrippers = 1 << 5,
    kLoads = 1 << 6,
    kObstacles = 1 << 7,
    kContact = 1 << 8,
    kGravity = 1 << 9,
    kStages = 1 << 10,
    kSolver = 1 << 11,
    kProbes = 1 << 12,
  };
  Q_ENUM(Part)
  Q_DECLARE_FLAGS(Parts, Part)
  Q_FLAG(Parts)
  static constexpr Parts kAllParts = Parts::fromInt((1 << 13) - 1);
  // The scene file's key of `part` ("fabric", "gravity", …).
  static const char* key(Part part);
  // The parts in which `a` and `b` differ.
  static Parts differences(const Scene& a, const Scene& b);

  const Scene& scene() const { return scene_; }
  const QString& file() const { return file_; }
  QUndoStack* undoStack() { return &undo_; }
  bool isModified() const { return !undo_.isClean(); }
  // The shell model of scene(); null when the engine cannot model it (after
  // an apply() not checked, or an undo to such a scene), with the engine's
  // message in modelProblem(). Changes only with the scene.
  const std::shared_ptr<const ShellModel>& model() const { return model_; }
  const QString& modelProblem() const { return model_problem_; }
  // Shell models the documents of this process built (check(), open, undo,
  // redo): what shows that an accepted edit builds one.
  static long long modelBuilds();

  // Reads a scene file and models it (throws SceneError /
  // std::runtime_error, keeping what was open); clears undo.
  void open(const QString& file);
  // A new, unsaved scene from a template file (Save then asks where).
  void openTemplate(const QString& file);
  // Writes the scene; throws std::runtime_error naming the file. Saved into
  // another folder, file references (Kawabata data, obstacle meshes) are
  // written as absolute paths, so the scene still finds them.
  void saveAs(const QString& file);
  // An edit named `what` ("thickness 0.5 mm"): undoable; nothing happens
  // when `after` equals the scene, or while the document is locked.
  void apply(const QString& what, const Scene& after);

  // Locked while a run works on the scene: every edit is refused (tryApply
  // says why), so no editor, dialog or script can change it under the run.
  void setLocked(bool locked) { locked_ = locked; }
  bool isLocked() const { return locked_; }

  // The folder the scene's relative file references are resolved in.
  std::filesystem::path directory() const;
  // A scene's JSON form read by the scene reader's rules, references
  // resolved in directory(). Throws SceneError with the reader's message.
  Scene parse(const nlohmann::json& document) const;
  // What is wrong with `after` by the reader's rules and the engine's (it
  // must mesh and every selection must match nodes), or "". The model it
  // builds is kept for `after`, should it be applied next.
  QString check(const Scene& after) const;
  // check(), then apply(); false with the reason in `problem`.
  bool tryApply(const QString& what, const Scene& after, QString* problem = nullptr);

  // The scene's JSON form, as the scene file has it: editors put what the
  // user typed into it and hand it back to tryApplyJson.
  nlohmann::json json() const;
  // `document` read by parse() (the reader's message, with the key, when
  // it is wrong), then tryApply().
  bool tryApplyJson(const QString& what,
                    const nlohmann::json& document,
                    QString* problem = nullptr);

 signals:
  void changed();  // after open, an edit, undo or redo
  // Right after changed(): the parts that changed (every part on open). An
  // undo names the parts its edit changed, as does the redo.
  void partsChanged(drape::SceneDocument::Parts parts);

 private:
  friend class SceneEdit;
  void set(const Scene& scene);
  // The model of `scene`: check()'s when it was for this scene, else built.
  void Model(const Scene& scene);

  Scene scene_;
  std::shared_ptr<const ShellModel> model_;
  QString model_problem_;
  // The last scene check() accepted, with its model.
  mutable std::optional<Scene> checked_;
  mutable std::shared_ptr<const ShellModel> checked_model_;
  QString file_;
  QString origin_;  // the folder the scene's relative references are in
  QUndoStack undo_;
  bool locked_ = false;
};

}  // namespace drape

// Outside the namespace: declared in it, these operators would hide Qt's own
// (Qt::CTRL | Qt::Key_E) from code in namespace drape.
Q_DECLARE_OPERATORS_FOR_FLAGS(drape::SceneDocument::Parts)
