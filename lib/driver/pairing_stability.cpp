// The predicted stability of a run's pairing and the nearest stable alternative (pairing_stability.hpp).
#include "driver/pairing_stability.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

#include "core/error.hpp"
#include "core/timer.hpp"
#include "scene/scene_mesh.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::driver {
namespace {

// A candidate change of the scene's T_{C,H} or p_C, with the edit that makes it.
struct Candidate {
  scene::Scene scene;
  std::string edit;
};

// A ratio h/H as a scene writes it: a fraction of small whole numbers where it is one ("1/2"),
// else the number.
std::string ratio_text(double ratio) {
  for (int denominator = 1; denominator <= 64; ++denominator) {
    const double numerator = ratio * denominator;
    if (std::abs(numerator - std::round(numerator)) < 1e-9 * denominator && std::round(numerator) >= 1)
      return denominator == 1 ? fmt::format("{}", std::lround(numerator))
                              : fmt::format("{}/{}", std::lround(numerator), denominator);
  }
  return fmt::format("{:.6g}", ratio);
}

// T_{C,H} with twice the segment length: `ratio` halved or `m` halved (none for breakpoints).
std::optional<Candidate> coarsened(const scene::Scene& scene) {
  Candidate c{scene, ""};
  std::vector<std::string> texts;
  if (!scene.ratio.empty()) {
    for (auto& ratio : c.scene.ratio) {
      ratio.value /= 2;
      ratio.text = ratio_text(ratio.value);
      texts.push_back(fmt::format("\"{}\"", ratio.text));
    }
    c.edit = fmt::format("[contact_mesh] ratio = {}",
                         texts.size() == 1 ? texts.front() : fmt::format("[{}]", fmt::join(texts, ", ")));
    return c;
  }
  if (!scene.m.empty()) {
    for (auto& m : c.scene.m) {
      if (m < 2 || m % 2 != 0) return std::nullopt;  // (an odd m would not be twice as coarse)
      m /= 2;
      texts.push_back(std::to_string(m));
    }
    c.edit = fmt::format("[contact_mesh] m = {}",
                         texts.size() == 1 ? texts.front() : fmt::format("[{}]", fmt::join(texts, ", ")));
    return c;
  }
  return std::nullopt;
}

// Every candidate: p_C lowered (a number p_C only), T_{C,H} coarsened, and both.
std::vector<Candidate> candidates(const scene::Scene& scene) {
  std::vector<Candidate> bases{{scene, ""}};
  if (auto c = coarsened(scene)) bases.push_back(std::move(*c));
  const int lowest = scene.family.kind == space::MultiplierFamilyKind::discontinuous ? 0 : 1;
  std::vector<Candidate> out;
  for (const auto& base : bases) {
    if (!base.edit.empty()) out.push_back(base);
    if (!scene.pc.rule.empty()) continue;
    for (int pc = scene.pc.value - 1; pc >= lowest; --pc) {
      Candidate c = base;
      c.scene.pc = {pc, {}};
      c.edit = (base.edit.empty() ? "" : base.edit + ", ") + fmt::format("[discretization] pC = {}", pc);
      out.push_back(std::move(c));
    }
  }
  return out;
}

// The pairing as the warning names it.
std::string pairing_text(const scene::Scene& scene) {
  std::string mesh = "breakpoints as given";
  if (!scene.ratio.empty()) {
    std::vector<std::string> texts;
    for (const auto& r : scene.ratio) texts.push_back(r.text);
    mesh = "h/H = " + fmt::format("{}", fmt::join(texts, ", "));
  } else if (!scene.m.empty()) {
    mesh = fmt::format("m = {}", fmt::join(scene.m, ", "));
  }
  return fmt::format("p = {}, p_C = {}, {}, family {}", scene.p.label(), scene.pc.label(), mesh,
                     space::to_string(scene.family));
}

// The master's trace edges as Φ maps them onto the slave's arc length: the covered mortar
// segments merged per master edge.
void add_master_traces(infsup::TracePairing& pairing, const scene::Scene& master_scene,
                       const mesh::ContactBoundary& slave, const mesh::MasterProjection& projection) {
  const auto degrees = scene::scene_trace_degrees(master_scene, projection.master());
  int last_edge = -1;
  for (const auto& piece : projection.mortar_segments(slave)) {
    // (a piece shorter than round-off carries nothing, and would repeat a node)
    if (!piece.covered || piece.master_edge < 0 || piece.s_end - piece.s_begin <= 1e-12 * slave.length()) continue;
    if (piece.master_edge == last_edge &&
        std::abs(pairing.master_edges.back()[1] - piece.s_begin) < 1e-12 * slave.length()) {
      pairing.master_edges.back()[1] = piece.s_end;
      continue;
    }
    pairing.master_edges.push_back({piece.s_begin, piece.s_end});
    pairing.master_degrees.push_back(degrees[piece.master_edge]);
    last_edge = piece.master_edge;
  }
}

}  // namespace

infsup::TracePairing trace_pairing_of(const scene::Scene& scene, const mesh::ContactBoundary& contact,
                                      const std::vector<std::array<bool, 2>>& held_zone_ends,
                                      const mesh::BoundaryMesh& boundary_mesh, std::vector<int> segment_degrees,
                                      const mesh::MasterProjection* projection, const std::vector<int>& trace_degrees) {
  infsup::TracePairing pairing;
  pairing.held_zone_ends = held_zone_ends;
  for (const auto& edge : contact.edges()) pairing.edges.push_back({edge.s_begin, edge.s_end});
  pairing.edge_degrees = trace_degrees.empty() ? scene::scene_trace_degrees(scene, contact) : trace_degrees;
  const auto& mesh = contact.mesh();
  for (const auto& edge : contact.edges()) {
    // The cell's extent normal to the edge's chord.
    const auto& ends = mesh.edge(edge.edge);
    const mesh::Point a = mesh.vertex(ends[0]), chord = mesh.vertex(ends[1]) - a;
    const mesh::Point normal = mesh::Point(-chord.y(), chord.x()) / chord.norm();
    double depth = 0.0;
    for (const int v : mesh.cell(edge.cell)) depth = std::max(depth, std::abs((mesh.vertex(v) - a).dot(normal)));
    pairing.edge_depths.push_back(depth);
  }
  pairing.boundary_mesh = &boundary_mesh;
  pairing.segment_degrees = std::move(segment_degrees);
  pairing.family = scene.family;
  if (projection && scene.pair) add_master_traces(pairing, scene.pair->master, contact, *projection);
  // The elastic friction pairing has no weight; the scalar one (22) pairs sμ with v.
  if (!scene.is_elastic() && scene.problem == infsup::PairingProblem::friction)
    if (auto s = scene_function(scene, "data.s", scene.friction_bound))
      pairing.weight = [s, &contact](double arc) { return s(contact.point_at(arc)); };
  return pairing;
}

std::optional<CandidatePrediction> predict_candidate(const scene::Scene& candidate,
                                                     const mesh::ContactBoundary& contact,
                                                     const std::vector<std::array<bool, 2>>& held_zone_ends,
                                                     const mesh::MasterProjection* projection) {
  try {
    const auto bm = scene::build_scene_boundary_mesh(candidate, contact);
    auto degrees = scene::scene_segment_degrees(candidate, contact, bm);
    scene::check_family_fits(candidate, bm, degrees);
    const space::MultiplierSpace multipliers(bm, degrees);
    const long long count = space::multiplier_function_count(multipliers, candidate.family);
    const auto predicted =
        infsup::predict_alpha(trace_pairing_of(candidate, contact, held_zone_ends, bm, std::move(degrees), projection));
    return CandidatePrediction{predicted.alpha, count};
  } catch (const InputError&) {
    return std::nullopt;  // not a discretization of this mesh
  } catch (const NumericalError&) {
    return std::nullopt;  // no prediction: not offered
  }
}

StabilityReport predict_stability(const scene::Scene& scene, const SceneDiscretization& d,
                                  const mesh::MasterProjection* projection) {
  Stopwatch clock;
  scene::check_family_fits(scene, *d.boundary_mesh, d.segment_degrees);  // its message names the scene's keys
  StabilityReport report;
  report.threshold = infsup::kStablePatchAlpha;
  infsup::PredictedAlpha predicted;
  try {
    predicted = infsup::predict_alpha(trace_pairing_of(scene, *d.contact, d.held_zone_ends, *d.boundary_mesh,
                                                       d.segment_degrees, projection, d.trace_degrees));
  } catch (const NumericalError& error) {
    // No prediction is no reason to stop the run: the report says why it is missing.
    report.failure = error.what();
    report.seconds = clock.seconds();
    return report;
  }
  report.alpha_predicted = predicted.alpha;
  report.stable = predicted.stable();
  report.pi = predicted.pi;
  report.patches = predicted.patches;
  report.distinct_patches = predicted.distinct_patches;
  if (predicted.weakest_segment >= 0) {
    const auto& bm = *d.boundary_mesh;
    report.weakest_point = d.contact->point_at(
        0.5 * (bm.segment_begin(predicted.weakest_segment) + bm.segment_end(predicted.weakest_segment)));
  }
  if (!report.stable) {
    for (const auto& candidate : candidates(scene)) {
      const auto predicted = predict_candidate(candidate.scene, *d.contact, d.held_zone_ends, projection);
      if (!predicted || !predicted->stable()) continue;
      const auto& best = report.alternative;
      if (!best || predicted->nmult > best->nmult ||
          (predicted->nmult == best->nmult && predicted->alpha > best->alpha_predicted))
        report.alternative = StableAlternative{candidate.edit, predicted->alpha, predicted->nmult};
    }
    report.warning = fmt::format(
        "the pairing {} is predicted unstable: local α = {:.3g} < {} on the patch around (x, y) = ({:.4g}, {:.4g}) "
        "(Π = {:.3g}): the traces there do not control some multiplier, so λ may oscillate and is not determined "
        "in the limit h → 0. ",
        pairing_text(scene), report.alpha_predicted, report.threshold, report.weakest_point.x(),
        report.weakest_point.y(), report.pi);
    report.warning +=
        report.alternative
            ? fmt::format("Stable alternative: {} (predicted α = {:.3g}, {} multipliers).", report.alternative->edit,
                          report.alternative->alpha_predicted, report.alternative->nmult)
            : std::string(
                  "No stable alternative among p_C lowered and T_{C,H} coarsened by 2: try "
                  "`hpcontact advise`.");
  }
  report.seconds = clock.seconds();
  return report;
}

void act_on_stability(const scene::Scene& scene, StabilityReport& report,
                      const std::function<void(const std::string&)>& say) {
  if (report.stable || scene.stability == scene::Scene::StabilityPolicy::ignore) return;
  if (scene.stability == scene::Scene::StabilityPolicy::refuse)
    throw InputError(
        fmt::format("{}: {} (refused: solve.stability = \"refuse\")", scene.where("solve.stability"), report.warning));
  report.warned = true;
  if (say)
    say("warning: " + report.warning + " (solve.stability = \"ignore\" silences this, \"refuse\" stops the run)");
}

}  // namespace hpcontact::driver
