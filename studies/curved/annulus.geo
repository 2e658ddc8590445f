// Quarter annulus 1 < r < 2, 0 < θ < π/2 with its two circular arcs as Gmsh Circle curves, so that
// hpcontact follows them exactly (mesh/gmsh_curves.hpp). Physical curves: inner (r = 1),
// outer (r = 2), bottom (y = 0), left (x = 0).
h = 0.6;
Point(1) = {0, 0, 0, h};
Point(2) = {1, 0, 0, h};
Point(3) = {2, 0, 0, h};
Point(4) = {0, 2, 0, h};
Point(5) = {0, 1, 0, h};
Line(1) = {2, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("bottom") = {1};
Physical Curve("outer") = {2};
Physical Curve("left") = {3};
Physical Curve("inner") = {4};
Physical Surface("annulus") = {1};
