// Forms placed by hand: the forms the workbench offers (the dress form in
// its sizes, resources/forms/forms.json), a new one stood on the floor
// under the fabric, and the fabric laid just above an obstacle — where,
// lowered flat, it would first come within a small clearance of it.
#pragma once

#include <QString>

#include <filesystem>
#include <optional>
#include <vector>

#include "core/model/mesh.h"
#include "core/model/scene.h"

namespace drape {

struct FormChoice {
  QString name;          // "Dress form, medium"
  QString file;          // absolute
  QString measurements;  // "bust 85.6 cm, waist 66.1 cm, hip 90.7 cm, 60 cm tall"
};

// The catalogue in its order. Throws std::runtime_error naming what is wrong.
std::vector<FormChoice> FormCatalogue();

// The gap left under the fabric: its half thickness (its surface), the
// larger of 1 mm and its thickness, and the imperfection's amplitude.
double StartClearance(const Scene& scene);

// `scene` with the fabric's (first part's) elevation just above obstacle
// `index`, its flat nodes those of `mesh`; none, with the reason in `why`,
// when the obstacle has no top or the fabric is not over it.
std::optional<Scene> FabricAbove(const Scene& scene,
                                 const Mesh& mesh,
                                 int index,
                                 const std::filesystem::path& scene_dir,
                                 QString* why);

// `after` (an edit of `before` that moved, turned or scaled obstacle
// `index`) with the fabric laid just above the obstacle again when it lay
// just above it before (to a micrometre): a fabric placed on a form
// follows it; one placed elsewhere stays.
Scene FollowingTheForm(const Scene& before,
                       const Scene& after,
                       const Mesh& mesh,
                       int index,
                       const std::filesystem::path& scene_dir);

// `scene` with `form` added as a mesh obstacle standing on the floor
// (z = 0) under the middle of the fabric, named after the form.
Scene WithForm(const Scene& scene, const Mesh& mesh, const FormChoice& form);

}  // namespace drape
