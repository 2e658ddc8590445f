// The α record as a CSV row: the one schema of `hpcontact infsup --csv` and of a stability sweep's
// alpha.csv, written, and read back when a sweep resumes or merges its slices.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "infsup/infsup_record.hpp"
#include "io/csv_writer.hpp"

namespace hpcontact::io {

/// The columns, one row per α (infsup::InfSupRecord):
///   problem, norm    signorini | friction (condition (11) or (22)); interp | extension (H^{-1/2})
///   p, pC            degrees; for degree rules the smallest p_T and the largest p_C (as in Π)
///   level            the sweep's level, counted from 1 (1 for `hpcontact infsup`)
///   n, m             edges of T_h on Γ_C, segments of T_{C,H}
///   h, h_min, H      longest edge of T_h, shortest edge of T_h on Γ_C, longest segment of T_{C,H}
///   ratio            h/H as given (scene or sweep), otherwise m / n
///   Pi               Π(h, H, p, p_C) of (20)
///   alpha            α, ≥ 0 (0 where S_G is singular to working precision)
///   alpha_predicted  the local predictor's α of the same pairing (infsup/local_alpha.hpp)
///   alpha_error      the estimate of |α − α_∞| from the H^{-1/2} reference
///   ndofs, nmult     unknowns of the primal and the multiplier space
///   seconds          operators and eigenproblem: the one column that differs between runs
/// (the record's alpha_converged is not a column).
std::vector<std::string> alpha_columns();

/// Adds `record` as a row of `table`, whose columns are alpha_columns().
void add_alpha_row(CsvTable& table, const infsup::InfSupRecord& record);

/// The record of one row of such a table (a line without its newline), or none unless it has
/// every column, its labels are known and every number parses completely (integers whole).
std::optional<infsup::InfSupRecord> read_alpha_row(const std::string& line);

}  // namespace hpcontact::io
