// MasterProjection: the closest point on the master's Γ_C, the gap, and the mortar segments.
#include "mesh/contact_pair_geometry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace hpcontact::mesh {
namespace {

// Sign changes of a smooth function along a curved edge are looked for between this many equal
// pieces: enough for edges whose curve turns by less than a quarter circle, which meshes that
// resolve their geometry keep (a straight edge needs only its two ends).
constexpr int kCurvedSamples = 8;

// A root of f in [a, b] where f(a) and f(b) differ in sign (or one is zero), by the Illinois
// variant of false position, which keeps the bracket (f is smooth but need not be monotone) and
// converges superlinearly: a curved edge costs a cell-map evaluation per step, and bisection to the
// last bit took fifty of them. Ends when the bracket stops shrinking, the root being then known to
// round-off.
template <class Function>
double bracketed_root(const Function& f, double a, double b, double fa, double fb) {
  if (fa == 0.0) return a;
  if (fb == 0.0) return b;
  int retained = 0;  // which end stayed last time: −1 a, +1 b
  for (int iteration = 0; iteration < 200; ++iteration) {
    double c = (a * fb - b * fa) / (fb - fa);
    // Where false position stalls next to an end, halve instead.
    if (!(c > a && c < b)) c = 0.5 * (a + b);
    if (c <= a || c >= b) break;
    const double fc = f(c);
    if (fc == 0.0) return c;
    if ((fa < 0.0) == (fc < 0.0)) {
      a = c;
      fa = fc;
      if (retained == 1) fb *= 0.5;
      retained = 1;
    } else {
      b = c;
      fb = fc;
      if (retained == -1) fa *= 0.5;
      retained = -1;
    }
    if (b - a <= 4.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), std::abs(b))) break;
  }
  return std::abs(fa) <= std::abs(fb) ? a : b;
}

// The roots of f on [a, b] (samples + 1 values, a bracketed root in each piece where the sign changes).
template <class Function>
std::vector<double> roots_on(const Function& f, double a, double b, int samples) {
  std::vector<double> roots;
  double previous_s = a, previous_f = f(a);
  if (previous_f == 0.0) roots.push_back(a);
  for (int k = 1; k <= samples; ++k) {
    const double s = k == samples ? b : a + (b - a) * k / samples;
    const double value = f(s);
    if (value == 0.0)
      roots.push_back(s);
    else if (previous_f != 0.0 && (previous_f < 0.0) != (value < 0.0))
      roots.push_back(bracketed_root(f, previous_s, s, previous_f, value));
    previous_s = s;
    previous_f = value;
  }
  return roots;
}

// Sorted values with those closer than `tolerance` to their predecessor removed.
std::vector<double> sorted_distinct(std::vector<double> values, double tolerance) {
  std::sort(values.begin(), values.end());
  std::vector<double> distinct;
  for (double value : values)
    if (distinct.empty() || value - distinct.back() > tolerance) distinct.push_back(value);
  return distinct;
}

}  // namespace

MasterProjection::MasterProjection(const ContactBoundary& master) : master_(&master) {
  const auto& edges = master.edges();
  for (int k = 0; k < static_cast<int>(edges.size()); ++k)
    centres_.push_back(master.point_on_edge(k, 0.5 * (edges[k].s_begin + edges[k].s_end)));
}

MasterProjection::EdgePoint MasterProjection::nearest_on_edge(int k, const Point& x) const {
  const TraceEdge& edge = master_->edges()[k];
  if (!edge.arc) {
    const Point a = master_->point_on_edge(k, edge.s_begin), b = master_->point_on_edge(k, edge.s_end);
    const double fraction = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    const double s = edge.s_begin + fraction * (edge.s_end - edge.s_begin);
    return {s, edge.local_parameter(s), (1.0 - fraction) * a + fraction * b};
  }
  // The minima of |γ − x|²/2 inside the edge are where its derivative along the edge, of the sign
  // of (γ − x)·γ', changes sign; the ends are candidates too. Searched in the cell's edge parameter t.
  const auto slope = [&](double t) {
    return (master_->point_at_parameter(k, t) - x).dot(master_->tangent_at_parameter(k, t));
  };
  auto candidates = roots_on(slope, -1.0, 1.0, kCurvedSamples);
  candidates.push_back(-1.0);
  candidates.push_back(1.0);
  EdgePoint best{0.0, 0.0, Point::Zero()};
  double best_distance = std::numeric_limits<double>::infinity();
  for (const double t : candidates) {
    const Point point = master_->point_at_parameter(k, t);
    const double distance = (point - x).squaredNorm();
    if (distance < best_distance) {
      best_distance = distance;
      best = {0.0, t, point};
    }
  }
  best.s = std::clamp(master_->arc_length_at_parameter(k, best.t), edge.s_begin, edge.s_end);
  return best;
}

MasterPoint MasterProjection::project(const Point& x) const {
  const auto& edges = master_->edges();
  const auto n_edges = static_cast<int>(edges.size());
  // Every point of an edge lies within half its arc length of its middle: a lower bound of its
  // distance to x. The edge of the smallest bound is measured first, so that the bound prunes
  // nearly every other edge (a curved one costs a cell-map evaluation per step of its root search).
  std::vector<double> bound(static_cast<std::size_t>(n_edges));
  int first = 0;
  for (int k = 0; k < n_edges; ++k) {
    bound[k] = (x - centres_[k]).norm() - 0.5 * (edges[k].s_end - edges[k].s_begin);
    if (bound[k] < bound[first]) first = k;
  }
  MasterPoint best;
  best.distance = std::numeric_limits<double>::infinity();
  for (int visited = 0; visited < n_edges; ++visited) {
    const int k = visited == 0 ? first : (visited <= first ? visited - 1 : visited);
    if (bound[k] > best.distance) continue;
    const EdgePoint nearest = nearest_on_edge(k, x);
    const double distance = (nearest.point - x).norm();
    // Ties go to the lower edge index, whichever was measured first.
    if (distance < best.distance || (distance == best.distance && k < best.edge))
      best = {nearest.point, nearest.s, nearest.t, k, distance, true};
  }
  // Beyond an open zone's end: x − Φ(x) leaves the zone along its outward tangent there.
  const TraceEdge& edge = edges[best.edge];
  const ContactZone& zone = master_->zones()[edge.zone];
  const double tolerance = 1e-12 * master_->length();
  if (!zone.closed && best.s <= edge.s_begin && edge.s_begin <= zone.s_begin)
    best.covered = (x - best.point).dot(-master_->tangent_at_parameter(best.edge, best.t)) <= tolerance;
  if (!zone.closed && best.s >= edge.s_end && edge.s_end >= zone.s_end)
    best.covered = (x - best.point).dot(master_->tangent_at_parameter(best.edge, best.t)) <= tolerance;
  return best;
}

double MasterProjection::gap(const ContactBoundary& slave, double s) const {
  const Point x = slave.point_at(s);
  return (project(x).point - x).dot(slave.normal_at(s));
}

std::vector<double> MasterProjection::slave_breakpoints(const ContactBoundary& slave) const {
  const auto& master_edges = master_->edges();
  const auto& slave_edges = slave.edges();
  const double tolerance = 1e-9 * master_->length();
  std::vector<double> found;
  for (int k = 0; k < static_cast<int>(master_edges.size()); ++k)
    for (const double t_vertex : {-1.0, 1.0}) {
      // The normal line of edge k through its vertex: (x − v)·τ = 0, searched along each slave
      // edge in its cell's edge parameter.
      const Point vertex = master_->point_at_parameter(k, t_vertex);
      const Point tangent = master_->tangent_at_parameter(k, t_vertex);
      for (int j = 0; j < static_cast<int>(slave_edges.size()); ++j) {
        const auto side = [&](double t) { return (slave.point_at_parameter(j, t) - vertex).dot(tangent); };
        const int samples = slave_edges[j].arc ? kCurvedSamples : 1;
        for (double t : roots_on(side, -1.0, 1.0, samples))
          if ((project(slave.point_at_parameter(j, t)).point - vertex).norm() <= tolerance)
            found.push_back(slave.arc_length_at_parameter(j, t));
      }
    }
  return sorted_distinct(std::move(found), 1e-12 * slave.length());
}

std::vector<MortarSegment> MasterProjection::mortar_segments(const ContactBoundary& slave,
                                                             const std::vector<double>& extra) const {
  auto cuts = slave_breakpoints(slave);
  cuts.insert(cuts.end(), extra.begin(), extra.end());
  cuts = sorted_distinct(std::move(cuts), 0.0);
  const auto& master_edges = master_->edges();
  std::vector<MortarSegment> segments;
  for (int j = 0; j < static_cast<int>(slave.edges().size()); ++j) {
    const TraceEdge& edge = slave.edges()[j];
    const double tolerance = 1e-12 * (edge.s_end - edge.s_begin);
    std::vector<double> ends{edge.s_begin};
    for (double cut : cuts)
      if (cut > edge.s_begin + tolerance && cut < edge.s_end - tolerance) ends.push_back(cut);
    ends.push_back(edge.s_end);
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
      const double a = ends[i], b = ends[i + 1];
      const MasterPoint middle = project(slave.point_on_edge(j, 0.5 * (a + b)));
      // Φ of a covered segment must stay on the middle's master edge (its ends included); where
      // the master does not cover the slave, no master term is integrated.
      const TraceEdge& image = master_edges[middle.edge];
      const double image_tolerance = 1e-9 * (image.s_end - image.s_begin);
      for (const double s : {a + 0.25 * (b - a), a + 0.75 * (b - a)}) {
        if (!middle.covered) break;
        const MasterPoint quarter = project(slave.point_on_edge(j, s));
        if (quarter.s < image.s_begin - image_tolerance || quarter.s > image.s_end + image_tolerance) {
          const Point x = slave.point_on_edge(j, s);
          throw InputError(fmt::format(
              "contact pair: the closest point on the master boundary jumps near the slave point ({:.6g}, {:.6g}) "
              "(slave arc length {:.6g}): from master arc length {:.6g} to {:.6g}; a concave master boundary or two "
              "master zones equally near are not supported as a pair",
              x.x(), x.y(), s, middle.s, quarter.s));
        }
      }
      segments.push_back({a, b, j, middle.edge, middle.covered});
    }
  }
  return segments;
}

}  // namespace hpcontact::mesh
