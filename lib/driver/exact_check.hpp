// The comparison of an elastic run with its scene's [exact] solution: each body's displacement
// and the contact pressure, as ExactErrors in the run's result.
#pragma once

#include <optional>
#include <vector>

#include "assembly/cell_field.hpp"
#include "contact/elastic_contact.hpp"
#include "driver/run_result.hpp"
#include "linalg/distribution.hpp"
#include "scene/scene.hpp"

namespace hpcontact::driver {

/// One body's displacement and the scene that describes the body.
struct BodyField {
  const scene::Scene* scene = nullptr;
  assembly::CellField u;
  const mesh::Mesh* mesh = nullptr;  ///< the whole mesh u lives on
};

/// The errors against [exact] of `bodies` (the displacement of those whose scene gives exact.u_x,
/// u_y; several bodies: the largest deviation over all relative to the largest exact value) and
/// of `pressure` on the Γ_C of `setup` (exact.pressure of the first body's scene); empty when no
/// scene gives [exact].
/// @throws InputError if [exact] is given in a distributed run (checked serially only).
std::optional<ExactErrors> exact_errors_of(const std::vector<BodyField>& bodies,
                                           const contact::ElasticContactSetup& setup, const Eigen::VectorXd& pressure,
                                           const linalg::Distribution& distribution);

}  // namespace hpcontact::driver
