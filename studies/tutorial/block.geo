// The tutorial's body: a block with a sloped top, clamped along the top, resting on a rigid
// obstacle along its bottom edge. Meshed into quadrilaterals only (hpcontact's element):
//   gmsh -2 -format msh4 block.geo -o block.msh
h = 0.2;
Point(1) = {0, 0, 0, h};
Point(2) = {2, 0, 0, h};
Point(3) = {2, 1, 0, h};
Point(4) = {0, 1.5, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("contact") = {1};
Physical Curve("clamped") = {3};
Physical Curve("free") = {2, 4};
Physical Surface("block") = {1};
Mesh.RecombineAll = 1;          // quadrilaterals ...
Mesh.Algorithm = 6;             // ... recombined from a frontal-Delaunay mesh,
Mesh.SubdivisionAlgorithm = 1;  // every triangle left split into quads
Mesh.ElementOrder = 1;
