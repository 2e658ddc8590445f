// An isotropic material of linear elasticity in the plane: its Lamé parameters, from Young's
// modulus and Poisson's ratio in plane strain or plane stress.
#pragma once

#include <array>
#include <string>

namespace hpcontact::assembly {

enum class PlaneModel { strain, stress };

/// "plane_strain" / "plane_stress".
std::string to_string(PlaneModel model);

struct Material {
  double lambda = 0.0;  ///< first Lamé parameter (of the plane model)
  double mu = 0.0;      ///< shear modulus
  /// σ_zz = out_of_plane · (ε_xx + ε_yy): λ in plane strain, 0 in plane stress.
  double out_of_plane = 0.0;
};

/// Lamé parameters of Young's modulus E > 0 and Poisson's ratio ν ∈ (−1, ½):
///   plane strain  λ = Eν / ((1 + ν)(1 − 2ν)),  μ = E / (2(1 + ν));
///   plane stress  λ = Eν / (1 − ν²)            (the same μ).
/// @throws InputError outside these ranges.
Material lame_parameters(double young, double poisson, PlaneModel model);

/// σ = λ tr(ε) I + 2μ ε of the strain (ε_xx, ε_yy, ε_xy) as (σ_xx, σ_yy, σ_zz, σ_xy), σ_zz of the
/// plane model.
std::array<double, 4> plane_stress_of(const Material& m, double exx, double eyy, double exy);

/// The von Mises stress of (σ_xx, σ_yy, σ_zz, σ_xy).
double von_mises_of(const std::array<double, 4>& s);

}  // namespace hpcontact::assembly
