// Hertz contact of an elastic cylinder of finite length on an elastic block,
// in 3D: meshes/hertz.geo's plane-strain section extruded along the
// cylinder's axis z. The quarter x >= 0, z >= 0 of the problem: x = 0 and
// z = 0 (the middle of the cylinder's length) are planes of symmetry; the
// cylinder and the block both end, free, at z = Lz (a cylinder of length
// 2 Lz lying along a block as long as itself).
//
// Body 1 (physical volume 1): the half-cylinder of radius R, its axis on
// x = 0 at height R - d0, cut by its diametral plane y = R - d0, where the
// load acts; its lowest line dips d0 below the block's top (as in 2D: the
// overlap is taken up by the cylinder's rigid descent in small strain).
// Body 2 (physical volume 2): the block [0, L] x [-H, 0] x [0, Lz].
//
// Boundary tags (physical surfaces):
//   10 the cylinder's surface (the slave),  11 its diametral plane (load),
//   12 the cylinder's symmetry plane x = 0, 13 the cylinder's z = 0,
//   14 the cylinder's free end z = Lz,
//   20 the block's top (master),            21 the block's bottom,
//   22 the block's symmetry plane x = 0,    23 the block's far side x = L,
//   24 the block's z = 0,                   25 the block's free end z = Lz.
// The section's quadrilaterals are hertz.geo's (size h within 2 a0 of the
// contact line, growing to hmax), extruded in
// nz layers, the last nz_end of them over the length a0 * 4 at the free
// end, where the pressure departs from the plane-strain one over a few
// contact half-widths.
DefineConstant[ R = 1, L = 2, H = 2, a0 = 0.1, h = 0.02, hmax = 0.2,
                d0 = 2e-4, Lz = 4, nz = 12, nz_end = 4 ];

// The cylinder's section
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

// The block's section
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

// Sizes: h near the contact line, hmax away from it.
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

// Frontal-Delaunay, then recombined into quadrilaterals only (full-quad
// Blossom: hertz.geo's subdivision would split the extruded layers too).
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 3;

// Along z: nz - nz_end equal layers up to Lz - 4 a0, nz_end over the rest.
// Extrude gives the end face, the volume, then the sides in the order of
// the curve loop.
If (Lz <= 4 * a0 || nz <= nz_end || nz_end < 1)
  Error("hertz_cylinder_3d.geo: Lz must exceed 4 a0 (the length of the end's layers), nz must exceed nz_end, nz_end at least 1");
EndIf
fz = (Lz - 4 * a0) / Lz;
cyl[] = Extrude {0, 0, Lz} {
  Surface{1}; Layers{{nz - nz_end, nz_end}, {fz, 1}}; Recombine; };
blk[] = Extrude {0, 0, Lz} {
  Surface{2}; Layers{{nz - nz_end, nz_end}, {fz, 1}}; Recombine; };

Physical Volume(1) = {cyl[1]};
Physical Volume(2) = {blk[1]};
Physical Surface(10) = {cyl[2], cyl[3]};
Physical Surface(11) = {cyl[4]};
Physical Surface(12) = {cyl[5]};
Physical Surface(13) = {1};
Physical Surface(14) = {cyl[0]};
Physical Surface(20) = {blk[2]};
Physical Surface(21) = {blk[4]};
Physical Surface(22) = {blk[5]};
Physical Surface(23) = {blk[3]};
Physical Surface(24) = {2};
Physical Surface(25) = {blk[0]};
