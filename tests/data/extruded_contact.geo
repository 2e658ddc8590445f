// Γ_C of studies/three_d/extruded_*.toml, the face z = −1 of (−1, 1) × (0, 0.5) × (−1, 1), as
// triangles for contact_mesh.mesh (tests/cli/solid_trace_products_test.cpp).
s = 0.5;
Point(1) = {-1, 0, -1, s}; Point(2) = {1, 0, -1, s}; Point(3) = {1, 0.5, -1, s}; Point(4) = {-1, 0.5, -1, s};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
