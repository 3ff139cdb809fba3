// The table of a plan's evaluations (DIR/plan.csv, docs/plan.md): one row
// per evaluation, in the order they ended, with its parameters, objective
// terms, each constraint's margin, status and time.
#pragma once

#include <filesystem>
#include <vector>

#include "core/plan/plan_file.h"
#include "core/plan/plan_search.h"

namespace drape {

// Writes the rows (header first; an empty cell where a number does not
// exist, never NaN or inf). Throws std::runtime_error when it cannot write.
void WritePlanCsv(const Plan& plan,
                  const std::vector<PlanEvaluation>& evaluations,
                  const std::filesystem::path& file);

}  // namespace drape
