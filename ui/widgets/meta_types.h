// Core types that cross threads in queued signals.
#pragma once

#include <QMetaType>

#include <memory>

#include "core/model/scene.h"
#include "core/solve/error_estimate.h"
#include "core/solve/shell_solver.h"
#include "core/solve/solve_summary.h"
#include "core/solve/step_state.h"

Q_DECLARE_METATYPE(drape::Scene)
Q_DECLARE_METATYPE(drape::ErrorEstimate)
Q_DECLARE_METATYPE(drape::SolveSummary)
Q_DECLARE_METATYPE(std::shared_ptr<const drape::StepState>)
Q_DECLARE_METATYPE(std::shared_ptr<drape::ShellSolver>)
