// The paper's §7 square (-1,1)² for triangles: Γ_C the bottom edge, Γ_D the top edge and the upper
// half of the right edge (a point at (1, 0) where Γ_D ends), Γ_N the rest. Unstructured triangles
// of size h (Gmsh's frontal-Delaunay), written as MSH 4.1 ASCII with physical groups:
//   gmsh -2 -format msh41 square.geo -o square.msh
h = 0.125;
Point(1) = {-1, -1, 0, h};
Point(2) = {1, -1, 0, h};
Point(3) = {1, 0, 0, h};
Point(4) = {1, 1, 0, h};
Point(5) = {-1, 1, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Physical Curve("contact") = {1};
Physical Curve("dirichlet") = {3, 4};
Physical Curve("neumann") = {2, 5};
Physical Surface("square") = {1};
Mesh.Algorithm = 6;
Mesh.ElementOrder = 1;
