// Boundary samples of an elastic contact solution on Γ_C (boundary_<effect>.csv): the normal and
// tangential displacement, the gap to the obstacle, the contact pressure and the tangential
// traction; for a pair of bodies (boundary_<pair>_<effect>.csv) the gap between them and both
// bodies' normal displacements.
#pragma once

#include "contact/elastic_contact.hpp"
#include "contact/two_body_contact.hpp"
#include "io/csv_writer.hpp"
#include "mesh/contact_pair_geometry.hpp"
#include "postprocess/bound_violation.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::postprocess {

struct ElasticBoundarySamples {
  /// x,y,s_arc,u_n,u_t,gap,pressure,traction_t,sigma_xx,sigma_yy,sigma_zz,sigma_xy,zone with
  /// gap = g − u·n ≥ 0, pressure = −σ_nn ≥ 0 in contact (the normal multiplier), traction_t = σ_nt
  /// (along increasing s), σ(u_h) from the cell beside Γ_C (one body; a pair's samples have their
  /// own columns), zone of Γ_C.
  io::CsvTable table;
  double contact_set_length = 0.0;  ///< where pressure > 1e-10 max pressure, from the samples
  double total_force = 0.0;         ///< P = ∫_{Γ_C} pressure ds (exact, from the multiplier)
  double tangential_force = 0.0;    ///< T = ∫_{Γ_C} σ_nt ds (exact, from the multiplier)
  /// The resultant of the contact traction on the body, ∫_{Γ_C} (−p n + σ_nt t) ds (Gauss
  /// quadrature on each interval of the common refinement, exact on straight edges).
  Eigen::Vector2d contact_force = Eigen::Vector2d::Zero();
  std::vector<double> zone_contact_set_length, zone_total_force, zone_tangential_force;  ///< per zone of Γ_C
  std::vector<Eigen::Vector2d> zone_contact_force;
  BoundViolation bounds;  ///< the pressure below 0 between the constraint points
};

/// P = ∫_{Γ_C} p ds of a multiplier in M^{p_C}(T_{C,H}) (Legendre coefficients): ∫ P_0 = 2 on
/// [-1, 1], so each segment contributes its c_0 times its length.
double total_force(const space::MultiplierSpace& multipliers, const Eigen::VectorXd& pressure, int zone = -1);

/// Samples every interval of the common refinement of T_h|Γ_C and T_{C,H} at `per_interval`
/// equidistant points including both ends.
ElasticBoundarySamples sample_elastic_boundary(const contact::ElasticContactSetup& setup,
                                               const contact::ElasticContactSolution& solution, int per_interval = 20);

/// The same on the slave's Γ_C of a pair, the table's columns
/// x,y,s_arc,gap,pressure,traction_t,u_n_slave,u_n_master,zone with gap = g − (u_s − u_m∘Φ)·n_s,
/// g = (Φ(x) − x)·n_s (`projection` onto the master's Γ_C), u_n_master = u_m(Φ(x))·n_s.
ElasticBoundarySamples sample_pair_boundary(const contact::TwoBodyContactSetup& setup,
                                            const contact::TwoBodyContactSolution& solution,
                                            const mesh::MasterProjection& projection, int per_interval = 20);

}  // namespace hpcontact::postprocess
