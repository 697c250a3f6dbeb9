// Hertz contact of an elastic cylinder on an elastic block, plane strain:
// the quarter x >= 0 of the problem (x = 0 is a line of symmetry).
//
// Body 1 (physical surface 1): the half-cylinder of radius R, its centre on
// x = 0 at height R - d0, cut by its diametral plane y = R - d0, where the
// load acts. Its lowest point dips d0 below the block's top. d0 = 0, bodies
// that just touch, is solved too: a step that would start with no node
// closed closes the nodes whose gap is within 1 % of a segment
// (contact_interface.cc), which then hold the cylinder that nothing else
// holds vertically (tests/hertz_touching). The small overlap of the default is the model the
// validation was measured on; in small strain it changes nothing in the
// solution (the cylinder's vertical rigid-body translation absorbs it) as
// long as the contact zone contains the overlap zone, |x| < sqrt(2 R d0).
// Body 2 (physical surface 2): the block [0, L] x [-H, 0].
//
// Boundary tags (physical curves):
//   10 the cylinder's surface (the slave),   11 its diametral plane (load),
//   12 the cylinder's symmetry line,         20 the block's top (master),
//   21 the block's bottom,                   22 the block's symmetry line,
//   23 the block's far side.
// Quadrilaterals of size h within 2 a0 of the contact, growing to hmax far
// from it (a0: the expected contact half-width); every cell a quadrilateral
// (recombined, then subdivided once: the cells are h/2).
DefineConstant[ R = 1, L = 5, H = 5, a0 = 0.1, h = 0.02, hmax = 0.25,
                d0 = 2e-4 ];

// The cylinder
Point(1) = {0, R - d0, 0};          // centre
Point(2) = {0, -d0, 0};             // lowest point
Point(3) = {R, R - d0, 0};
Point(4) = {R * Sin(Pi / 12), R - d0 - R * Cos(Pi / 12), 0};
Circle(1) = {2, 1, 4};
Circle(2) = {4, 1, 3};
Line(3) = {3, 1};
Line(4) = {1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// The block
Point(11) = {0, 0, 0};
Point(12) = {L, 0, 0};
Point(13) = {L, -H, 0};
Point(14) = {0, -H, 0};
Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 11};
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};

// Sizes: h near the contact, hmax away from it.
Field[1] = Distance;
Field[1].PointsList = {2, 11};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hmax;
Field[2].DistMin = 2 * a0;
Field[2].DistMax = 2 * a0 + R;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Mesh.Algorithm = 6;            // frontal-Delaunay, then recombined
Mesh.RecombineAll = 1;
Mesh.SubdivisionAlgorithm = 1; // all quadrilaterals

Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Curve(10) = {1, 2};
Physical Curve(11) = {3};
Physical Curve(12) = {4};
Physical Curve(20) = {11};
Physical Curve(21) = {13};
Physical Curve(22) = {14};
Physical Curve(23) = {12};
