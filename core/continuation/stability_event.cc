#include "core/continuation/stability_event.h"

namespace drape {

const char* ToString(StabilityKind kind) {
  switch (kind) {
    case StabilityKind::kLimit:
      return "limit";
    case StabilityKind::kBifurcation:
      return "bifurcation";
    case StabilityKind::kSnap:
      return "snap";
  }
  return "?";
}

const char* ToString(SnapTrigger trigger) {
  switch (trigger) {
    case SnapTrigger::kLimit:
      return "limit";
    case SnapTrigger::kBifurcation:
      return "bifurcation";
    case SnapTrigger::kStart:
      return "start";
    case SnapTrigger::kSliding:
      return "sliding";
    case SnapTrigger::kRelease:
      return "release";
    case SnapTrigger::kStalled:
      return "stalled";
  }
  return "?";
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
