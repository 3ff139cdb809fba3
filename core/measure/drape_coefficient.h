// The Cusick drape test (BS 5058, ISO 9073-9) measured on a state: the
// drape coefficient, the nodes and the shadow's outline, as a drapemeter
// reports them.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/measure/drape_nodes.h"
#include "core/measure/radial_profile.h"
#include "core/measure/shadow.h"

namespace drape {

struct DrapeTestOptions {
  Eigen::Vector3d down{0, 0, -1};   // gravity's direction
  Eigen::Vector3d centre{0, 0, 0};  // the support disc's centre [m]
  double disc_radius = 0;           // [m]
  double specimen_area = 0;         // the flat specimen's area [m²]
  int profile_samples = 1440;       // rays of the outline, 0.25° apart
  // A node stands out of the outline by at least this fraction of the
  // hanging length (the flat specimen's equivalent radius minus the
  // disc's); 0.025 is 1.5 mm for the standard 30 cm specimen on 18 cm discs.
  double node_prominence = 0.025;
};

struct DrapeMeasurement {
  double drape_coefficient = 0;  // (A_shadow − A_disc)/(A_specimen − A_disc)
  double shadow_area = 0;        // [m²]
  double disc_area = 0;          // [m²]
  double specimen_area = 0;      // [m²]
  Shadow shadow;                 // in the plane across gravity through the centre
  RadialProfile profile;         // about the centre
  std::vector<DrapeNode> nodes;
};

// "drape coefficient 0.905 · 4 nodes": what the overlay and the workbench say.
std::string DrapeSummary(const DrapeMeasurement& m);

// Throws std::invalid_argument for a disc not smaller than the specimen, a
// non-positive disc radius or area, or a state that is not finite.
DrapeMeasurement MeasureDrape(const Eigen::MatrixX3d& positions,
                              const Eigen::Matrix<int, Eigen::Dynamic, 4>& quads,
                              const DrapeTestOptions& options);

}  // namespace drape
