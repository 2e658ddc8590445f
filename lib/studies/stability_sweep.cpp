// Reading, running and fitting stability sweeps.
#include "studies/stability_sweep.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <tuple>

#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "io/atomic_file.hpp"
#include "io/toml_reader.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "norms/h_minus_half_gram.hpp"
#include "norms/primal_operators.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::studies {

double parse_ratio(const std::string& text, const std::string& where) {
  double value = NAN;
  try {
    std::size_t used = 0;
    const auto slash = text.find('/');
    if (slash == std::string::npos) {
      value = std::stod(text, &used);
      if (used != text.size()) value = NAN;
    } else {
      const double numerator = std::stod(text.substr(0, slash), &used);
      const bool whole_numerator = used == slash;
      const double denominator = std::stod(text.substr(slash + 1), &used);
      value = (whole_numerator && used == text.size() - slash - 1) ? numerator / denominator : NAN;
    }
  } catch (const std::exception&) {
    value = NAN;
  }
  if (!(value > 0.0) || !std::isfinite(value))
    throw_bad_input(where, "ratio", "\"" + text + "\"",
                    "must be a positive number or fraction such as \"2/3\"");
  return value;
}

namespace {

std::vector<int> to_int(const std::vector<long long>& values) {
  return {values.begin(), values.end()};
}

}  // namespace

StabilitySweep read_stability_sweep(const std::string& path) {
  const io::TomlTable root = io::parse_toml_file(path);
  StabilitySweep sweep;
  sweep.file = path;
  const auto table = root.table("sweep", true);
  sweep.degrees = to_int(table.integer_list("p", 1, 20));
  sweep.multiplier_degrees = to_int(table.integer_list("pC", 0, 19));
  sweep.levels = to_int(table.integer_list("n", 2, 4096));
  sweep.pc_below_p = table.choice("pc_rule", {"below_p", "all"}, "below_p") == "below_p";
  sweep.ratios = table.string_list("ratio", std::vector<std::string>{"1"});
  for (const auto& r : sweep.ratios) {
    const double ratio = parse_ratio(r, path + ": key 'sweep.ratio'");
    for (int n : sweep.levels) {
      const double m = n * ratio;
      if (n % 2 != 0 || std::abs(m - std::lround(m)) > 1e-9 * m || std::lround(m) < 1)
        throw_bad_input(path, "sweep.n", std::to_string(n),
                        "must be even and n · ratio a whole number for every ratio (ratio " + r +
                            " gives " + fmt::format("{}", m) + ")");
    }
  }
  sweep.norms = table.string_list("norm", std::vector<std::string>{"interp"});
  for (const auto& norm : sweep.norms) infsup::parse_gram_norm(norm, path + ": key 'sweep.norm'");
  sweep.problems = table.string_list("problem", std::vector<std::string>{"signorini"});
  for (const auto& problem : sweep.problems)
    infsup::parse_pairing_problem(problem, path + ": key 'sweep.problem'");
  sweep.fit_levels = static_cast<int>(table.integer("fit_levels", 2, 20, 3));
  sweep.eigensolver = table.choice("eigensolver", {"slepc", "dense"}, "slepc");
  table.reject_unknown_keys();
  const auto reference = root.table("reference");
  sweep.interpolation_reference.subdivisions =
      static_cast<int>(reference.integer("interp_subdivisions", 1, 64, 2));
  sweep.interpolation_reference.degree = static_cast<int>(reference.integer("interp_degree", 0, 40, 0));
  sweep.extension_reference.refinements =
      static_cast<int>(reference.integer("extension_refinements", 0, 4, 1));
  sweep.extension_reference.extra_degree =
      static_cast<int>(reference.integer("extension_extra_degree", 0, 10, 2));
  reference.reject_unknown_keys();
  root.reject_unknown_keys();
  return sweep;
}

std::vector<std::string> alpha_columns() {
  return {"problem", "norm", "p", "pC", "n", "m", "h", "H", "ratio", "Pi", "alpha", "ndofs",
          "nmult", "seconds"};
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
                     "(other columns): choose another --out folder");
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
  const auto [rank, size] = mpi_rank_and_size();
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

// Identifies a point for resuming: the ratio is compared through m = n · ratio.
std::string point_key(const std::string& problem, const std::string& norm, int p, int pc, int n, long m) {
  return fmt::format("{}/{}/{}/{}/{}/{}", problem, norm, p, pc, n, m);
}

}  // namespace

void run_stability_sweep(const StabilitySweep& sweep, const std::filesystem::path& alpha_csv,
                         const std::function<void(int, int, const std::string&)>& progress) {
  std::set<std::string> done;
  std::map<std::tuple<int, long, int>, Eigen::MatrixXd> interpolation_grams;  // (n, m, p_C) → G
  std::string content = io::CsvTable(alpha_columns()).to_string();
  for (const auto& row : read_csv(alpha_csv)) {
    done.insert(point_key(row.at("problem"), row.at("norm"), std::stoi(row.at("p")),
                          std::stoi(row.at("pC")), std::stoi(row.at("n")), std::stol(row.at("m"))));
  }
  if (std::filesystem::exists(alpha_csv)) {
    std::ifstream in(alpha_csv);
    std::stringstream existing;
    existing << in.rdbuf();
    content = existing.str();
    if (!content.empty() && content.back() != '\n') content += '\n';
  }

  struct Point { std::string problem, norm, ratio; int p, pc, n; };
  // Grouped by (n, p): the points of a group share T_h and S^p(T_h), so A_G (and the extension
  // norm's reference) is factorized once per group; the interpolation-norm Gram matrix depends only
  // on (n, h/H, p_C) and is kept for the level.
  std::vector<Point> points;
  for (int n : sweep.levels)
    for (int p : sweep.degrees)
      for (const auto& problem : sweep.problems)
        for (const auto& norm : sweep.norms)
          for (int pc : sweep.multiplier_degrees) {
            if (sweep.pc_below_p && pc >= p) continue;
            for (const auto& ratio : sweep.ratios) points.push_back({problem, norm, ratio, p, pc, n});
          }
  const auto backend = infsup::parse_eigen_backend(sweep.eigensolver, sweep.file);
  auto key_of = [&](const Point& point) {
    const long m = std::lround(point.n * parse_ratio(point.ratio, sweep.file));
    return point_key(point.problem, infsup::to_string(infsup::parse_gram_norm(point.norm, "")), point.p, point.pc,
                     point.n, m);
  };
  // Groups of points sharing (n, p), with what is left to do in each and a cost estimate: the
  // factorizations grow like (dofs)^1.2 (dofs ~ (n p)², and ~ (2 n (p + 2))² for the extension
  // norm's reference), each point adds a little.
  struct Group { std::size_t first, last; bool todo, extension; double cost; int owner = 0; };
  std::vector<Group> groups;
  for (std::size_t first = 0; first < points.size();) {
    Group g{first, first, false, false, 0.0};
    int todo_points = 0;
    while (g.last < points.size() && points[g.last].n == points[first].n && points[g.last].p == points[first].p) {
      if (!done.contains(key_of(points[g.last]))) {
        g.todo = true;
        ++todo_points;
        g.extension = g.extension || infsup::parse_gram_norm(points[g.last].norm, sweep.file) == infsup::GramNorm::extension;
      }
      ++g.last;
    }
    const double dofs = std::pow(points[first].n * points[first].p, 2.0);
    const double reference = std::pow(2.0 * points[first].n * (points[first].p + 2), 2.0);
    g.cost = std::pow(dofs, 1.2) + (g.extension ? std::pow(reference, 1.2) : 0.0) + 0.05 * todo_points * dofs;
    groups.push_back(g);
    first = g.last;
  }
  // Under mpirun the groups are scheduled on the ranks longest first, each to the least loaded
  // rank (LPT); rank 0 gathers the rows and writes them in the serial order, so the file is the
  // same as a serial run's.
  const auto [rank, size] = mpi_rank_and_size();
  {
    std::vector<std::size_t> order(groups.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return groups[a].cost > groups[b].cost; });
    std::vector<double> load(size, 0.0);
    for (std::size_t i : order) {
      if (!groups[i].todo) continue;
      const int owner = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
      groups[i].owner = owner;
      load[owner] += groups[i].cost;
    }
  }
  std::vector<std::pair<int, std::string>> new_rows;  // (point index, CSV line), parallel runs
  int index = 0;
  for (const Group& g : groups) {
    const std::size_t first = g.first, last = g.last;
    const int n = points[first].n, p = points[first].p;
    const bool any_extension = g.extension;
    if (!g.todo || g.owner != rank) {
      index += static_cast<int>(last - first);
      continue;
    }
    const auto mesh = mesh::make_paper_square_mesh(n);
    const std::vector<int> cell_degrees(mesh.n_cells(), p);
    const norms::PrimalOperators primal(mesh, cell_degrees);
    std::unique_ptr<norms::ExtensionReferenceFactor> extension;
    if (any_extension)
      extension = std::make_unique<norms::ExtensionReferenceFactor>(mesh, cell_degrees, sweep.extension_reference);
    for (std::size_t k = first; k < last; ++k) {
      const Point& point = points[k];
      ++index;
      const std::string key = key_of(point);
      if (done.contains(key)) continue;
      if (progress)
        progress(index, static_cast<int>(points.size()),
                 fmt::format("{} {} p={} pC={} n={} h/H={}", point.problem, point.norm, point.p, point.pc, point.n,
                             point.ratio));
      const double ratio = parse_ratio(point.ratio, sweep.file);
      const long m = std::lround(point.n * ratio);
      const auto boundary = mesh::BoundaryMesh::uniform(2.0, static_cast<int>(m));
      infsup::InfSupSetup setup;
      setup.mesh = &mesh;
      setup.cell_degrees = cell_degrees;
      setup.boundary_mesh = &boundary;
      setup.segment_degrees.assign(m, point.pc);
      setup.norm = infsup::parse_gram_norm(point.norm, sweep.file);
      setup.problem = infsup::parse_pairing_problem(point.problem, sweep.file);
      setup.friction_bound = [](const mesh::Point& x) { return (1.0 - x.x()) * (1.0 - x.x()); };
      setup.interpolation_reference = sweep.interpolation_reference;
      setup.extension_reference = sweep.extension_reference;
      setup.primal = &primal;
      setup.extension = extension.get();
      if (setup.norm == infsup::GramNorm::interpolation) {
        auto& gram = interpolation_grams[{n, m, point.pc}];
        if (gram.size() == 0) {
          const space::MultiplierSpace multipliers(boundary, setup.segment_degrees);
          gram = norms::interpolation_norm_gram(primal.contact(), multipliers, sweep.interpolation_reference);
        }
        setup.gram = &gram;
      }
      const auto result = infsup::analyse_infsup(setup, backend);
      io::CsvTable row(alpha_columns());
      row.add_row({point.problem, infsup::to_string(setup.norm), static_cast<long long>(point.p),
                   static_cast<long long>(point.pc), static_cast<long long>(point.n), static_cast<long long>(m),
                   result.h, result.H, ratio, result.pi, result.alpha, static_cast<long long>(result.n_primal_dofs),
                   static_cast<long long>(result.n_multiplier_dofs), result.seconds});
      const std::string text = row.to_string();
      if (size == 1) content += text.substr(text.find('\n') + 1);
      else new_rows.emplace_back(index, text.substr(text.find('\n') + 1));
      done.insert(key);
    }
    // Saved once per group: an interrupted sweep resumes from the last finished (n, p).
    if (size == 1) io::write_file_atomically(alpha_csv, content);
    // Grams of a finished level are not needed again.
    if (last == points.size() || points[last].n != n) interpolation_grams.clear();
  }
  if (size > 1) {
    const auto all = gather_rows_on_rank_zero(new_rows);
    if (rank == 0) {
      for (const auto& [point_index, line] : all) content += line;
      io::write_file_atomically(alpha_csv, content);
    }
    MPI_Barrier(MPI_COMM_WORLD);  // alpha.csv is complete before any rank goes on
  }
}

io::CsvTable fit_verdicts(const std::filesystem::path& alpha_csv, int fit_levels) {
  using Key = std::tuple<std::string, std::string, int, int, std::string>;
  std::map<Key, std::vector<std::pair<double, double>>> series;  // (h, α)
  std::map<Key, double> ratio_value;
  for (const auto& row : read_csv(alpha_csv)) {
    const double ratio = std::stod(row.at("ratio"));
    const Key key{row.at("problem"), row.at("norm"), std::stoi(row.at("p")), std::stoi(row.at("pC")),
                  fmt::format("{:.6g}", ratio)};
    series[key].emplace_back(std::stod(row.at("h")), std::stod(row.at("alpha")));
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
      rate = sxy / sxx;
      constant = std::exp(mean_y - rate * mean_x);
      verdict = rate >= 0.3 ? "decaying" : "stable";
    }
    const auto& [problem, norm, p, pc, ratio_text] = key;
    verdicts.add_row({problem, norm, static_cast<long long>(p), static_cast<long long>(pc),
                      ratio_value[key], rate, constant, alpha_finest, verdict});
  }
  return verdicts;
}

}  // namespace hpcontact::studies
