// ParaView output of u_h: every cell subdivided into k × k bilinear quadrilaterals (k = p_T by
// default), u as point data, written as VTK XML UnstructuredGrid (ASCII).
#pragma once

#include <Eigen/Core>
#include <filesystem>

#include "space/h1_space.hpp"

namespace hpcontact::io {

/// @param subdivisions per cell and direction; 0 means p_T (so u is sampled at p_T + 1 points).
void write_vtu(const std::filesystem::path& path, const space::H1Space& space, const Eigen::VectorXd& u,
               int subdivisions = 0);

}  // namespace hpcontact::io
