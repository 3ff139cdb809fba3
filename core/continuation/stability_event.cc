#include "core/continuation/stability_event.h"

namespace drape {

const char* ToString(StabilityKind kind) {
  return kind == StabilityKind::kLimit ? "limit" : "bifurcation";
}

const char* ToString(Branch branch) {
  switch (branch) {
    case Branch::kFundamental:
      return "fundamental";
    case Branch::kStable:
      return "stable";
    case Branch::kNone:
      return "none";
  }
  return "?";
}

}  // namespace drape
