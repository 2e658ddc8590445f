// The eigenvector of α (the spurious mode when α is small) sampled along Γ_C, for mode.csv.
#pragma once

#include <Eigen/Core>

#include "io/csv_writer.hpp"
#include "mesh/contact_boundary.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::postprocess {

/// The mode sampled at `samples_per_segment` equidistant points of every segment (both ends
/// included, so jumps show): columns x, mu, y, s (x, y physical, s arc length along Γ_C), and
/// mu_t when the mode has two parts (the elastic friction pairing: normal, then tangential).
io::CsvTable sample_mode(const mesh::ContactBoundary& contact, const space::MultiplierSpace& multipliers,
                         const Eigen::VectorXd& mode, int samples_per_segment = 20);

}  // namespace hpcontact::postprocess
