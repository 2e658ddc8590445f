// The punch of the two-body Hertz problem: the lower half of the disc of radius 1 centred at
// (0, 1), its flat top clamped (and moved), its arc the contact boundary. The cells shrink towards
// the arc's lowest point (0, 0), where it meets the block. Triangles; the arc followed exactly.
h_far = 0.2;
h_contact = 0.002;
Point(1) = {0, 1, 0, h_far};
Point(2) = {-1, 1, 0, h_far};
Point(3) = {0, 0, 0, h_contact};
Point(4) = {1, 1, 0, h_far};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Physical Curve("arc") = {1, 2};
Physical Curve("top") = {3};
Physical Surface("disc") = {1};
