// A rigid obstacle given as geometry ([obstacle] in a scene) and the gap it makes: the distance
// from a point of Γ_C along Γ_C's outward normal n to the obstacle's surface (negative where the
// body starts inside it), the g of u ≤ g (scalar model) and u·n ≤ g (elasticity).
//   plane     through `point`, with `normal` its unit normal towards the body
//   circle    a disk (2-D section of a cylinder) of `radius` about `point`, the body outside it
//   parabola  vertex `point`, `normal` towards the body there, curvature radius `radius`: the
//             surface V + ξτ − ξ²/(2R)·normal (Hertz's approximation of a round indenter)
//   distance  an expression φ(x, y): > 0 on the body's side, 0 on the surface; the gap is the
//             root of φ(X + t n) found by Newton
// The shapes' gaps are exact (a line or quadratic along the normal). A normal that does not meet
// the obstacle is an input error naming the point: no gap is guessed there.
#pragma once

#include <functional>
#include <string>

#include "mesh/contact_boundary.hpp"

namespace hpcontact::contact {

enum class ObstacleType { plane, circle, parabola, distance };
const char* to_string(ObstacleType type);

struct RigidObstacle {
  ObstacleType type = ObstacleType::plane;
  mesh::Point point = mesh::Point::Zero();    ///< plane: a point on it; circle: centre; parabola: vertex
  mesh::Point normal = mesh::Point::UnitY();  ///< plane, parabola: unit normal towards the body
  double radius = 1.0;                        ///< circle, parabola
  std::string distance;                       ///< distance: φ(x, y)
  std::string origin;                         ///< "scene.toml: [obstacle]", for messages
};

/// The gap at points of Γ_C: each point is located on its edge of `contact` (the nearest one,
/// searched from the last edge found, since points come in order along Γ_C), whose outward
/// normal there is n. `contact` must outlive the function. @throws InputError (when called)
/// where the normal misses the obstacle or Newton on φ fails.
std::function<double(const mesh::Point&)> obstacle_gap(const RigidObstacle& obstacle,
                                                       const mesh::ContactBoundary& contact);

/// The gap from X along the unit vector n (the part that needs no mesh; exposed for tests);
/// `length` sets the scale of Newton's steps for a distance expression (obstacle_gap passes the
/// length of Γ_C). @throws InputError where the normal misses the obstacle.
double gap_along(const RigidObstacle& obstacle, const mesh::Point& x, const mesh::Point& n, double length = 1.0);

}  // namespace hpcontact::contact
