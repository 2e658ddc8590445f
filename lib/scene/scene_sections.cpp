// The sections of a scene file in file order, with whether each is required and what it holds
// (the reader's order and the key reference's headings).
#include "scene/scene_keys.hpp"

namespace hpcontact::scene {

const std::vector<SceneSection>& scene_sections() {
  static const std::vector<SceneSection> sections{
      {"domain", true, "Ω and T_h: a rectangle or a Gmsh mesh"},
      {"boundary", true, "the boundary parts Γ_C and Γ_D"},
      {"contact_mesh", true, "T_{C,H}: exactly one of m, ratio, breakpoints, mesh (3-D)"},
      {"discretization", true, "the degrees p and p_C"},
      {"data", false,
       "the data: f (scalar model); f_x, f_y, t_x, t_y, friction_coefficient (elastic effects); g (the obstacle, for "
       "elasticity the gap to it along the outward normal: u·n ≤ g); s"},
      {"obstacle", false,
       "a rigid obstacle as geometry, instead of data.g: the gap is computed along Γ_C's outward normal (exact "
       "for the shapes, Newton for an expression)"},
      {"material", false, "the elastic body (effects frictionless, tresca, coulomb)"},
      {"exact", false,
       "a known solution the run compares with (patch tests, manufactured solutions); in a two-body scene each "
       "body's own, the pressure the slave's"},
      {"infsup", false, "the inf-sup constant α (effect infsup, `hpcontact infsup`)"},
      {"solve", false, "the contact solve"},
      {"run", false, "effects and outputs of `hpcontact solve`"},
      {"convergence", false, "the convergence effect"},
      {"adapt", false,
       "hp-adaptivity of T_h and T_{C,H} from the residual error estimator (adapt.target makes a scene adaptive)"}};
  return sections;
}

}  // namespace hpcontact::scene
