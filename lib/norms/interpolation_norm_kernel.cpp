// interpolation_norm_gram_kernel: image sums of K₀, Chebyshev fits of their smooth parts, and
// graded Gauss quadrature of segment pairs.
#include "norms/interpolation_norm_kernel.hpp"

#include <gsl/gsl_sf_bessel.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "basis/quadrature.hpp"
#include "core/error.hpp"

namespace hpcontact::norms {
namespace {

// K₀(x) < 1e-19 beyond this distance, below round-off of the O(1) values near the diagonal; GSL
// would also report underflow (and abort through its default handler) far beyond it.
constexpr double kNegligibleDistance = 42.0;

double bessel_k0(double x) { return x >= kNegligibleDistance ? 0.0 : gsl_sf_bessel_K0(x); }

// The periodic images are summed with K₀ cut off only where it underflows (K₀(690) ≈ 1e-301,
// GSL's K₀ underflows near 705): a cut-off at kNegligibleDistance would leave a step of 1e-19 in
// the image sums, which on a long Γ_C (L = 8: sums of size 1e-8) their Chebyshev fits cannot
// resolve. The sums are then smooth, and negligible where all of them lie below kNegligibleValue.
constexpr double kImageDistance = 690.0;
constexpr double kNegligibleValue = 1e-19;  // ≈ K₀(kNegligibleDistance)

double bessel_k0_image(double x) { return x >= kImageDistance ? 0.0 : gsl_sf_bessel_K0(x); }

// A Chebyshev interpolant of an analytic function on [lo, hi], degree doubled until the trailing
// coefficients are at round-off of the largest. The values carry GSL's relative error (a few ε),
// so the trailing coefficients settle near 2e-15 of the largest and no lower (measured: 2.5e-15
// on Γ_C of length 20 at every n up to 8192): 1e-14 of the image sums, themselves at most
// K₀(L) against the O(1) singular part of the kernel, is far below the kernel's round-off.
class ChebyshevFit {
 public:
  ChebyshevFit(const std::function<double(double)>& f, double lo, double hi) : lo_(lo), hi_(hi) {
    for (int n = 16;; n *= 2) {
      std::vector<double> values(n);
      for (int k = 0; k < n; ++k) values[k] = f(map(std::cos(std::numbers::pi * (k + 0.5) / n)));
      coefficients_.assign(n, 0.0);
      for (int j = 0; j < n; ++j) {
        double sum = 0.0;
        for (int k = 0; k < n; ++k) sum += values[k] * std::cos(std::numbers::pi * j * (k + 0.5) / n);
        coefficients_[j] = (j == 0 ? 1.0 : 2.0) * sum / n;
      }
      double largest = 0.0, tail = 0.0;
      for (int j = 0; j < n; ++j) largest = std::max(largest, std::abs(coefficients_[j]));
      for (int j = n - 4; j < n; ++j) tail = std::max(tail, std::abs(coefficients_[j]));
      if (tail <= 1e-14 * largest || largest == 0.0) break;
      HPC_VERIFY(n < 8192, "interpolation norm: the image sum of the kernel is not resolved by 8192 Chebyshev terms");
    }
    while (!coefficients_.empty() && std::abs(coefficients_.back()) <= 1e-18 * std::abs(coefficients_.front()))
      coefficients_.pop_back();
  }
  /// A bound of |f| on [lo, hi]: Σ |c_j|.
  double max_abs() const {
    double sum = 0.0;
    for (double c : coefficients_) sum += std::abs(c);
    return sum;
  }
  double operator()(double x) const {  // Clenshaw
    const double t = (2.0 * x - lo_ - hi_) / (hi_ - lo_);
    double b1 = 0.0, b2 = 0.0;
    for (int j = static_cast<int>(coefficients_.size()) - 1; j >= 1; --j) {
      const double b0 = 2.0 * t * b1 - b2 + coefficients_[j];
      b2 = b1;
      b1 = b0;
    }
    return coefficients_.empty() ? 0.0 : t * b1 - b2 + coefficients_[0];
  }

 private:
  double map(double t) const { return 0.5 * (lo_ + hi_) + 0.5 * (hi_ - lo_) * t; }
  double lo_, hi_;
  std::vector<double> coefficients_;
};

// k₋ (of x = s − t) or k₊ (of y = s + t) of the header.
struct Kernel {
  bool sum = false;  ///< k₊
  double length = 0.0;
  ChebyshevFit images;
  std::vector<double> singular_points;

  double operator()(double x) const {
    const double singular = sum ? bessel_k0(x) + bessel_k0(2.0 * length - x) : bessel_k0(std::abs(x));
    return singular + images(x);
  }
  /// Whether the kernel vanishes to round-off on [lo, hi].
  bool negligible_on(double lo, double hi) const {
    if (images.max_abs() > kNegligibleValue) return false;
    return std::all_of(singular_points.begin(), singular_points.end(), [&](double z) {
      return std::max({lo - z, z - hi, 0.0}) >= kNegligibleDistance;
    });
  }
};

Kernel difference_kernel(double length) {
  auto images = [length](double x) {
    double sum = 0.0;
    for (int j = 1; (2 * j - 1) * length < kImageDistance; ++j)
      sum += bessel_k0_image(x + 2 * j * length) + bessel_k0_image(2 * j * length - x);
    return sum;
  };
  return {false, length, ChebyshevFit(images, -length, length), {0.0}};
}

Kernel sum_kernel(double length) {
  auto images = [length](double y) {
    double sum = 0.0;
    for (int j = 1; 2 * j * length - 2 * length < kImageDistance; ++j)
      sum += bessel_k0_image(y + 2 * j * length) + (j >= 2 ? bessel_k0_image(2 * j * length - y) : 0.0);
    return sum;
  };
  return {true, length, ChebyshevFit(images, 0.0, 2.0 * length), {0.0, 2.0 * length}};
}

struct Resolution {
  int extra_points;                      ///< Gauss points beyond those that integrate the polynomial part exactly
  double depth;                          ///< grading stops at this fraction of a piece's length from a singularity
  static constexpr double ratio = 0.25;  ///< geometric grading: distance/length ≥ 1/3 per subinterval
};

Resolution resolution_of(int level) { return {6 + 6 * level, std::pow(10.0, -8.0 - 6.0 * level)}; }

// Legendre values P_0..P_p at τ into `out`.
void legendre(int p, double tau, double* out) {
  out[0] = 1.0;
  if (p >= 1) out[1] = tau;
  for (int j = 2; j <= p; ++j) out[j] = ((2 * j - 1) * tau * out[j - 1] - (j - 1) * out[j - 2]) / j;
}

struct Segment {
  double begin, end;
  int degree;
  double tau(double s) const { return 2.0 * (s - begin) / (end - begin) - 1.0; }
};

// ∫_I ∫_J μ_i(s) μ_j(t) k(s ∓ t) ds dt, shape (p_I + 1, p_J + 1): the outer integral over
// x = s ∓ t, the inner one over the s with (s, t) ∈ I × J, which is exact by Gauss because the
// integrand is a polynomial of degree p_I + p_J in s.
class PairIntegral {
 public:
  PairIntegral(const Segment& i, const Segment& j, const Kernel& kernel, const Resolution& resolution)
      : i_(i),
        j_(j),
        kernel_(kernel),
        resolution_(resolution),
        inner_(basis::gauss_legendre(basis::gauss_points_for_degree(i.degree + j.degree))),
        outer_(
            basis::gauss_legendre(basis::gauss_points_for_degree(i.degree + j.degree + 1) + resolution.extra_points)),
        value_i_(i.degree + 1),
        value_j_(j.degree + 1),
        result_(Eigen::MatrixXd::Zero(i.degree + 1, j.degree + 1)) {}

  Eigen::MatrixXd compute() {
    // The correlation (convolution) of the two bases is a polynomial between these points.
    const bool sum = kernel_.sum;
    const double lo = sum ? i_.begin + j_.begin : i_.begin - j_.end;
    const double hi = sum ? i_.end + j_.end : i_.end - j_.begin;
    if (kernel_.negligible_on(lo, hi)) return result_;
    std::vector<double> cuts{lo, hi};
    for (double x :
         sum ? std::vector{i_.begin + j_.end, i_.end + j_.begin} : std::vector{i_.begin - j_.begin, i_.end - j_.end})
      cuts.push_back(x);
    for (double z : kernel_.singular_points)
      if (z > lo && z < hi) cuts.push_back(z);
    std::sort(cuts.begin(), cuts.end());
    const double merge = 1e-14 * (hi - lo);
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
      if (cuts[k + 1] - cuts[k] > merge) piece(cuts[k], cuts[k + 1]);
    return result_;
  }

 private:
  // Distance from [a, b] to the nearest singularity at or below a (above b).
  double distance_below(double a) const {
    double d = INFINITY;
    for (double z : kernel_.singular_points)
      if (z <= a + 1e-14 * std::abs(a)) d = std::min(d, std::max(a - z, 0.0));
    return d;
  }
  double distance_above(double b) const {
    double d = INFINITY;
    for (double z : kernel_.singular_points)
      if (z >= b - 1e-14 * std::abs(b)) d = std::min(d, std::max(z - b, 0.0));
    return d;
  }

  void piece(double a, double b) {
    const double length = b - a, below = distance_below(a), above = distance_above(b);
    if (below < length && above < length) {
      piece(a, 0.5 * (a + b));
      piece(0.5 * (a + b), b);
    } else if (below < length || above < length) {
      // Subintervals [r_{k+1}, r_k] from the end nearest the singularity, r_k = length · ratio^k,
      // until r_K reaches the singularity's distance (or the depth); then [0, r_K].
      const bool towards_a = below < length;
      const double stop = std::max(towards_a ? below : above, resolution_.depth * length);
      double r = length;
      while (r > stop) {
        const double next = r * Resolution::ratio;
        towards_a ? gauss(a + next, a + r) : gauss(b - r, b - next);
        r = next;
      }
      towards_a ? gauss(a, a + r) : gauss(b - r, b);
    } else {
      gauss(a, b);
    }
  }

  void gauss(double a, double b) {
    const double half = 0.5 * (b - a);
    for (std::size_t g = 0; g < outer_.points.size(); ++g) {
      const double x = a + half * (outer_.points[g] + 1.0);
      // s ∈ I with t = s − x ∈ J (difference) or t = x − s ∈ J (sum).
      const double s_lo = kernel_.sum ? std::max(i_.begin, x - j_.end) : std::max(i_.begin, x + j_.begin);
      const double s_hi = kernel_.sum ? std::min(i_.end, x - j_.begin) : std::min(i_.end, x + j_.end);
      if (s_hi <= s_lo) continue;
      const double weight = half * outer_.weights[g] * kernel_(x) * 0.5 * (s_hi - s_lo);
      for (std::size_t q = 0; q < inner_.points.size(); ++q) {
        const double s = s_lo + 0.5 * (s_hi - s_lo) * (inner_.points[q] + 1.0);
        const double t = kernel_.sum ? x - s : s - x;
        legendre(i_.degree, i_.tau(s), value_i_.data());
        legendre(j_.degree, j_.tau(t), value_j_.data());
        const double w = weight * inner_.weights[q];
        for (int ii = 0; ii <= i_.degree; ++ii)
          for (int jj = 0; jj <= j_.degree; ++jj) result_(ii, jj) += w * value_i_[ii] * value_j_[jj];
      }
    }
  }

  const Segment& i_;
  const Segment& j_;
  const Kernel& kernel_;
  const Resolution& resolution_;
  const basis::QuadratureRule1D& inner_;
  const basis::QuadratureRule1D& outer_;
  std::vector<double> value_i_, value_j_;
  Eigen::MatrixXd result_;
};

}  // namespace

Eigen::MatrixXd interpolation_norm_gram_kernel(const space::MultiplierSpace& multipliers,
                                               const KernelQuadrature& quadrature) {
  if (quadrature.level < 0 || quadrature.level > 4)
    throw_bad_input("interpolation norm", "quadrature level", std::to_string(quadrature.level), "must be in 0..4");
  // Γ_C's zones are disjoint curves: H^{1/2} of their union is the sum of each one's, and G is
  // block diagonal, each zone's block the Neumann kernel of its own arc [0, L_z].
  const auto& boundary = multipliers.boundary_mesh();
  const Resolution resolution = resolution_of(quadrature.level);
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(multipliers.n_dofs(), multipliers.n_dofs());
  for (std::size_t z = 0; z < boundary.zones().size(); ++z) {
    const auto& zone = boundary.zones()[z];
    if (zone.closed)
      throw InputError(
          "the interpolation norm of H^{-1/2}(Γ_C) is built for open curves (the kernel of an interval); a zone "
          "of Γ_C is a closed curve: use the extension norm ([infsup] norm = \"extension\")");
    const double length = zone.end - zone.begin;
    const Kernel difference = difference_kernel(length), sum = sum_kernel(length);
    std::vector<int> indices;
    std::vector<Segment> segments;
    for (int k = 0; k < multipliers.n_segments(); ++k)
      if (boundary.zone_of_segment(k) == static_cast<int>(z)) {
        indices.push_back(k);
        segments.push_back({boundary.segment_begin(k) - zone.begin, boundary.segment_end(k) - zone.begin,
                            multipliers.segment_degree(k)});
      }
    for (std::size_t a = 0; a < segments.size(); ++a)
      for (std::size_t b = a; b < segments.size(); ++b) {
        const Eigen::MatrixXd block = PairIntegral(segments[a], segments[b], difference, resolution).compute() +
                                      PairIntegral(segments[a], segments[b], sum, resolution).compute();
        const int k = indices[a], l = indices[b];
        gram.block(multipliers.first_dof(k), multipliers.first_dof(l), block.rows(), block.cols()) = block;
        if (l != k)
          gram.block(multipliers.first_dof(l), multipliers.first_dof(k), block.cols(), block.rows()) =
              block.transpose();
      }
  }
  gram /= std::numbers::pi;
  return 0.5 * (gram + gram.transpose());
}

}  // namespace hpcontact::norms
