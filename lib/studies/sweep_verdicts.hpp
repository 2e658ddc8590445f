// Verdicts of a stability sweep from the rows of its alpha.csv.
#pragma once

#include <vector>

#include "infsup/infsup_record.hpp"
#include "io/csv_writer.hpp"

namespace hpcontact::studies {

/// Fits α ≈ C h_min^r over the `fit_levels` finest levels of each configuration among `rows`
/// (h_min, the shortest edge on Γ_C, is h on uniform meshes and the size of the finest layer on
/// graded ones, where checkerboard modes live) and returns verdicts.csv:
/// problem,norm,p,pC,family,ratio,rate,C,alpha_finest,verdict with verdict
///   singular        α_finest ≤ 1e-6 (α² ≤ 1e-12 λ_max, λ_max ≤ 1 here: zero to working precision)
///   decaying        r ≥ 0.3 (α → 0 like h_min^r)
///   stable          otherwise (α bounded below)
///   too_few_levels  one level only
///   h_unchanged     the levels do not refine Γ_C (no rate can be fitted)
/// Configurations come in the order of their labels, each level's rows in the order given.
io::CsvTable fit_verdicts(const std::vector<infsup::InfSupRecord>& rows, int fit_levels);

}  // namespace hpcontact::studies
