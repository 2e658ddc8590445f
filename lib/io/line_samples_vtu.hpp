// Samples along Γ_C (u, the obstacle or bound, λ, … from the boundary tables) as a VTK XML
// UnstructuredGrid of line cells: consecutive samples of one contact zone joined by a VTK_LINE,
// every numeric column as point data. ParaView shows the multiplier beside the VTU of u, and
// meshio reads it (it reads no PolyData).
#pragma once

#include <string>

#include "io/csv_writer.hpp"

namespace hpcontact::io {

/// @param table with numeric columns "x", "y" and "zone"; rows of one zone consecutive and in
///        order along it. Every numeric column but x and y becomes a point array (zone too).
/// @throws std::logic_error if a required column is missing (a programming error).
std::string line_samples_vtu_text(const CsvTable& table);

}  // namespace hpcontact::io
