// The tutorial's second body: a slab whose bottom is a circular arc (through (-1, 0), (0, -0.3),
// (1, 0); centre (0, 91/60)), clamped along its top, resting on a rigid obstacle along the arc.
// Triangles (hpcontact meshes a .geo on the fly with [domain] cells = "triangles"), and the arc is
// followed exactly, not by its chords.
h = 0.25;
Point(1) = {-1, 0, 0, h};
Point(2) = {1, 0, 0, h};
Point(3) = {1, 0.5, 0, h};
Point(4) = {-1, 0.5, 0, h};
Point(5) = {0, 91/60, 0, h};
Circle(1) = {1, 5, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("contact") = {1};
Physical Curve("clamped") = {3};
Physical Curve("free") = {2, 4};
Physical Surface("arch") = {1};
