// Unit disk for the Powell-Sabin tests: a polygonal approximation of a
// curved boundary, where every boundary vertex is a shallow convex corner.
// Regenerate with
//   gmsh -2 -format msh2 disk.geo -o disk.msh
SetFactory("OpenCASCADE");
Disk(1) = {0, 0, 0, 1, 1};
Physical Curve("circle", 0) = {1};
Physical Surface("domain", 1) = {1};
Mesh.CharacteristicLengthMax = 0.3;
