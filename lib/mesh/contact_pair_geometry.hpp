// The geometry of a contact pair of two bodies in the reference configuration (small
// deformation): the closest-point projection Φ of the slave body's Γ_C onto the master body's,
// the gap g = (Φ(x) − x)·n_s along the slave's outward normal, and the mortar segments, the pieces
// of the slave's trace edges that Φ maps into one master edge each, over which the coupling
// ∫ μ (v_s − v_m∘Φ)·n_s is integrated.
#pragma once

#include <vector>

#include "mesh/contact_boundary.hpp"

namespace hpcontact::mesh {

/// Φ(x) and where it lies on the master boundary.
struct MasterPoint {
  Point point = Point::Zero();  ///< Φ(x), the point of the master boundary nearest to x
  double s = 0.0;               ///< its arc length on the master boundary
  double t = 0.0;               ///< its parameter on the master cell's edge (TraceEdge::local_parameter(s))
  int edge = -1;                ///< the master trace edge holding it (the nearer one at a vertex)
  double distance = 0.0;        ///< |Φ(x) − x|
  /// False where x lies beyond an end of an open master zone (Φ(x) is that end and x − Φ(x)
  /// points away from the zone): the slave is not covered by the master there.
  bool covered = true;
};

/// One piece of a slave trace edge that Φ maps into a single master edge.
struct MortarSegment {
  double s_begin = 0.0, s_end = 0.0;  ///< arc lengths on the slave's Γ_C
  int slave_edge = -1;                ///< index into the slave's ContactBoundary::edges()
  int master_edge = -1;               ///< index into the master's ContactBoundary::edges()
  bool covered = true;                ///< MasterPoint::covered inside the segment
};

/// Φ onto the master boundary of a pair. Holds a reference to `master`, which must outlive it.
class MasterProjection {
 public:
  explicit MasterProjection(const ContactBoundary& master);
  explicit MasterProjection(ContactBoundary&&) = delete;  // a temporary would dangle

  const ContactBoundary& master() const { return *master_; }

  /// Φ(x): the nearest point over all master edges (straight edges in closed form, curved ones by
  /// a sign change of the derivative of |γ − x|²/2 along the edge, of the sign of (γ − x)·γ', searched
  /// in the cell's edge parameter t and refined by false position to round-off).
  /// Edges farther than the nearest point found so far are skipped by a bounding circle (centre
  /// at the edge's middle, radius half its length), so a query costs about one distance per edge.
  MasterPoint project(const Point& x) const;

  /// The gap at arc length s of the slave's Γ_C: (Φ(x) − x)·n_s(x), x = slave.point_at(s).
  double gap(const ContactBoundary& slave, double s) const;

  /// The slave arc lengths, ascending, at which Φ(x(s)) passes a master vertex (zone ends
  /// included: where the slave's coverage by the master begins or ends): the points x(s) on the
  /// master's normal line through the vertex (at a corner, on each of its two normal lines) whose
  /// projection is that vertex. Slave vertices are not listed.
  std::vector<double> slave_breakpoints(const ContactBoundary& slave) const;

  /// The slave's trace edges split at slave_breakpoints and at `extra` (e.g. the breakpoints of
  /// T_{C,H}), in the order of s, each with the master edge that Φ maps it into.
  /// @throws InputError naming the slave position if Φ jumps inside a covered segment (a concave
  /// master or two master zones equally near: the closest point is not continuous there).
  std::vector<MortarSegment> mortar_segments(const ContactBoundary& slave, const std::vector<double>& extra = {}) const;

 private:
  /// The nearest point of master edge k to x: its arc length, edge parameter and position.
  struct EdgePoint {
    double s, t;
    Point point;
  };
  EdgePoint nearest_on_edge(int k, const Point& x) const;

  const ContactBoundary* master_;
  std::vector<Point> centres_;  ///< each master edge's point at its middle arc length
};

}  // namespace hpcontact::mesh
