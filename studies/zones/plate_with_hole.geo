// The square (-2, 2)² with a circular hole of radius 1/2 at the origin: four Circle arcs, which
// hpcontact follows exactly. Physical curves: outer (the square's sides), hole (a closed curve).
h = 0.5;
Point(1) = {-2, -2, 0, h};
Point(2) = {2, -2, 0, h};
Point(3) = {2, 2, 0, h};
Point(4) = {-2, 2, 0, h};
Point(5) = {0, 0, 0, h};
Point(6) = {0.5, 0, 0, h / 2};
Point(7) = {0, 0.5, 0, h / 2};
Point(8) = {-0.5, 0, 0, h / 2};
Point(9) = {0, -0.5, 0, h / 2};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Circle(5) = {6, 5, 7};
Circle(6) = {7, 5, 8};
Circle(7) = {8, 5, 9};
Circle(8) = {9, 5, 6};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};
Physical Curve("outer") = {1, 2, 3, 4};
Physical Curve("hole") = {5, 6, 7, 8};
Physical Surface("plate") = {1};
