// legendre_decay: shell energies of u_h in Legendre products on each reference cell.
#include "adapt/legendre_decay.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>

#include "assembly/cell_values.hpp"
#include "basis/lobatto.hpp"

namespace hpcontact::adapt {
namespace {

// e_0 … e_p of component `component` of u_h on cell c: u_h at a rule exact for degree 2p, projected on the Legendre
// products ordered by shell; a weighted QR orthogonalizes them (on the square they are orthogonal already, on the
// triangle they are not).
std::vector<double> shell_energies(const space::H1Space& space, const assembly::CellField& u, int c, int component) {
  const int p = space.cell_degree(c);
  const auto type = space.mesh().cell_type(c);
  const auto rule = assembly::cell_quadrature(type, p + 2);
  const auto values = assembly::tabulate_cell(space, c, rule.points);
  const Eigen::VectorXd u_at = values.values * u.coefficients(c).col(component);
  const bool square = type == mesh::CellType::quadrilateral;
  std::vector<std::pair<int, int>> modes;  // (i, j) by shell
  for (int k = 0; k <= p; ++k)
    for (int i = 0; i <= k; ++i) {
      if (square) {
        modes.push_back({i, k});
        if (i < k) modes.push_back({k, i});
      } else {
        modes.push_back({i, k - i});
      }
    }
  const int n = rule.points.size();
  Eigen::MatrixXd a(n, static_cast<Eigen::Index>(modes.size()));
  Eigen::VectorXd b(n);
  for (int q = 0; q < n; ++q) {
    const double root = std::sqrt(rule.weights[q]);
    const Eigen::VectorXd px = basis::legendre_values(p, rule.points.xi[q]);
    const Eigen::VectorXd py = basis::legendre_values(p, rule.points.eta[q]);
    for (std::size_t m = 0; m < modes.size(); ++m) a(q, m) = root * px[modes[m].first] * py[modes[m].second];
    b[q] = root * u_at[q];
  }
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(a);
  const Eigen::VectorXd coefficients = (qr.householderQ().transpose() * b).head(a.cols());
  std::vector<double> energies(p + 1, 0.0);
  for (std::size_t m = 0; m < modes.size(); ++m) {
    const int shell = square ? std::max(modes[m].first, modes[m].second) : modes[m].first + modes[m].second;
    energies[shell] += coefficients[m] * coefficients[m];
  }
  return energies;
}

// θ of one component on cell c (the header's fit); 0 where it is constant to round-off.
double decay_ratio(const std::vector<double>& e) {
  const int p = static_cast<int>(e.size()) - 1;
  double total = 0.0;
  for (double x : e) total += x;
  // Shells below round-off of the whole carry no information on the decay.
  const double floor = 1e-28 * total;
  std::vector<std::pair<double, double>> points;  // (k, log √e_k)
  for (int k = std::max(1, p - 3); k <= p; ++k) points.push_back({k, 0.5 * std::log(std::max(e[k], floor))});
  if (total <= 0.0 || points.size() < 2) return 0.0;
  double mk = 0.0, ml = 0.0;
  for (const auto& [k, l] : points) mk += k, ml += l;
  mk /= points.size(), ml /= points.size();
  double sxy = 0.0, sxx = 0.0;
  for (const auto& [k, l] : points) sxy += (k - mk) * (l - ml), sxx += (k - mk) * (k - mk);
  return std::min(1.0, std::exp(sxy / sxx));
}

}  // namespace

std::vector<double> legendre_decay(const space::H1Space& space, const assembly::CellField& u) {
  const auto& mesh = space.mesh();
  std::vector<double> theta(mesh.n_cells(), 0.0);
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int k = 0; k < u.components; ++k) theta[c] = std::max(theta[c], decay_ratio(shell_energies(space, u, c, k)));
  return theta;
}

}  // namespace hpcontact::adapt
