// The unit cube meshed by Gmsh's defaults: linear Delaunay tetrahedra. Γ_C is the floor z = 0
// (OpenCASCADE's surface 5), Γ_D the lid z = 1 (surface 6).
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Physical Surface("floor") = {5};
Physical Surface("lid") = {6};
Physical Volume("cube") = {1};
