// Two blocks pressed together in 3D, the contact patch test written as a
// general problem: the lower block [0, 1]^2 x [-0.5, 0] (physical volume 1,
// its top the master, 20) and the upper block [0, 1]^2 x [0, 0.5] (physical
// volume 2, its bottom the slave, 10), with nl x nl and nu x nu hexahedra
// across the interface (non-matching meshes) and nh layers each. Tags: 21
// the lower block's bottom, 11 the upper block's top; 12 and 22 the sides
// x = 0, 13 and 23 the sides y = 0, 14 and 24 the other two sides.
//
// Each block is built point by point (Macro MakeBlock), not extruded: gmsh's
// extrusion merges coincident points, and the two blocks must not share
// the points of their interface.
DefineConstant[ nl = 5, nu = 4, nh = 2 ];

// A block [0, 1]^2 x [z0, z0 + 0.5] of n x n x nh hexahedra; its entities
// numbered from o. Sets bottom, top, x0, y0, others: its faces.
Macro MakeBlock
  For k In {0:1}
    z = z0 + 0.5 * k;
    Point(o + 4 * k + 1) = {0, 0, z}; Point(o + 4 * k + 2) = {1, 0, z};
    Point(o + 4 * k + 3) = {1, 1, z}; Point(o + 4 * k + 4) = {0, 1, z};
    For i In {1:4}
      Line(o + 4 * k + i) = {o + 4 * k + i, o + 4 * k + (i % 4) + 1};
    EndFor
  EndFor
  For i In {1:4}
    Line(o + 8 + i) = {o + i, o + 4 + i};
  EndFor
  // bottom, top, then the sides along lines 1-4 (y = 0, x = 1, y = 1, x = 0)
  Curve Loop(o + 1) = {o + 1, o + 2, o + 3, o + 4};
  Curve Loop(o + 2) = {o + 5, o + 6, o + 7, o + 8};
  For i In {1:4}
    Curve Loop(o + 2 + i) = {o + i, o + 8 + (i % 4) + 1, -(o + 4 + i), -(o + 8 + i)};
  EndFor
  For i In {1:6}
    Plane Surface(o + i) = {o + i};
  EndFor
  Surface Loop(o + 1) = {o + 1 : o + 6};
  Volume(o + 1) = {o + 1};
  Transfinite Curve{o + 1 : o + 8} = n + 1;
  Transfinite Curve{o + 9 : o + 12} = nh + 1;
  Transfinite Surface{o + 1 : o + 6};
  Recombine Surface{o + 1 : o + 6};
  Transfinite Volume{o + 1};
  bottom = o + 1; top = o + 2; y0 = o + 3; x0 = o + 6;
  others[] = {o + 4, o + 5};
Return

o = 0; z0 = -0.5; n = nl; Call MakeBlock;
Physical Volume(1) = {o + 1};
Physical Surface(21) = {bottom};
Physical Surface(20) = {top};
Physical Surface(22) = {x0};
Physical Surface(23) = {y0};
Physical Surface(24) = {others[]};
o = 100; z0 = 0; n = nu; Call MakeBlock;
Physical Volume(2) = {o + 1};
Physical Surface(10) = {bottom};
Physical Surface(11) = {top};
Physical Surface(12) = {x0};
Physical Surface(13) = {y0};
Physical Surface(14) = {others[]};
