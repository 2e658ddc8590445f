// T_{C,H} of studies/three_d/hertz.toml: the contact patch 0 ≤ x, y ≤ 0.48 of the block's
// top face z = 0 in triangles of at most 0.06 (H = 2h), with the quarter circle r = 0.3065 as an
// edge of the mesh: Hertz's contact radius for the force of studies/three_d/hertz_grid.toml.
r = 0.3065; L = 0.48; s = 0.06;
Point(1) = {0, 0, 0, s}; Point(2) = {r, 0, 0, s}; Point(3) = {L, 0, 0, s};
Point(4) = {L, L, 0, s}; Point(5) = {0, L, 0, s}; Point(6) = {0, r, 0, s};
Line(1) = {1, 2}; Circle(2) = {2, 1, 6}; Line(3) = {6, 1};
Line(4) = {2, 3}; Line(5) = {3, 4}; Line(6) = {4, 5}; Line(7) = {5, 6};
Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};
Curve Loop(2) = {4, 5, 6, 7, -2}; Plane Surface(2) = {2};
