// Two concentric quarter rings about the origin, the general problem's
// counterpart of the rings: the inner ring a <= r <= b (physical surface 1)
// and the outer ring d <= r <= c (physical surface 2), d = b + g. g > 0 is a
// gap, g < 0 an interference (the rings overlap by -g: a shrink fit).
// Each ring is a structured mesh (transfinite) with ni and no segments
// along its quarter arcs and nr cells across: ni != no gives non-matching
// meshes on the contact arcs, ni = no matching ones whose slave nodes face
// the master's vertices.
// Tags (physical curves): 10 the inner ring's outer arc (r = b), 11 its inner
// arc (r = a), 12 its side on y = 0, 13 its other side (x = 0 for the
// quarter); 20 the outer ring's inner arc (r = d), 21 its outer arc (r = c),
// 22 its side on y = 0, 23 its other side. `angle` (degrees, below 180) is
// the sector's: 90 by default, the quarter.
DefineConstant[ a = 0.5, b = 0.6, g = 1e-3, c = 0.7, ni = 20, no = 20,
                nr = 4, angle = 90 ];
d = b + g;
ca = Cos(angle * Pi / 180); sa = Sin(angle * Pi / 180);
If (angle == 90) // exactly on x = 0, as before the angle was a parameter
  ca = 0; sa = 1;
EndIf

Point(1) = {0, 0, 0};
// The inner ring
Point(2) = {a, 0, 0}; Point(3) = {b, 0, 0};
Point(4) = {b * ca, b * sa, 0}; Point(5) = {a * ca, a * sa, 0};
Line(1) = {2, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{2, 4} = ni + 1;
Transfinite Curve{1, 3} = nr + 1;
Transfinite Surface{1};
Recombine Surface{1};

// The outer ring
Point(6) = {d, 0, 0}; Point(7) = {c, 0, 0};
Point(8) = {c * ca, c * sa, 0}; Point(9) = {d * ca, d * sa, 0};
Line(5) = {6, 7};
Circle(6) = {7, 1, 8};
Line(7) = {8, 9};
Circle(8) = {9, 1, 6};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Transfinite Curve{6, 8} = no + 1;
Transfinite Curve{5, 7} = nr + 1;
Transfinite Surface{2};
Recombine Surface{2};

Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Curve(10) = {2};
Physical Curve(11) = {4};
Physical Curve(12) = {1};
Physical Curve(13) = {3};
Physical Curve(20) = {8};
Physical Curve(21) = {6};
Physical Curve(22) = {5};
Physical Curve(23) = {7};
