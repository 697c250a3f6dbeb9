// A rigid flat punch on an elastic half-plane, plane strain: the punch, a
// block [-b, b] x [0, hp] a thousand times stiffer than the half-plane
// (physical surface 2), pressed onto a block [-L, L] x [-D, 0] (physical
// surface 1) that stands for the half-plane (L and D twenty times b).
// The punch's base is the slave (ns segments: ns / 2 before the subdivision
// below), the block's top the master, its cells of size hm (before the
// subdivision) within 2 b of the punch and growing to hmax away from it, so
// that the two surfaces do not match (ns = 200, hm = 0.0125: 0.005 against
// 0.00625 once subdivided, the slave the finer).
// Tags (physical curves): 10 the punch's base (slave), 11 its top (load),
// 12 its sides; 20 the block's top (master), 21 its bottom, 22 its sides.
// Every cell a quadrilateral: gmsh's frontal-Delaunay triangles recombined,
// then each quadrilateral split in four (Mesh.SubdivisionAlgorithm = 1).
DefineConstant[ b = 0.5, L = 10, D = 10, ns = 200, hm = 0.0125, hmax = 1,
                hp = 0.5 ];
Point(1) = {-L, -D, 0, hmax}; Point(2) = {L, -D, 0, hmax};
Point(3) = {L, 0, 0, hmax};   Point(4) = {-L, 0, 0, hmax};
Point(5) = {-2 * b, 0, 0, hm}; Point(6) = {2 * b, 0, 0, hm};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 6};
Line(4) = {6, 5}; Line(5) = {5, 4}; Line(6) = {4, 1};
Transfinite Curve{4} = Round(4 * b / hm) + 1;
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Point(11) = {-b, 0, 0}; Point(12) = {b, 0, 0};
Point(13) = {b, hp, 0}; Point(14) = {-b, hp, 0};
Line(11) = {11, 12}; Line(12) = {12, 13}; Line(13) = {13, 14};
Line(14) = {14, 11};
Transfinite Curve{11, 13} = ns / 2 + 1; Transfinite Curve{12, 14} = 4;
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};
Transfinite Surface{2};
Recombine Surface{1, 2};
Mesh.Algorithm = 6;
Mesh.SubdivisionAlgorithm = 1;
Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Curve(20) = {3, 4, 5};
Physical Curve(21) = {1};
Physical Curve(22) = {2, 6};
Physical Curve(10) = {11};
Physical Curve(11) = {13};
Physical Curve(12) = {12, 14};
