// What a scene's obstacles and holds mean for contact: the NodeContact a
// run uses (null without obstacles), whether contact alone must keep the
// fabric from moving as a rigid body (then it is stabilised), and the
// barrier that keeps the fabric's layers apart.
#pragma once

#include <memory>

#include "core/contact/node_contact.h"
#include "core/contact/self_contact.h"
#include "core/fe/dof_map.h"
#include "core/fe/shell_model.h"
#include "core/model/scene.h"

namespace drape {

// The scene's obstacles with its penalty ("auto": AutoPenalty) and friction.
// Throws SceneError ("obstacles") when the reference fabric starts inside an
// obstacle, naming the deepest node, its depth and the obstacle; and for an
// unreadable or open mesh obstacle ("obstacles[i].mesh.file").
std::unique_ptr<NodeContact> MakeNodeContact(const Scene& scene, const ShellModel& model);

// The normal law of a scene's contact: its penalty ("auto": AutoPenalty),
// or its barrier (contact.law "barrier"), whose distance defaults to half
// the thickness.
NormalLaw NormalLawFor(const Scene& scene, const ShellModel& model);

// contact.barrier_distance against the part's size (its diagonal [m]).
void CheckBarrierDistance(const Scene& scene, double part_diagonal);

// contact.friction_slip against the part's size (its diagonal [m]): a
// SceneError naming the key when it is not smaller.
void CheckFrictionSlip(const Scene& scene, double part_diagonal);

// Whether the held nodes alone stop every rigid motion: three of them not on
// one line (a clamp fixes position and director, so one clamped node with a
// second held node also does).
bool HoldsRestrainRigidMotion(const ShellModel& model, const DofMap& dofs);

// Parts of the fabric count as distinct layers when farther apart at rest
// than a few elements (a fold's hinge bends them close) and than ten
// thicknesses [m]. `element_size`: the mean element edge.
double LayerExclusion(const ShellModel& model, double element_size);

// The self-contact barrier of a scene (contact.self): the layers kept
// contact.thickness apart (default the fabric's), the barrier acting over
// half that again, and stiff enough that halfway into its band it carries
// ten times a node's weight.
SelfContactSettings SelfContactSettingsFor(const Scene& scene,
                                           const ShellModel& model,
                                           double exclusion);

}  // namespace drape
