// The contact pressure of a frictionless elastic solution against the 2-D Hertz solution of a
// rigid cylinder of radius R on a half-plane (parabolic approximation of the cylinder):
//   P = ∫ p ds,  E* = E / (1 − ν²),  a² = 4 P R / (π E*),  p_H(x) = (2P / (π a²)) √(a² − (x − x_c)²).
#pragma once

#include "contact/elastic_contact.hpp"

namespace hpcontact::postprocess {

struct HertzComparison {
  double total_force = 0.0;       ///< P of the discrete pressure
  double hertz_half_width = 0.0;  ///< a of Hertz for that P
  /// The discrete contact half-width: half the extent of {p_h > 1e-2 max p_h} on Γ_C (both sampled), to
  /// 5e-4 of the segment length by sampling. The threshold lies above the oscillations a
  /// multiplier constrained at points shows beside the free boundary (≈ 2e-3 max p_h at p_C = 3)
  /// and costs little: p_H = 1e-2 max p_H lies 5e-5 a inside the Hertz edge.
  double half_width = 0.0;
  double profile_error = 0.0;  ///< ‖p_h − p_H‖_{L²(Γ_C)} / ‖p_H‖_{L²(Γ_C)}
};

/// Γ_C must be a segment of the line y = const (x is the coordinate along it); `plane_strain_modulus`
/// is E* (E / (1 − ν²) in plane strain). @throws InputError if Γ_C is not straight and horizontal
/// or the pressure vanishes.
HertzComparison compare_with_hertz(const contact::ElasticContactSetup& setup,
                                   const contact::ElasticContactSolution& solution, double radius,
                                   double plane_strain_modulus, double centre = 0.0);

}  // namespace hpcontact::postprocess
