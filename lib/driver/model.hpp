// The model-specific part of a run behind one small interface: the operators of the body on T_h,
// its contact problems, its inf-sup pairing. The scalar model of the paper and the elastic body
// implement it today (scalar_model.hpp, elastic_model.hpp); the run pipeline (scene_run.hpp) knows
// nothing else about them, so a new model (two bodies, 3-D) is one more implementation.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "adapt/residual_estimator.hpp"
#include "core/operator_log.hpp"
#include "driver/run_result.hpp"
#include "driver/scene_discretization.hpp"
#include "infsup/infsup_operators.hpp"
#include "io/csv_writer.hpp"
#include "io/vtu_writer.hpp"
#include "linalg/distribution.hpp"
#include "scene/scene.hpp"

namespace hpcontact::driver {

/// One ParaView file of a solved problem: the solution on one body.
struct SolutionGrid {
  std::string suffix;  ///< after solution_<name>: empty for one body, _<body> for each body of a pair
  std::vector<std::pair<std::string, int>> fields;  ///< the file's point fields
  /// The solution on this rank's cells as the VTU's arrays, built when called: the model that
  /// solved it must still be alive.
  std::function<io::VtuGrid()> grid;
};

/// What the adaptivity reads of a solve (adaptive_run.hpp): η_T² per cell of T_h with the sums of
/// its terms, and θ_T, the smoothness of u_h per cell (adapt/legendre_decay.hpp).
struct AdaptIndicators {
  adapt::ResidualIndicators residual;
  std::vector<double> theta;
};

/// One contact problem solved by a model, with what its outputs need.
struct SolvedProblem {
  ContactResult result;
  /// Its name in the names of files and tables (boundary_<name>.csv, solution_<name>.vtu): the
  /// effect's, or <pair>_<effect> for the contact pair of a two-body scene.
  std::string name;
  io::CsvTable samples;  ///< boundary_<name>.csv: the fields sampled along Γ_C
  /// The multiplier convergence errors are measured on: Legendre coefficients in the
  /// discretization's MultiplierSpace (λ for the scalar model, the pressure for elasticity).
  Eigen::VectorXd error_multiplier;
  std::vector<SolutionGrid> solutions;  ///< one per body
  /// An adaptive scene's (scene.is_adaptive(), serial): the estimator's indicators of this solve.
  std::optional<AdaptIndicators> indicators;
};

class Model {
 public:
  virtual ~Model() = default;
  /// The contact problems the scene asks of this model, in the order they run.
  virtual std::vector<scene::Effect> problems() const = 0;
  /// Solves `problem` (one of problems()) on the model's operators.
  virtual SolvedProblem solve(scene::Effect problem) const = 0;
  /// The scene's inf-sup pairing on the model's operators ([infsup] problem, norm).
  virtual infsup::InfSupSetup infsup_setup() const = 0;
  /// The mesh the operators live on (distributed: the rank's part).
  virtual const mesh::Mesh& operators_mesh() const = 0;
  virtual long long n_dofs() const = 0;
  /// Frees the factorizations (they record their iterations into the log).
  virtual void release_factors() const = 0;
  /// The weight of the norm of multiplier errors of `problem`, as a function of the arc length on
  /// the Γ_C of `finest` (empty: L²).
  virtual std::function<double(double)> multiplier_error_weight(scene::Effect problem,
                                                                const SceneDiscretization& finest) const = 0;
  /// Φ onto the master's Γ_C for a contact pair of two bodies; null for one body.
  virtual const mesh::MasterProjection* master_projection() const { return nullptr; }
  /// What summary.json says of the model beyond the discretization (the material); empty: nothing.
  virtual std::optional<MaterialSummary> material() const { return std::nullopt; }
};

/// The scene's model (elastic if the scene poses an elastic body, else the scalar model) with its
/// operators on `d`, factorized over `distribution`'s ranks; `scene` and `d` must outlive it.
/// Operators built are recorded in `log` if given.
std::unique_ptr<Model> build_model(const scene::Scene& scene, const SceneDiscretization& d, OperatorLog* log,
                                   const linalg::Distribution& distribution);

}  // namespace hpcontact::driver
