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

// A root of f in [a, b] where f(a) and f(b) differ in sign (or one is zero), by bisection to the
// last bit of the interval: f is smooth but need not be monotone, and bisection cannot leave the
// bracket.
template <class Function>
double bisect(const Function& f, double a, double b, double fa) {
  for (int iteration = 0; iteration < 200 && b - a > 0.0; ++iteration) {
    const double middle = 0.5 * (a + b);
    if (middle <= a || middle >= b) break;
    const double fm = f(middle);
    if ((fa < 0.0) == (fm < 0.0)) {
      a = middle;
      fa = fm;
    } else {
      b = middle;
    }
  }
  return 0.5 * (a + b);
}

// The roots of f on [a, b] (samples + 1 values, a bisection in each piece where the sign changes).
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
      roots.push_back(bisect(f, previous_s, s, previous_f));
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

double MasterProjection::nearest_on_edge(int k, const Point& x) const {
  const TraceEdge& edge = master_->edges()[k];
  const double length = edge.s_end - edge.s_begin;
  if (!edge.arc) {
    const Point a = master_->point_on_edge(k, edge.s_begin), b = master_->point_on_edge(k, edge.s_end);
    const double t = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    return edge.s_begin + t * length;
  }
  // The minima of |γ(s) − x|²/2 inside the edge are where its derivative (γ(s) − x)·γ'(s) (|γ'| = 1
  // in arc length) changes sign from − to +; the ends are candidates too.
  const auto slope = [&](double s) { return (master_->point_on_edge(k, s) - x).dot(master_->tangent_on_edge(k, s)); };
  auto candidates = roots_on(slope, edge.s_begin, edge.s_end, kCurvedSamples);
  candidates.push_back(edge.s_begin);
  candidates.push_back(edge.s_end);
  return *std::min_element(candidates.begin(), candidates.end(), [&](double a, double b) {
    return (master_->point_on_edge(k, a) - x).squaredNorm() < (master_->point_on_edge(k, b) - x).squaredNorm();
  });
}

MasterPoint MasterProjection::project(const Point& x) const {
  const auto& edges = master_->edges();
  MasterPoint best;
  best.distance = std::numeric_limits<double>::infinity();
  for (int k = 0; k < static_cast<int>(edges.size()); ++k) {
    // Every point of the edge lies within half its arc length of its middle.
    if ((x - centres_[k]).norm() - 0.5 * (edges[k].s_end - edges[k].s_begin) > best.distance) continue;
    const double s = nearest_on_edge(k, x);
    const Point point = master_->point_on_edge(k, s);
    const double distance = (point - x).norm();
    if (distance < best.distance) best = {point, s, k, distance, true};
  }
  // Beyond an open zone's end: x − Φ(x) leaves the zone along its outward tangent there.
  const TraceEdge& edge = edges[best.edge];
  const ContactZone& zone = master_->zones()[edge.zone];
  const double tolerance = 1e-12 * master_->length();
  if (!zone.closed && best.s <= edge.s_begin && edge.s_begin <= zone.s_begin)
    best.covered = (x - best.point).dot(-master_->tangent_on_edge(best.edge, best.s)) <= tolerance;
  if (!zone.closed && best.s >= edge.s_end && edge.s_end >= zone.s_end)
    best.covered = (x - best.point).dot(master_->tangent_on_edge(best.edge, best.s)) <= tolerance;
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
    for (const double s_vertex : {master_edges[k].s_begin, master_edges[k].s_end}) {
      // The normal line of edge k through its vertex: (x − v)·t = 0.
      const Point vertex = master_->point_on_edge(k, s_vertex);
      const Point tangent = master_->tangent_on_edge(k, s_vertex);
      for (int j = 0; j < static_cast<int>(slave_edges.size()); ++j) {
        const auto side = [&](double s) { return (slave.point_on_edge(j, s) - vertex).dot(tangent); };
        const int samples = slave_edges[j].arc ? kCurvedSamples : 1;
        for (double s : roots_on(side, slave_edges[j].s_begin, slave_edges[j].s_end, samples))
          if ((project(slave.point_on_edge(j, s)).point - vertex).norm() <= tolerance) found.push_back(s);
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
