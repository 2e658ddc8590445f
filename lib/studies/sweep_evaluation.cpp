// SweepEvaluation: a point's α on its group's T_h and operators, with the Gram ladders of the
// envelope multiplier space that every point of a share restricts.
#include "studies/sweep_evaluation.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/rank_agreement.hpp"
#include "driver/elastic_scene.hpp"
#include "driver/pairing_stability.hpp"
#include "driver/scene_discretization.hpp"
#include "driver/solid_pairing.hpp"
#include "infsup/solid_infsup.hpp"
#include "mesh/boundary_mesh.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/contact_pair_geometry.hpp"
#include "norms/h_minus_half_gram.hpp"
#include "operators/elastic_operators.hpp"
#include "operators/primal_operators.hpp"
#include "scene/scene_mesh.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::studies {

// T_h of one group (level, p) and its operators, shared by the group's points. Distributed, a
// planar T_h and its degrees are on the group's first rank only (the operators and the extension
// norm's references send the others their parts), Γ_C on every rank; a 3-D box is on every rank.
class SweepEvaluation::Group {
 public:
  Group(const scene::Scene& level_scene, std::size_t group_share, linalg::Distribution distribution)
      : scene(level_scene), share(group_share) {
    if (scene.dimension() == 3) {
      build_solid(distribution);
      return;
    }
    built = driver::build_scene_mesh_on_first_rank(scene, distribution);
    contact.emplace(*built.contact_cells);
    if (scene.is_elastic())
      elastic = driver::scene_elastic_operators(scene, built.mesh.get(), built.cell_degrees, nullptr, distribution);
    else
      primal =
          std::make_unique<operators::PrimalOperators>(built.mesh.get(), built.cell_degrees, nullptr, distribution);
    if (scene.pair) build_master(distribution);
  }
  scene::Scene scene;
  std::size_t share;
  driver::SceneMesh built;
  std::optional<mesh::ContactBoundary> contact;  ///< planar levels
  /// The operators of the scalar model, or of an elastic scene (its α pairs [S^p(T_h)]² with the
  /// normal and tangential multipliers): one of the two, each split over the group's ranks once.
  std::unique_ptr<operators::PrimalOperators> primal;
  std::unique_ptr<operators::ElasticOperators> elastic;
  /// A contact pair: the master body's mesh, operators and Φ onto its Γ_C.
  driver::SceneMesh master_built;
  std::unique_ptr<operators::ElasticOperators> master;
  std::unique_ptr<mesh::MasterProjection> projection;
  /// A 3-D level: the box, Γ_C and the space, and A_G with Γ_C's trace last (every point's p_C and
  /// T_{C,H} share it).
  std::unique_ptr<driver::SolidDiscretization> solid;
  std::unique_ptr<assembly::CondensedFactor> solid_gram;

 private:
  // (a group of ranks: each holds the box, A_G is factorized over them, and all compute every point)
  void build_solid(linalg::Distribution distribution) {
    solid = driver::discretize_solid_scene(scene, false);  // (each point builds its T_{C,H})
    solid_gram = std::make_unique<assembly::CondensedFactor>(
        solid->vector_space ? infsup::solid_gram_factor(*solid->vector_space, *solid->surface, true, distribution)
                            : infsup::solid_gram_factor(*solid->space, *solid->surface, true, distribution));
  }

  void build_master(linalg::Distribution distribution) {
    if (distribution.distributed())
      throw InputError(scene.file +
                       ": α of a two-body pair is swept serially for now; run the sweep without "
                       "mpirun (or with one rank per group)");
    master_built = driver::build_scene_mesh_on_first_rank(scene.pair->master, distribution);
    master = driver::scene_elastic_operators(scene.pair->master, master_built.mesh.get(), master_built.cell_degrees);
    projection = std::make_unique<mesh::MasterProjection>(master->contact());
  }
};

// Per (norm, ratio) of a share (a level, or a (level, ratio): SweepGroup::share) the Gram ladder of
// the envelope multiplier space, whose degree on each segment is the largest of the sweep's p_C
// there: every point's G is a principal submatrix of it (norms::restrict_gram), so one Gram matrix
// per reference level serves all p_C (and, for the extension norm, one reference at the sweep's
// largest p serves all p).
struct SweepEvaluation::EnvelopeGram {
  std::unique_ptr<mesh::BoundaryMesh> boundary;
  std::unique_ptr<space::MultiplierSpace> multipliers;
  std::unique_ptr<norms::GramLadder> ladder;
};
struct SweepEvaluation::ShareGrams {
  std::map<std::pair<infsup::GramNorm, std::size_t>, EnvelopeGram> envelopes;
};

namespace {

/// The scene's degrees on `mesh` where it is (distributed: the first rank), a failure raised on
/// every rank alike; empty elsewhere.
std::vector<int> cell_degrees_on_first_rank(const scene::Scene& scene, const mesh::Mesh* mesh,
                                            linalg::Distribution distribution) {
  std::vector<int> degrees;
  const auto evaluate = [&] {
    if (mesh) degrees = scene::scene_cell_degrees(scene, *mesh);
  };
  if (distribution.distributed())
    run_on_all_ranks_agreeing(evaluate, distribution.ranks);
  else
    evaluate();
  return degrees;
}

}  // namespace

SweepEvaluation::SweepEvaluation(const StabilitySweep& sweep, const std::vector<SweepPoint>& points,
                                 linalg::Distribution distribution)
    : sweep_(sweep),
      points_(points),
      ratios_(ratio_choices(sweep)),
      degrees_used_(multiplier_degrees_used(points)),
      backend_(infsup::parse_eigen_backend(sweep.eigensolver, sweep.file)),
      largest_p_(sweep.degrees.empty() ? std::nullopt
                                       : std::optional(*std::max_element(sweep.degrees.begin(), sweep.degrees.end()))),
      distribution_(distribution) {}

SweepEvaluation::~SweepEvaluation() = default;

std::shared_ptr<const SweepEvaluation::Group> SweepEvaluation::start_group(const SweepGroup& group) const {
  return std::make_shared<const Group>(point_scene(sweep_.levels[group.level].scene, {.p = points_[group.first].p}),
                                       group.share, distribution_);
}

void SweepEvaluation::release_share(std::size_t share) { grams_of_share_.erase(share); }

/// The envelope Gram ladder of the point's (norm, ratio) on its share, built on first use.
const SweepEvaluation::EnvelopeGram& SweepEvaluation::envelope_of(const SweepPoint& point, const Group& group,
                                                                  const mesh::BoundaryMesh& boundary) {
  auto& grams = grams_of_share_[group.share];
  if (!grams) grams = std::make_unique<ShareGrams>();
  auto& envelope = grams->envelopes[{point.gram, point.ratio}];
  if (envelope.multipliers) return envelope;
  const scene::Scene& level_scene = sweep_.levels[point.level].scene;
  envelope.boundary = std::make_unique<mesh::BoundaryMesh>(boundary);
  std::vector<int> degrees(boundary.n_segments(), 0);
  for (const auto pc : degrees_used_.at({point.level, point.ratio})) {
    const auto at_pc = scene::scene_segment_degrees(point_scene(level_scene, {.pc = pc, .ratio = ratios_[point.ratio]}),
                                                    *group.contact, boundary);
    for (std::size_t k = 0; k < degrees.size(); ++k) degrees[k] = std::max(degrees[k], at_pc[k]);
  }
  envelope.multipliers = std::make_unique<space::MultiplierSpace>(*envelope.boundary, std::move(degrees));
  envelope.ladder = std::make_unique<norms::GramLadder>(
      point.gram == infsup::GramNorm::interpolation
          ? norms::interpolation_gram_ladder(*envelope.multipliers)
          : norms::extension_gram_ladder(group.built.mesh.get(),
                                         cell_degrees_on_first_rank(point_scene(level_scene, {.p = largest_p_}),
                                                                    group.built.mesh.get(), distribution_),
                                         *envelope.multipliers, distribution_));
  return envelope;
}

infsup::InfSupRecord SweepEvaluation::evaluate_point(const SweepPoint& point, const Group& group) {
  const auto& ratio = ratios_[point.ratio];
  if (group.solid) {
    scene::Scene scene = point_scene(
        group.scene,
        {.pc = point.pc, .ratio = ratio, .problem = point.pairing, .norm = point.gram, .family = point.family});
    scene.alpha_tolerance = sweep_.alpha_tolerance;
    return driver::solid_scene_alpha(scene, *group.solid, backend_, group.solid_gram.get(),
                                     static_cast<int>(point.level) + 1)
        .summary.record;
  }
  const scene::Scene scene = point_scene(
      group.scene,
      {.pc = point.pc, .ratio = ratio, .problem = point.pairing, .norm = point.gram, .family = point.family});
  const auto boundary = scene::build_scene_boundary_mesh(scene, *group.contact);
  auto segment_degrees = scene::scene_segment_degrees(scene, *group.contact, boundary);
  auto setup = group.elastic ? driver::infsup_setup_of(scene, group.built.mesh.get(), group.built.cell_degrees,
                                                       boundary, std::move(segment_degrees), *group.elastic)
                             : driver::infsup_setup_of(scene, group.built.mesh.get(), group.built.cell_degrees,
                                                       boundary, std::move(segment_degrees), *group.primal);
  setup.alpha_tolerance = sweep_.alpha_tolerance;
  setup.master = group.master.get();
  setup.projection = group.projection.get();
  const auto& envelope = envelope_of(point, group, boundary);
  const norms::GramLadder ladder = norms::restricted_ladder(*envelope.ladder, *envelope.multipliers,
                                                            space::MultiplierSpace(boundary, setup.segment_degrees));
  setup.grams = &ladder;
  const auto& facts = sweep_.level_facts[point.level];
  const infsup::PairingFacts pairing{.problem = point.pairing,
                                     .norm = point.gram,
                                     .family = point.family,
                                     .p = point.reported_p,
                                     .pc = point.reported_pc,
                                     .level = static_cast<int>(point.level) + 1,
                                     .n = facts.contact_edges,
                                     .m = static_cast<int>(point.m),
                                     .h_min = facts.contact_h_min,
                                     .ratio = ratio ? std::optional<double>(ratio->value) : std::nullopt};
  auto record = infsup::make_infsup_record(pairing, infsup::analyse_infsup(setup, backend_));
  record.alpha_predicted =
      infsup::predict_alpha(driver::trace_pairing_of(scene, *group.contact, group.built.held_zone_ends, boundary,
                                                     setup.segment_degrees, group.projection.get()))
          .alpha;
  return record;
}

}  // namespace hpcontact::studies
