// Unstructured, non-uniform triangle mesh of an L-shaped domain for the
// Powell-Sabin tests: fine near the reflex corner (0.5, 0.5), coarse far
// from it. Regenerate with
//   gmsh -2 -format msh2 l_shape.geo -o l_shape.msh
h_fine   = 0.07;
h_coarse = 0.25;
Point(1) = {0, 0, 0, h_coarse};
Point(2) = {1, 0, 0, h_coarse};
Point(3) = {1, 0.5, 0, h_fine * 2};
Point(4) = {0.5, 0.5, 0, h_fine};
Point(5) = {0.5, 1, 0, h_fine * 2};
Point(6) = {0, 1, 0, h_coarse};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Physical Curve("bottom", 2) = {1};
Physical Curve("right", 1) = {2};
Physical Curve("notch", 4) = {3, 4};
Physical Curve("top", 3) = {5};
Physical Curve("left", 0) = {6};
Physical Surface("domain", 1) = {1};
Mesh.Algorithm = 5;
