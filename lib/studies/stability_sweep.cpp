// Reading, running and fitting stability sweeps.
#include "studies/stability_sweep.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>

#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"
#include "io/atomic_file.hpp"
#include "io/toml_reader.hpp"
#include "mesh/boundary_mesh.hpp"
#include "mesh/contact_boundary.hpp"
#include "driver/scene_discretization.hpp"
#include "scene/scene_mesh.hpp"
#include "studies/sweep_rows.hpp"
#include "norms/h_minus_half_gram.hpp"
#include "operators/primal_operators.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::studies {

namespace {

std::vector<int> to_int(const std::vector<long long>& values) {
  return {values.begin(), values.end()};
}

/// The scene of one point: the level's scene with the sweep's p, p_C (replacing degree rules),
/// ratio (replacing the scene's m, ratio or breakpoints) where the sweep gives them, and the
/// point's pairing and norm.
scene::Scene point_scene(scene::Scene scene, int p, int pc, const std::optional<scene::Ratio>& ratio,
                         infsup::PairingProblem problem = infsup::PairingProblem::signorini,
                         infsup::GramNorm norm = infsup::GramNorm::interpolation) {
  if (p > 0) scene.p = scene::Degree{p, {}};
  if (pc >= 0) scene.pc = scene::Degree{pc, {}};
  if (ratio) {
    scene.ratio = *ratio;
    scene.m = 0;
    scene.breakpoints.clear();
  }
  scene.problem = problem;
  scene.norm = norm;
  return scene;
}

/// The sweep's ratios, or one empty choice: the scene's own contact mesh.
std::vector<std::optional<scene::Ratio>> ratio_choices(const StabilitySweep& sweep) {
  if (sweep.ratios.empty()) return {std::nullopt};
  return {sweep.ratios.begin(), sweep.ratios.end()};
}

/// "level 2 (domain.n_x=24 domain.n_y=24)", for messages and progress.
std::string level_name(const StabilitySweep& sweep, std::size_t level) {
  const auto& label = sweep.levels[level].label;
  return fmt::format("level {}{}", level + 1, label.empty() ? "" : " (" + label + ")");
}

}  // namespace

StabilitySweep read_stability_sweep(const std::string& path) {
  const io::TomlTable root = io::parse_toml_file(path);
  StabilitySweep sweep;
  sweep.file = path;
  const auto table = root.table("sweep", true);
  const std::string base = (std::filesystem::path(path).parent_path() / table.string("scene")).string();
  if (!std::filesystem::is_regular_file(base))
    throw_bad_input(path, "sweep.scene", table.string("scene"), "a scene file, relative to the sweep file (" + base + " does not exist)");
  table.has("set");
  table.has("levels");
  sweep.levels = scene::scene_variants(base, table.table("set"), table.table("levels"), path + ": key 'sweep.levels'");
  if (table.has("p")) sweep.degrees = to_int(table.integer_list("p", 1, 20));
  if (table.has("pC")) sweep.multiplier_degrees = to_int(table.integer_list("pC", 0, 19));
  sweep.pc_below_p = table.choice("pc_rule", {"below_p", "all"}, "below_p") == "below_p";
  for (const auto& r : table.string_list("ratio", std::vector<std::string>{}))
    sweep.ratios.push_back(scene::parse_ratio(r, path, "sweep.ratio"));
  const scene::Scene& first = sweep.levels.front().scene;
  for (const auto& norm : table.string_list("norm", std::vector<std::string>{infsup::to_string(first.norm)}))
    sweep.norms.push_back(infsup::parse_gram_norm(norm, path + ": key 'sweep.norm'"));
  for (const auto& problem : table.string_list("problem", std::vector<std::string>{infsup::to_string(first.problem)}))
    sweep.problems.push_back(infsup::parse_pairing_problem(problem, path + ": key 'sweep.problem'"));
  sweep.fit_levels = static_cast<int>(table.integer("fit_levels", 2, 20, 3));
  sweep.eigensolver = table.choice("eigensolver", {"slepc", "dense"}, "slepc");
  sweep.alpha_tolerance = table.number_in("alpha_tol", 1e-12, 0.1, 1e-4);
  table.reject_unknown_keys();
  if (root.has("reference"))
    throw_bad_input(path, "reference", "(table)",
                    "no longer read: the H^{-1/2} references are refined until alpha_error is below [sweep] alpha_tol");
  root.reject_unknown_keys();

  // Every level's meshes, degrees and data, checked now: a sweep does not stop half-way on input.
  const bool friction = std::find(sweep.problems.begin(), sweep.problems.end(), infsup::PairingProblem::friction) !=
                        sweep.problems.end();
  const auto ratios = ratio_choices(sweep);
  for (std::size_t level = 0; level < sweep.levels.size(); ++level) {
    const scene::Scene& scene = sweep.levels[level].scene;
    try {
      if (friction && scene.friction_bound.empty())
        throw_bad_input(scene.file, "data.s", "(missing)",
                        "the friction pairing (22) of sweep.problem needs the friction bound s");
      const auto mesh = scene::build_scene_mesh(scene);
      const mesh::ContactBoundary contact(mesh);
      StabilitySweep::LevelFacts facts;
      facts.cells = mesh.n_cells();
      facts.contact_edges = static_cast<int>(contact.edges().size());
      const auto nodes = contact.breakpoints();
      facts.contact_h_min = nodes.back() - nodes.front();
      for (std::size_t k = 0; k + 1 < nodes.size(); ++k) facts.contact_h_min = std::min(facts.contact_h_min, nodes[k + 1] - nodes[k]);
      const auto cell_degrees = scene::scene_cell_degrees(scene, mesh);
      facts.scene_p = *std::min_element(cell_degrees.begin(), cell_degrees.end());
      for (const auto& ratio : ratios) {
        const auto at_point = point_scene(scene, 0, -1, ratio);
        std::optional<mesh::BoundaryMesh> built;
        try {
          built.emplace(scene::build_scene_boundary_mesh(at_point, contact));
        } catch (const InputError& error) {
          if (!ratio) throw;
          throw InputError(fmt::format("with sweep.ratio = {}: {}", ratio->text, error.what()));
        }
        const auto& boundary_mesh = *built;
        const auto segment_degrees = scene::scene_segment_degrees(at_point, contact, boundary_mesh);
        facts.segments.push_back(boundary_mesh.n_segments());
        facts.scene_pc.push_back(*std::max_element(segment_degrees.begin(), segment_degrees.end()));
      }
      sweep.level_facts.push_back(std::move(facts));
    } catch (const InputError& error) {
      throw InputError(fmt::format("{}: {} of the scene {}: {}", path, level_name(sweep, level), base, error.what()));
    }
  }
  return sweep;
}

std::vector<std::string> alpha_columns() {
  return {"problem", "norm", "p", "pC", "level", "n", "m", "h", "h_min", "H", "ratio", "Pi", "alpha", "alpha_error",
          "ndofs", "nmult", "seconds"};
}

namespace {

std::vector<std::map<std::string, std::string>> read_csv(const std::filesystem::path& path) {
  std::vector<std::map<std::string, std::string>> rows;
  std::ifstream in(path);
  if (!in) return rows;
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream header_stream(line);
  for (std::string cell; std::getline(header_stream, cell, ',');) header.push_back(cell);
  if (header != alpha_columns())
    throw InputError("'" + path.string() + "' is not an alpha.csv written by hpcontact sweep " +
                     "(other columns, e.g. from an older version): choose another --out folder, or --restart");
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::map<std::string, std::string> row;
    std::stringstream cells(line);
    std::size_t k = 0;
    for (std::string cell; std::getline(cells, cell, ',') && k < header.size(); ++k) row[header[k]] = cell;
    rows.push_back(std::move(row));
  }
  return rows;
}

// Every rank's (index, line) pairs, on rank 0 sorted by index (empty elsewhere).
std::vector<std::pair<int, std::string>> gather_rows_on_rank_zero(const std::vector<std::pair<int, std::string>>& rows) {
  const int rank = mpi_rank_and_size().first, size = mpi_rank_and_size().second;
  std::string packed;
  for (const auto& [index, line] : rows) packed += std::to_string(index) + '\t' + line;  // line ends in '\n'
  int length = static_cast<int>(packed.size());
  std::vector<int> lengths(size), offsets(size, 0);
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::string all;
  if (rank == 0) {
    for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + lengths[r - 1];
    all.resize(static_cast<std::size_t>(offsets[size - 1] + lengths[size - 1]));
  }
  MPI_Gatherv(packed.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0,
              MPI_COMM_WORLD);
  std::vector<std::pair<int, std::string>> out;
  std::stringstream stream(all);
  for (std::string index, line; std::getline(stream, index, '\t') && std::getline(stream, line);)
    out.emplace_back(std::stoi(index), line + '\n');
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

void run_stability_sweep(const StabilitySweep& sweep, const std::filesystem::path& alpha_csv,
                         const std::function<void(int, int, const std::string&)>& progress) {
  // A point: a level, the sweep's p and p_C (0 and -1: the scene's), a ratio index into
  // `ratios` (the scene's contact mesh when the sweep gives none), a problem and a norm.
  const auto ratios = ratio_choices(sweep);
  struct Point {
    std::string problem, norm;  ///< labels in alpha.csv
    infsup::PairingProblem pairing;
    infsup::GramNorm gram;
    std::size_t level, ratio;
    int p, pc;            ///< as given to the scene (0, -1: the scene's own)
    int reported_p, reported_pc;
    long m;
  };
  // Grouped by (level, p): the points of a group share T_h and S^p(T_h), so A_G is factorized
  // once per group. The Gram matrices depend only on T_{C,H}, p_C and the reference, which is
  // one per level (the extension norm's on the level's T_h refined, of degree the sweep's largest
  // p plus extension_extra_degree), so they are kept for the level.
  const std::vector<int> degrees = sweep.degrees.empty() ? std::vector<int>{0} : sweep.degrees;
  const std::vector<int> multiplier_degrees = sweep.multiplier_degrees.empty() ? std::vector<int>{-1} : sweep.multiplier_degrees;
  std::vector<Point> points;
  std::map<std::pair<std::size_t, std::size_t>, std::set<int>> multiplier_degrees_used;  // (level, ratio) → p_C as given
  for (std::size_t level = 0; level < sweep.levels.size(); ++level) {
    const auto& facts = sweep.level_facts[level];
    for (int p : degrees)
      for (const auto& problem : sweep.problems)
        for (const auto& norm : sweep.norms)
          for (int pc : multiplier_degrees)
            for (std::size_t r = 0; r < ratios.size(); ++r) {
              const int reported_p = p > 0 ? p : facts.scene_p, reported_pc = pc >= 0 ? pc : facts.scene_pc[r];
              if (sweep.pc_below_p && reported_pc >= reported_p) continue;
              points.push_back({infsup::to_string(problem), infsup::to_string(norm), problem, norm, level, r, p, pc,
                                reported_p, reported_pc, facts.segments[r]});
              multiplier_degrees_used[{level, r}].insert(pc);
            }
  }
  const auto backend = infsup::parse_eigen_backend(sweep.eigensolver, sweep.file);
  auto key_of = [&](const Point& point) {
    return point_key(point.problem, point.norm, point.reported_p, point.reported_pc, static_cast<int>(point.level) + 1,
                     point.m);
  };
  // Rows stored by an earlier run (alpha.csv and the shards of an interrupted mpirun), validated:
  // bad or foreign rows are computed again. The file is always written in the order of `points`.
  // Plain variables, not a structured binding: lambdas below capture them (clang 14 refuses).
  const int rank = mpi_rank_and_size().first;
  const int size = mpi_rank_and_size().second;
  std::map<std::string, std::size_t> index_of_key;
  for (std::size_t k = 0; k < points.size(); ++k) index_of_key[key_of(points[k])] = k;
  std::set<std::string> keys;
  for (const auto& [key, index] : index_of_key) keys.insert(key);
  std::map<std::string, std::string> stored = read_stored_rows(alpha_csv, keys, rank == 0);
  std::set<std::string> done;
  for (const auto& [key, line] : stored) done.insert(key);
  auto ordered_content = [&] {
    std::vector<std::pair<std::size_t, const std::string*>> lines;
    for (const auto& [key, line] : stored) lines.emplace_back(index_of_key.at(key), &line);
    std::sort(lines.begin(), lines.end());
    std::string content = io::CsvTable(alpha_columns()).to_string();
    for (const auto& [index, line] : lines) content += *line;
    return content;
  };

  // Groups of points sharing (level, p), with what is left to do in each and a cost estimate: the
  // factorizations grow like (dofs)^1.2 (dofs ~ cells p²), each point adds a little. What a level
  // shares (the extension norm's reference, ~ 4 cells (p + 2)² dofs, and the Gram matrices) is
  // built once by every rank that runs a group of the level.
  struct Group { std::size_t first, last; bool todo, extension; double cost; int owner = 0; };
  std::vector<Group> groups;
  std::vector<double> level_shared_cost(sweep.levels.size(), 0.0);
  for (std::size_t first = 0; first < points.size();) {
    Group g{first, first, false, false, 0.0};
    int todo_points = 0;
    while (g.last < points.size() && points[g.last].level == points[first].level && points[g.last].p == points[first].p) {
      if (!done.contains(key_of(points[g.last]))) {
        g.todo = true;
        ++todo_points;
        g.extension = g.extension || points[g.last].gram == infsup::GramNorm::extension;
      }
      ++g.last;
    }
    const std::size_t level = points[first].level;
    const double cells = sweep.level_facts[level].cells, p = points[first].reported_p;
    const double dofs = cells * p * p;
    g.cost = std::pow(dofs, 1.2) + 0.05 * todo_points * dofs;
    if (g.extension) {
      const double largest = sweep.degrees.empty() ? p : *std::max_element(sweep.degrees.begin(), sweep.degrees.end());
      level_shared_cost[level] = std::pow(4.0 * cells * (largest + 2) * (largest + 2), 1.2);
    }
    groups.push_back(g);
    first = g.last;
  }
  // Under mpirun the groups are scheduled on the ranks in two ways, and the one that finishes
  // first by the estimates is taken: whole levels longest first, each to the least loaded rank
  // (no shared work is repeated), or single groups longest first, each to the rank that would
  // finish it first, counting the level's shared work on a rank that has no group of the level
  // yet (balances better when there are fewer levels than ranks). Rank 0 gathers the rows and
  // writes them in the serial order, so the file is the same as a serial run's.
  {
    auto longest_first = [](std::vector<std::size_t> order, auto cost) {
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost(a) > cost(b); });
      return order;
    };
    std::vector<std::size_t> todo;
    std::vector<double> level_cost(sweep.levels.size(), 0.0);
    for (std::size_t i = 0; i < groups.size(); ++i) {
      if (!groups[i].todo) continue;
      todo.push_back(i);
      level_cost[points[groups[i].first].level] += groups[i].cost;
    }
    std::vector<std::size_t> levels;
    for (std::size_t level = 0; level < level_cost.size(); ++level)
      if (level_cost[level] > 0) {
        level_cost[level] += level_shared_cost[level];
        levels.push_back(level);
      }
    // (a) Whole levels.
    std::vector<double> load(size, 0.0);
    std::vector<int> level_owner(sweep.levels.size(), 0);
    for (std::size_t level : longest_first(levels, [&](std::size_t l) { return level_cost[l]; })) {
      level_owner[level] = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
      load[level_owner[level]] += level_cost[level];
    }
    const double by_levels = *std::max_element(load.begin(), load.end());
    // (b) Single groups.
    std::fill(load.begin(), load.end(), 0.0);
    std::vector<int> group_owner(groups.size(), 0);
    std::set<std::pair<int, std::size_t>> has_level;  // (rank, level)
    for (std::size_t i : longest_first(todo, [&](std::size_t g) { return groups[g].cost; })) {
      const std::size_t level = points[groups[i].first].level;
      auto finish = [&](int r) { return load[r] + groups[i].cost + (has_level.contains({r, level}) ? 0.0 : level_shared_cost[level]); };
      int owner = 0;
      for (int r = 1; r < size; ++r)
        if (finish(r) < finish(owner)) owner = r;
      load[owner] = finish(owner);
      has_level.insert({owner, level});
      group_owner[i] = owner;
    }
    const double by_groups = *std::max_element(load.begin(), load.end());
    for (std::size_t i : todo) groups[i].owner = by_levels <= by_groups ? level_owner[points[groups[i].first].level] : group_owner[i];
  }
  std::vector<std::pair<int, std::string>> new_rows;  // (point index, CSV line), parallel runs
  // What the points of the current level share: per (norm, ratio) the Gram ladder of the envelope
  // multiplier space, whose degree on each segment is the largest of the sweep's p_C there: every
  // point's G is a principal submatrix of it (norms::restrict_gram), so one Gram matrix per
  // reference level serves all p_C (and, for the extension norm, one reference at the sweep's
  // largest p serves all p).
  struct EnvelopeGram {
    std::unique_ptr<mesh::BoundaryMesh> boundary;
    std::unique_ptr<space::MultiplierSpace> multipliers;
    std::unique_ptr<norms::GramLadder> ladder;
  };
  struct LevelShared {
    std::size_t level = 0;
    std::map<std::pair<std::string, std::size_t>, EnvelopeGram> grams;
  } shared;
  const int largest_p = sweep.degrees.empty() ? 0 : *std::max_element(sweep.degrees.begin(), sweep.degrees.end());
  int index = 0;
  // A failure on one rank (bad data at a level, a full disk) ends the run on every rank.
  run_on_all_ranks_agreeing([&] {
  for (const Group& g : groups) {
    const std::size_t first = g.first, last = g.last;
    std::string group_lines;
    if (!g.todo || g.owner != rank) {
      index += static_cast<int>(last - first);
      continue;
    }
    const std::size_t level = points[first].level;
    if (level != shared.level) shared = LevelShared{level, {}};  // the last level's are not needed again
    const scene::Scene level_scene = point_scene(sweep.levels[level].scene, points[first].p, -1, std::nullopt);
    const auto mesh = scene::build_scene_mesh(level_scene);
    const mesh::ContactBoundary contact(mesh);
    const std::vector<int> cell_degrees = scene::scene_cell_degrees(level_scene, mesh);
    const operators::PrimalOperators primal(mesh, cell_degrees);
    for (std::size_t k = first; k < last; ++k) {
      const Point& point = points[k];
      ++index;
      const std::string key = key_of(point);
      if (done.contains(key)) continue;
      if (progress)
        progress(index, static_cast<int>(points.size()),
                 fmt::format("{} {} p={} pC={} {}{}", point.problem, point.norm, point.reported_p, point.reported_pc,
                             level_name(sweep, level), ratios[point.ratio] ? " h/H=" + ratios[point.ratio]->text : ""));
      const scene::Scene scene = point_scene(level_scene, 0, point.pc, ratios[point.ratio], point.pairing, point.gram);
      const auto boundary = scene::build_scene_boundary_mesh(scene, contact);
      auto setup = driver::infsup_setup_of(scene, mesh, cell_degrees, boundary, scene::scene_segment_degrees(scene, contact, boundary),
                                   primal);
      setup.alpha_tolerance = sweep.alpha_tolerance;
      auto& envelope = shared.grams[{point.norm, point.ratio}];
      if (!envelope.multipliers) {
        envelope.boundary = std::make_unique<mesh::BoundaryMesh>(boundary);
        std::vector<int> degrees(boundary.n_segments(), 0);
        for (int pc : multiplier_degrees_used[{level, point.ratio}]) {
          const auto at_pc = scene::scene_segment_degrees(point_scene(level_scene, 0, pc, ratios[point.ratio]), contact, boundary);
          for (std::size_t k = 0; k < degrees.size(); ++k) degrees[k] = std::max(degrees[k], at_pc[k]);
        }
        envelope.multipliers = std::make_unique<space::MultiplierSpace>(*envelope.boundary, std::move(degrees));
        envelope.ladder = std::make_unique<norms::GramLadder>(
            setup.norm == infsup::GramNorm::interpolation
                ? norms::interpolation_gram_ladder(*envelope.multipliers)
                : norms::extension_gram_ladder(
                      mesh, scene::scene_cell_degrees(point_scene(level_scene, largest_p, -1, std::nullopt), mesh),
                      *envelope.multipliers));
      }
      const norms::GramLadder grams = norms::restricted_ladder(
          *envelope.ladder, *envelope.multipliers, space::MultiplierSpace(boundary, setup.segment_degrees));
      setup.grams = &grams;
      const auto result = infsup::analyse_infsup(setup, backend);
      const double ratio = ratios[point.ratio] ? ratios[point.ratio]->value
                                               : static_cast<double>(point.m) / sweep.level_facts[level].contact_edges;
      io::CsvTable row(alpha_columns());
      row.add_row({point.problem, point.norm, static_cast<long long>(point.reported_p),
                   static_cast<long long>(point.reported_pc), static_cast<long long>(level + 1),
                   static_cast<long long>(sweep.level_facts[level].contact_edges), static_cast<long long>(point.m),
                   result.h, sweep.level_facts[level].contact_h_min, result.H, ratio, result.pi, result.alpha, result.alpha_error, static_cast<long long>(result.n_primal_dofs),
                   static_cast<long long>(result.n_multiplier_dofs), result.seconds});
      const std::string text = row.to_string();
      const std::string line = text.substr(text.find('\n') + 1);
      stored[key] = line;
      group_lines += line;
      if (size > 1) new_rows.emplace_back(static_cast<int>(index_of_key.at(key)), line);
      done.insert(key);
    }
    // Saved once per group, durably: an interrupted sweep resumes from the last finished (level, p).
    if (size == 1) io::write_file_atomically(alpha_csv, ordered_content());
    else if (!group_lines.empty()) append_durably(shard_path(alpha_csv, rank), group_lines);
  }
  });
  // Every rank's rows into alpha.csv (rank 0), and the shards removed once it is complete.
  run_on_all_ranks_agreeing([&] {
    if (size > 1) {
      for (const auto& [point_index, line] : gather_rows_on_rank_zero(new_rows))
        stored[key_of(points[static_cast<std::size_t>(point_index)])] = line;
    }
    if (rank == 0) {
      io::write_file_atomically(alpha_csv, ordered_content());
      for (const auto& shard : existing_shards(alpha_csv)) std::filesystem::remove(shard);
    }
  });
}

io::CsvTable fit_verdicts(const std::filesystem::path& alpha_csv, int fit_levels) {
  using Key = std::tuple<std::string, std::string, int, int, std::string>;
  std::map<Key, std::vector<std::pair<double, double>>> series;  // (h_min, α)
  std::map<Key, double> ratio_value;
  for (const auto& row : read_csv(alpha_csv)) {
    const double ratio = std::stod(row.at("ratio"));
    const Key key{row.at("problem"), row.at("norm"), std::stoi(row.at("p")), std::stoi(row.at("pC")),
                  fmt::format("{:.6g}", ratio)};
    series[key].emplace_back(std::stod(row.at("h_min")), std::stod(row.at("alpha")));
    ratio_value[key] = ratio;
  }
  io::CsvTable verdicts({"problem", "norm", "p", "pC", "ratio", "rate", "C", "alpha_finest", "verdict"});
  for (auto& [key, points] : series) {
    std::sort(points.begin(), points.end(), [](auto& a, auto& b) { return a.first > b.first; });
    const int count = std::min<int>(fit_levels, static_cast<int>(points.size()));
    const double alpha_finest = points.back().second;
    double rate = NAN, constant = NAN;
    std::string verdict;
    if (alpha_finest <= 1e-6) {
      verdict = "singular";
    } else if (count < 2) {
      verdict = "too_few_levels";
    } else {
      // Least squares for log α = log C + r log h over the finest levels.
      double mean_x = 0, mean_y = 0, sxx = 0, sxy = 0;
      const auto first = points.end() - count;
      for (auto it = first; it != points.end(); ++it) {
        mean_x += std::log(it->first) / count;
        mean_y += std::log(std::max(it->second, 1e-300)) / count;
      }
      for (auto it = first; it != points.end(); ++it) {
        const double dx = std::log(it->first) - mean_x;
        sxx += dx * dx;
        sxy += dx * (std::log(std::max(it->second, 1e-300)) - mean_y);
      }
      if (sxx < 1e-6 * count) {  // log h_min varies by less than 0.1 %: the levels do not refine Γ_C
        verdict = "h_unchanged";
      } else {
        rate = sxy / sxx;
        constant = std::exp(mean_y - rate * mean_x);
        verdict = rate >= 0.3 ? "decaying" : "stable";
      }
    }
    const auto& [problem, norm, p, pc, ratio_text] = key;
    verdicts.add_row({problem, norm, static_cast<long long>(p), static_cast<long long>(pc),
                      ratio_value[key], rate, constant, alpha_finest, verdict});
  }
  return verdicts;
}

}  // namespace hpcontact::studies
