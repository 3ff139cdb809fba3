// Reading how a scene is solved (a preset and the keys that override it)
// and the probes a run reports.
#include "core/io/scene_parser.h"

#include <cmath>

#include "core/model/solver_preset.h"

namespace drape {

SolverSettings SceneParser::ReadSolver(const JsonCursor& c) {
  c.ExpectObject({"preset",
                  "mesh_scale",
                  "tolerance",
                  "displacement_tolerance",
                  "target_iterations",
                  "acceleration",
                  "max_steps",
                  "max_iterations",
                  "max_step_cuts",
                  "max_turns",
                  "psi",
                  "branching",
                  "sequencing",
                  "max_wall_s",
                  "error_estimate"});
  SolverSettings s;
  // The preset first: the keys beside it override its values.
  if (auto p = c.Find("preset")) {
    const std::string name = p->String();
    std::optional<SolverPreset> preset = PresetNamed(name);
    if (!preset) {
      std::string names;
      for (const auto& d : PresetDefinitions())
        names += std::string(names.empty() ? "" : ", ") + d.name;
      p->Fail("'" + name + "' is not a preset; one of " + names);
    }
    s = WithPreset(s, *preset);
  }
  if (auto m = c.Find("mesh_scale")) {
    s.mesh_scale = m->Number();
    if (!(s.mesh_scale >= 0.1 && s.mesh_scale <= 10))
      m->Fail("must lie in [0.1, 10], found " + m->value().dump());
  }
  auto fraction = [&](const char* key, double& out) {
    if (auto v = c.Find(key)) {
      out = v->Number();
      if (!(out > 0 && out < 1)) v->Fail("must lie in (0, 1), found " + v->value().dump());
    }
  };
  auto count = [&](const char* key, int& out, int minimum) {
    if (auto v = c.Find(key)) {
      out = v->Integer();
      if (out < minimum)
        v->Fail("must be at least " + std::to_string(minimum) + ", found " + std::to_string(out));
    }
  };
  fraction("tolerance", s.tolerance);
  fraction("displacement_tolerance", s.displacement_tolerance);
  count("target_iterations", s.target_iterations, 1);
  count("max_steps", s.max_steps, 1);
  count("max_iterations", s.max_iterations, 1);
  count("max_step_cuts", s.max_step_cuts, 0);
  count("max_turns", s.max_turns, 0);
  if (auto q = c.Find("sequencing")) {
    if (q->value().is_string()) {
      if (q->String() != "auto")
        q->Fail("must be \"auto\" or an integer ≥ 1 (1: off), found " + q->value().dump());
      s.sequencing = kAutoSequencing;
    } else {
      count("sequencing", s.sequencing, 1);
    }
  }
  if (auto a = c.Find("acceleration")) s.acceleration = a->Boolean();
  if (auto e = c.Find("error_estimate")) s.error_estimate = e->Boolean();
  if (auto p = c.Find("psi")) s.psi = p->PositiveQuantity(dim::kLength);
  if (auto w = c.Find("max_wall_s")) {
    s.max_wall_s = w->Number();
    if (!(*s.max_wall_s > 0) || !std::isfinite(*s.max_wall_s))
      w->Fail("must be a number of seconds > 0, found " + w->value().dump());
  }
  if (auto b = c.Find("branching"))
    s.branching = static_cast<Branching>(b->Choice({"stable", "fundamental"}));
  return s;
}

Probe SceneParser::ReadProbe(const JsonCursor& c) {
  c.ExpectObject({"name", "at", "part"});
  Probe p;
  p.name = ReadName(c, "probe");
  p.at = c["at"].QuantityVec2(dim::kLength);
  p.part = ReadPartName(c);
  return p;
}

}  // namespace drape
