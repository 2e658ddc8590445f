// A sweep's output folder: taken for one run at a time (the lock), and its identity, the keys that
// decide its rows (every level's scene, the contents of its mesh files, and the sweep's lists,
// rule, norms, problems, families, eigensolver and tolerance), stored beside alpha.csv so that
// rows are resumed or merged only into the study that computed them.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "studies/stability_sweep.hpp"
#include "studies/sweep_rows.hpp"

namespace hpcontact::studies {

/// The file in a sweep's folder that holds its identity.
std::filesystem::path identity_path(const std::filesystem::path& folder);

/// The identity of `sweep`: one "key = value" line each, e.g. "level 1: domain.n_x = 12",
/// "sweep.p = 1 2 3". The verdicts' fit (fit_levels) is not part of it: it changes no row.
std::vector<std::string> sweep_identity(const StabilitySweep& sweep);

/// Claims `folder` for the study of `identity` before a run adds rows to it: a folder without rows
/// gets the identity file; a folder whose stored identity equals `identity` is resumed. Otherwise
/// InputError (exit 2) naming the folder and up to five keys that differ with both values (or,
/// for rows without an identity file, saying so), with the way out: another --out folder, or
/// --restart. `merge_source`: the folder is a slice given to --merge (it is only read).
void claim_sweep_folder(const std::filesystem::path& folder, const std::vector<std::string>& identity,
                        bool merge_source = false);

/// Writes `identity` into `folder` (replacing the one stored), e.g. after a merge.
void write_sweep_identity(const std::filesystem::path& folder, const std::vector<std::string>& identity);

/// Takes `folder` for a run of `sweep` (serial: the calling process alone): makes it (InputError
/// naming `option` if it cannot be a writable folder), locks it for the life of the returned lock,
/// with `restart` removes its rows and identity, then claims it (claim_sweep_folder).
std::unique_ptr<FolderLock> open_sweep_folder(const StabilitySweep& sweep, const std::filesystem::path& folder,
                                              bool restart);

}  // namespace hpcontact::studies
