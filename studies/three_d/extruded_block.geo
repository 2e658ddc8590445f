// The block (−1, 1) × (0, 0.5) × (−1, 1) of extruded_signorini.toml as Gmsh hexahedra: a point
// extruded into 8 segments along x, 2 layers along y and 8 along z, recombined — the box of
// n_x = 8, n_y = 2, n_z = 8. Physical surfaces: "bottom" (z = −1, Γ_C) and "top" (z = 1).
//   hpcontact solve studies/three_d/extruded_gmsh.toml --out results/extruded_gmsh
Point(1) = {-1, 0, -1};
edge[] = Extrude {2, 0, 0} { Point{1}; Layers{8}; };
bottom[] = Extrude {0, 0.5, 0} { Line{edge[1]}; Layers{2}; Recombine; };
block[] = Extrude {0, 0, 2} { Surface{bottom[1]}; Layers{8}; Recombine; };
Physical Surface("bottom") = {bottom[1]};
Physical Surface("top") = {block[0]};
Physical Volume("block") = {block[1]};
