// Two blocks pressed together, the contact patch test written as a general
// problem: the lower block [0, 1] x [-0.5, 0] (physical surface 1, its top
// the master, 20) and the upper block [0, 1] x [0, 0.5] (physical surface 2,
// its bottom the slave, 10), with nl and nu elements along the interface
// (non-matching meshes). Tags: 21 the lower block's bottom, 22 and 12 the
// left sides (x = 0), 11 the upper block's top, 13 and 23 the right sides.
// clockwise = 1 draws the lower block's outline clockwise, so that gmsh
// writes its cells clockwise (the program must reorient them). angle turns
// both blocks about the origin by that many degrees (an inclined interface
// and inclined supports: the interface then runs along (cos a, sin a)).
// gap > 0 lifts the upper block off the lower one by that distance along the
// interface's normal (< 0: the blocks overlap by that much).
DefineConstant[ nl = 5, nu = 7, nh = 3, clockwise = 0, angle = 0, gap = 0 ];
// (Each point turned here: gmsh's Rotate would merge the blocks' coincident
// points, and the two blocks would share their interface.)
c = Cos(angle * Pi / 180); s = Sin(angle * Pi / 180);
Point(1) = {0.5 * s, -0.5 * c, 0}; Point(2) = {c + 0.5 * s, s - 0.5 * c, 0};
Point(3) = {c, s, 0};              Point(4) = {0, 0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
If (clockwise)
  Curve Loop(1) = {-4, -3, -2, -1};
Else
  Curve Loop(1) = {1, 2, 3, 4};
EndIf
Plane Surface(1) = {1};
gx = -gap * s; gy = gap * c;
Point(5) = {gx, gy, 0};            Point(6) = {c + gx, s + gy, 0};
Point(7) = {c - 0.5 * s + gx, s + 0.5 * c + gy, 0};
Point(8) = {-0.5 * s + gx, 0.5 * c + gy, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{1, 3} = nl + 1; Transfinite Curve{2, 4} = nh + 1;
Transfinite Curve{5, 7} = nu + 1; Transfinite Curve{6, 8} = nh + 1;
Transfinite Surface{1}; Transfinite Surface{2};
Recombine Surface{1, 2};
Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Curve(20) = {3};
Physical Curve(21) = {1};
Physical Curve(22) = {4};
Physical Curve(23) = {2};
Physical Curve(10) = {5};
Physical Curve(11) = {7};
Physical Curve(12) = {8};
Physical Curve(13) = {6};
