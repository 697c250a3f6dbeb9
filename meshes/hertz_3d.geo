// Hertz contact of an elastic sphere on an elastic block, in 3D: the
// quarter x >= 0, y >= 0 of the problem (the planes x = 0 and y = 0 are
// planes of symmetry), built with gmsh's OpenCASCADE kernel and meshed with
// structured (transfinite) hexahedra.
//
// Body 1 (physical volume 1): the part of a sphere of radius R, centred on
// the z axis at height R - d0, under the plane z = zt and inside the
// column [0, s] x [0, s]: a punch with a spherical end. Its lowest point
// dips d0 below the block's top (a small overlap, as in meshes/hertz.geo:
// in small strain the punch's vertical rigid-body translation absorbs it).
// Hertz's solution needs the sphere only near the contact (radius a << s).
// Body 2 (physical volume 2): the block [0, L] x [0, L] x [-H, 0].
//
// Boundary tags (physical surfaces):
//   10 the spherical end (the slave),   11 the punch's top z = zt (load),
//   12 the punch's plane x = 0,         13 its plane y = 0,
//   14 the punch's sides x = s, y = s,
//   20 the block's top (master),        21 the block's bottom,
//   22 the block's plane x = 0,         23 its plane y = 0,
//   24 the block's far sides.
// Lines graded geometrically towards the contact: n x n x nz cells in the
// punch (ratio rs), m x m x mz in the block (ratio rb).
//
// The sphere is turned so that its poles lie on the y axis: OpenCASCADE's
// sphere has a pole (a degenerate point of its surface) on its axis, which
// would otherwise be the point of contact.
SetFactory("OpenCASCADE");
DefineConstant[ R = 1, s = 0.5, zt = 0.5, L = 2, H = 2, d0 = 2e-4,
                n = 20, nz = 14, rs = 1.1, m = 20, mz = 14, rb = 1.2 ];

Sphere(1) = {0, 0, R - d0, R};
Rotate {{1, 0, 0}, {0, 0, R - d0}, Pi / 2} { Volume{1}; }
Box(2) = {0, 0, -d0, s, s, zt + d0};
BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Box(4) = {0, 0, -H, L, L, H};

// The lines graded: each runs along x, y or z (the coordinate that changes
// most between its ends), its cells growing by `ratio` from the end nearer
// the plane of that coordinate through the origin.
Macro Grade
  For i In {0 : #curves[] - 1}
    ends[] = PointsOf{ Curve{curves[i]}; };
    p[] = Point{ends[0]};
    q[] = Point{ends[1]};
    k = 0;
    best = -1;
    For c In {0 : 2}
      If (Fabs(q[c] - p[c]) > best)
        best = Fabs(q[c] - p[c]);
        k = c;
      EndIf
    EndFor
    count = (k == 2) ? cz : cxy;
    If (Fabs(p[k]) <= Fabs(q[k]))
      Transfinite Curve{curves[i]} = count + 1 Using Progression ratio;
    Else
      Transfinite Curve{-curves[i]} = count + 1 Using Progression ratio;
    EndIf
  EndFor
Return

curves[] = Abs(Boundary{ Surface{ Abs(Boundary{ Volume{3}; }) }; });
cxy = n; cz = nz; ratio = rs; Call Grade;
curves[] = Abs(Boundary{ Surface{ Abs(Boundary{ Volume{4}; }) }; });
cxy = m; cz = mz; ratio = rb; Call Grade;
Transfinite Surface{:};
Recombine Surface{:};
Transfinite Volume{:};

// The surfaces, found by where they lie.
e = 1e-6;
top[] = Surface In BoundingBox{-e, -e, -e, L + e, L + e, e};
bottom[] = Surface In BoundingBox{-e, -e, -H - e, L + e, L + e, -H + e};
block_x0[] = Surface In BoundingBox{-e, -e, -H - e, e, L + e, e};
block_y0[] = Surface In BoundingBox{-e, -e, -H - e, L + e, e, e};
block_far[] = Surface In BoundingBox{L - e, -e, -H - e, L + e, L + e, e};
block_far[] += Surface In BoundingBox{-e, L - e, -H - e, L + e, L + e, e};
load[] = Surface In BoundingBox{-e, -e, zt - e, s + e, s + e, zt + e};
punch_x0[] = Surface In BoundingBox{-e, -e, -d0 - e, e, s + e, zt + e};
punch_y0[] = Surface In BoundingBox{-e, -e, -d0 - e, s + e, e, zt + e};
punch_far[] = Surface In BoundingBox{s - e, -e, -d0 - e, s + e, s + e, zt + e};
punch_far[] += Surface In BoundingBox{-e, s - e, -d0 - e, s + e, s + e, zt + e};
sphere[] = Abs(Boundary{ Volume{3}; });
sphere[] -= {load[], punch_x0[], punch_y0[], punch_far[]};

Physical Volume(1) = {3};
Physical Volume(2) = {4};
Physical Surface(10) = {sphere[]};
Physical Surface(11) = {load[]};
Physical Surface(12) = {punch_x0[]};
Physical Surface(13) = {punch_y0[]};
Physical Surface(14) = {punch_far[]};
Physical Surface(20) = {top[]};
Physical Surface(21) = {bottom[]};
Physical Surface(22) = {block_x0[]};
Physical Surface(23) = {block_y0[]};
Physical Surface(24) = {block_far[]};
