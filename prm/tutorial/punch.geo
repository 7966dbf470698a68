// Tutorial scene (README "Your own scene"): half of a plane-strain punch
// with a rounded nose, pressed onto a rigid plate. Units: mm.
//
// The punch is 2 W wide and H tall; its lower end is a circular arc of
// radius R whose lowest point touches the plate at the origin. Only the
// half x >= 0 is meshed (the axis x = 0 is a symmetry line).
//
// Mesh it (Debian package gmsh) from this folder:
//   gmsh -2 -format msh41 punch.geo -o punch.msh
// Physical tags become the ids signorini sees: the surface's tag is the
// body's material id, the curves' tags are boundary ids.

W  = 10;    // half-width
H  = 20;    // height
R  = 50;    // radius of the nose
yW = R - Sqrt(R^2 - W^2);   // height of the nose's ends above the plate

Point(1) = {0, 0, 0};       // lowest point of the nose, on the plate
Point(2) = {W, yW, 0};      // end of the nose arc
Point(3) = {W, H, 0};
Point(4) = {0, H, 0};
Point(5) = {0, R, 0};       // centre of the nose arc (not meshed)

Circle(1) = {1, 5, 2};      // the nose
Line(2)   = {2, 3};         // free side x = W
Line(3)   = {3, 4};         // top, where the load is applied
Line(4)   = {4, 1};         // symmetry axis x = 0
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Physical Curve("nose", 1)     = {1};
Physical Curve("side", 2)     = {2};
Physical Curve("top", 3)      = {3};
Physical Curve("axis", 4)     = {4};
Physical Surface("punch", 7)  = {1};

// Element size: 0.05 within 1.5 of the contact point (the contact zone's
// half-width is about 1), growing to 1.5 beyond 12.
Field[1] = Distance;
Field[1].PointsList = {1};
Field[2] = Threshold;
Field[2].InField  = 1;
Field[2].SizeMin  = 0.05;
Field[2].SizeMax  = 1.5;
Field[2].DistMin  = 1.5;
Field[2].DistMax  = 12;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

// Quadrilaterals: triangles by Frontal-Delaunay (algorithm 6), paired into
// quadrilaterals by the Blossom algorithm: 1505 quadrilaterals, no
// triangle. (Debian's gmsh 4.8 ends in a segmentation fault on this punch
// with algorithm 8, Frontal-Delaunay for quads.)
Mesh.Algorithm = 6;
Mesh.RecombinationAlgorithm = 1;
Recombine Surface{1};
