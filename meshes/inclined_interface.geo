// The square [0, 1] x [-0.5, 0.5] cut into two bodies by the inclined line
// from (0, -0.2) to (1, 0.2): the lower body (physical surface 3) and the
// upper one (4), with n1 and n2 elements along the interface (non-matching)
// and m across each body. The supports' ends lie on the contact surfaces.
// Tags: 31 bottom, 32 lower right, 33 the lower body's inclined top, 34
// lower left; 41 the upper body's inclined bottom, 42 upper right, 43 top,
// 44 upper left.
DefineConstant[ n1 = 5, n2 = 8, m = 4 ];
Point(1) = {0, -0.5, 0}; Point(2) = {1, -0.5, 0};
Point(3) = {1, 0.2, 0};  Point(4) = {0, -0.2, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
// (Points of their own: the bodies share no vertex.)
Point(5) = {0, -0.2, 0}; Point(6) = {1, 0.2, 0};
Point(7) = {1, 0.5, 0};  Point(8) = {0, 0.5, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{1, 3} = n1 + 1; Transfinite Curve{2, 4} = m + 1;
Transfinite Curve{5, 7} = n2 + 1; Transfinite Curve{6, 8} = m + 1;
Transfinite Surface{1}; Transfinite Surface{2};
Recombine Surface{1, 2};
Physical Surface(3) = {1};
Physical Surface(4) = {2};
Physical Curve(31) = {1};
Physical Curve(32) = {2};
Physical Curve(33) = {3};
Physical Curve(34) = {4};
Physical Curve(41) = {5};
Physical Curve(42) = {6};
Physical Curve(43) = {7};
Physical Curve(44) = {8};
