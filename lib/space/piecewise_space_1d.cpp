// Continuous piecewise Lobatto polynomials on a partition of an interval (piecewise_space_1d.hpp).
#include "space/piecewise_space_1d.hpp"

#include <algorithm>

#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"

namespace hpcontact::space {

PiecewiseSpace1D::PiecewiseSpace1D(std::vector<double> nodes, std::vector<int> degrees, bool keep_left, bool keep_right)
    : nodes_(std::move(nodes)), degrees_(std::move(degrees)) {
  HPC_VERIFY(nodes_.size() >= 2 && degrees_.size() + 1 == nodes_.size(), "a partition and one degree per piece");
  HPC_VERIFY(std::adjacent_find(nodes_.begin(), nodes_.end(), std::greater_equal<>()) == nodes_.end(),
             "increasing nodes");
  HPC_VERIFY(*std::min_element(degrees_.begin(), degrees_.end()) >= 1, "degrees of at least 1");
  vertex_dof_.assign(nodes_.size(), -1);
  for (std::size_t v = 0; v < nodes_.size(); ++v) {
    const bool kept = (v > 0 || keep_left) && (v + 1 < nodes_.size() || keep_right);
    if (kept) vertex_dof_[v] = n_dofs_++;
  }
  for (const int p : degrees_) {
    first_bubble_.push_back(n_dofs_);
    n_dofs_ += p - 1;
  }
}

int PiecewiseSpace1D::piece_at(double s) const {
  if (s < nodes_.front() || s > nodes_.back()) return -1;
  const auto it = std::lower_bound(nodes_.begin() + 1, nodes_.end() - 1, s);
  return static_cast<int>(it - nodes_.begin()) - 1;
}

PiecewiseSpace1D::PieceValues PiecewiseSpace1D::values_on(int piece, double t) const {
  const int p = degrees_[piece];
  Eigen::VectorXd n(p + 1), dn(p + 1);
  basis::lobatto_values(p, t, n, dn);
  const double dt_ds = 2.0 / (nodes_[piece + 1] - nodes_[piece]);
  PieceValues out;
  std::vector<double> values, derivatives;
  const auto add = [&](int dof, int shape) {
    if (dof < 0) return;
    out.dofs.push_back(dof);
    values.push_back(n[shape]);
    derivatives.push_back(dn[shape] * dt_ds);
  };
  add(vertex_dof_[piece], 0);
  add(vertex_dof_[piece + 1], 1);
  for (int k = 2; k <= p; ++k) add(first_bubble_[piece] + k - 2, k);
  out.values = Eigen::Map<Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
  out.derivatives = Eigen::Map<Eigen::VectorXd>(derivatives.data(), static_cast<Eigen::Index>(derivatives.size()));
  return out;
}

namespace {

// ∫ over the pieces of (f_i f_j) with f the values (derivatives = false) or the derivatives.
Eigen::MatrixXd gram(const PiecewiseSpace1D& space, bool derivatives) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(space.n_dofs(), space.n_dofs());
  for (int piece = 0; piece < space.n_pieces(); ++piece) {
    const auto& rule = basis::gauss_legendre(space.degree(piece) + 1);
    const double half = 0.5 * (space.nodes()[piece + 1] - space.nodes()[piece]);
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const auto v = space.values_on(piece, rule.points[q]);
      const Eigen::VectorXd& f = derivatives ? v.derivatives : v.values;
      for (std::size_t i = 0; i < v.dofs.size(); ++i)
        for (std::size_t j = 0; j < v.dofs.size(); ++j)
          out(v.dofs[i], v.dofs[j]) +=
              rule.weights[q] * half * f[static_cast<Eigen::Index>(i)] * f[static_cast<Eigen::Index>(j)];
    }
  }
  return out;
}

}  // namespace

Eigen::MatrixXd PiecewiseSpace1D::mass() const { return gram(*this, false); }
Eigen::MatrixXd PiecewiseSpace1D::stiffness() const { return gram(*this, true); }

}  // namespace hpcontact::space
