// Boundary samples of a contact solution on Γ_C (boundary_<problem>.csv): u, the obstacle or
// bound, and λ.
#pragma once

#include "assembly/cell_field.hpp"
#include "assembly/coupling.hpp"
#include "assembly/material.hpp"
#include "contact/contact_problem.hpp"
#include "io/csv_writer.hpp"
#include "linalg/distribution.hpp"
#include "postprocess/bound_violation.hpp"
#include "postprocess/point_locator.hpp"

namespace hpcontact::postprocess {

struct BoundarySamples {
  /// x,u,obstacle,lambda (Signorini) or x,u,s,lambda (friction), plus y,s_arc,zone
  io::CsvTable table;
  double contact_set_length;  ///< length of Γ_C where λ ≠ 0 (|λ| > 1e-10 max|λ|), from the samples
  std::vector<double> zone_contact_set_length;  ///< the same per zone of Γ_C
  BoundViolation bounds;                        ///< λ outside its bounds between the constraint points
};

/// The arc length of sample j of `per_interval` equidistant ones on an interval (both ends included).
inline double sample_arc(const assembly::CommonInterval& interval, int j, int per_interval) {
  return interval.s_begin + (interval.s_end - interval.s_begin) * j / (per_interval - 1);
}
/// Every interval's samples as points of the cells along Γ_C, interval by interval.
std::vector<CellPoint> sample_points(const mesh::ContactBoundary& contact,
                                     const std::vector<assembly::CommonInterval>& intervals, int per_interval);

/// The field at every point (one row each, a column per component): each point evaluated by the
/// rank that holds its cell, summed over `distribution`'s ranks, so that every rank has them all.
/// Collective when distributed (the cells of a distributed field are split over its ranks).
Eigen::MatrixXd values_at(const assembly::CellField& field, const std::vector<CellPoint>& points,
                          linalg::Distribution distribution);
/// The stress σ(u) of a displacement at every point, columns xx, yy, zz, xy (σ_zz of the plane
/// model), from the cell the point names and its material; gathered as values_at.
Eigen::MatrixXd stresses_at(const assembly::CellField& displacement, const std::vector<assembly::Material>& materials,
                            const std::vector<CellPoint>& points, linalg::Distribution distribution);

/// Samples every interval of the common refinement of T_h|Γ_C and T_{C,H} at `per_interval`
/// equidistant points including both ends, so that at least that many fall in every boundary
/// element and jumps of λ show.
BoundarySamples sample_boundary(const contact::ContactSetup& setup, const contact::ContactSolution& solution,
                                int per_interval = 20);

}  // namespace hpcontact::postprocess
