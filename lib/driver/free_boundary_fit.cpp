// The free-boundary fitting loop.
#include "driver/free_boundary_fit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "contact/free_boundary.hpp"
#include "core/byte_buffer.hpp"
#include "core/error.hpp"

namespace hpcontact::driver {
namespace {

/// One point per cluster of transitions lying within one segment of T_{C,H} (or `resolution`) of
/// each other: a mesh not yet fitted lets λ flicker between free and held over a few constraint
/// points near the free boundary. An odd cluster is one change of regime (its middle point); an
/// even one is no change (a flicker island) and is dropped.
std::vector<double> cluster_transitions(const std::vector<contact::FreeBoundaryPoint>& points,
                                        const mesh::BoundaryMesh& boundary_mesh, double resolution) {
  auto reach = [&](double s) {
    const int k = boundary_mesh.segment_at(s);
    return std::max(resolution, boundary_mesh.segment_end(k) - boundary_mesh.segment_begin(k));
  };
  std::vector<double> located;
  for (std::size_t begin = 0, end = 0; begin < points.size(); begin = end) {
    end = begin + 1;
    while (end < points.size() &&
           points[end].s - points[end - 1].s <= std::max(reach(points[end - 1].s), reach(points[end].s)))
      ++end;
    if ((end - begin) % 2 == 1) located.push_back(points[(begin + end) / 2].s);
  }
  return located;
}

}  // namespace

FreeBoundaryFit fit_free_boundary(const scene::Scene& scene, const std::vector<contact::ContactProblem>& problems,
                                  double tolerance, int max_solves) {
  FreeBoundaryFit fit{scene, {}, INFINITY, 0};
  std::vector<double> fitted_s;  // arc lengths of fit.points, which the current mesh is graded towards
  while (fit.solves < max_solves) {
    // Solve k of the fit grades no deeper than k layers: cells much smaller than the distance to
    // the free boundary leave λ's point values there undetermined (only its H^{-1/2} norm is
    // controlled), and their flicker would be taken for the free boundary.
    fit.scene.grading_layers = std::min(scene.grading_layers, fit.solves + 1);
    // One discretization per round, its operators (factor(K), F) shared by the problems.
    const auto d = discretize_scene(fit.scene);
    const operators::PrimalOperators primal(*d->mesh, d->cell_degrees);
    const auto& contact = *d->contact;
    // Transitions within a coarse cell of a given grading point are left to its layers: they could
    // not be grading points of their own, and they arise where the data make λ undetermined (for
    // (13) at x = 1 of §7, where s vanishes).
    const double coarse_cell = d->mesh->longest_edge();
    std::vector<double> located;
    for (const auto problem : problems) {
      const auto solution = contact::solve_contact(contact_setup_of(fit.scene, *d, problem, primal));
      for (double s : cluster_transitions(contact::locate_free_boundary(solution), *d->boundary_mesh,
                                          tolerance * contact.length()))
        if (std::none_of(scene.grading_points.begin(), scene.grading_points.end(),
                         [&](const mesh::Point& given) { return (given - contact.point_at(s)).norm() < coarse_cell; }))
          located.push_back(s);
    }
    ++fit.solves;
    // Points within one coarse cell of each other are one, at their mean: they could not both be
    // grading points, and those of different problems converge to one point where the problems
    // share their exact solution ((13) and (15)).
    std::sort(located.begin(), located.end());
    std::vector<double> merged;
    for (std::size_t begin = 0, end = 0; begin < located.size(); begin = end) {
      for (end = begin + 1; end < located.size() && located[end] - located[end - 1] < coarse_cell;) ++end;
      merged.push_back(std::accumulate(located.begin() + begin, located.begin() + end, 0.0) / (end - begin));
    }
    located = merged;
    if (located.size() == fitted_s.size()) {
      fit.moved = 0.0;
      for (std::size_t k = 0; k < located.size(); ++k)
        fit.moved = std::max(fit.moved, std::abs(located[k] - fitted_s[k]));
      if (fit.moved <= tolerance * contact.length()) {
        fit.scene.grading_layers = scene.grading_layers;
        return fit;
      }
    }
    fitted_s = located;
    fit.points.clear();
    for (double s : located) fit.points.push_back(contact.point_at(s));
    fit.scene.grading_points = scene.grading_points;
    fit.scene.grading_points.insert(fit.scene.grading_points.end(), fit.points.begin(), fit.points.end());
  }
  throw NumericalError(
      fmt::format("{}: the free boundary did not settle in {} solves (last move {:.3g} in arc length, "
                  "tolerance {:.3g} · |Γ_C|); more grading layers or a higher degree resolve it better",
                  scene.file, max_solves, fit.moved, tolerance));
}

FreeBoundaryFit fit_free_boundary_once(const scene::Scene& scene, const std::vector<contact::ContactProblem>& problems,
                                       MPI_Comm ranks) {
  std::optional<FreeBoundaryFit> fit;
  const auto bytes = bytes_made_by_first_rank(
      [&] {
        fit.emplace(fit_free_boundary(scene, problems));
        // (the grading points and layers, all the fit changes of the scene, sent as they are
        // rather than rebuilt from the points)
        ByteWriter out;
        mesh::put_points(out, fit->points), mesh::put_points(out, fit->scene.grading_points);
        out.put(fit->scene.grading_layers), out.put(fit->moved), out.put(fit->solves);
        return out.take();
      },
      ranks);
  if (fit) return std::move(*fit);
  ByteReader in(bytes);
  FreeBoundaryFit received{scene, mesh::get_points(in), 0.0, 0};
  received.scene.grading_points = mesh::get_points(in);
  received.scene.grading_layers = in.get<int>();
  received.moved = in.get<double>(), received.solves = in.get<int>();
  HPC_VERIFY(in.at_end(), "bytes of a free-boundary fit left over");
  return received;
}

}  // namespace hpcontact::driver
