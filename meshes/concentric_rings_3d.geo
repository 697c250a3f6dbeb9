// The two concentric quarter rings of concentric_rings.geo (the same
// geometry and parameters, repeated here) extruded through one layer of
// hexahedra of height h: the inner ring is physical
// volume 1, the outer ring volume 2. The tags of the 2D model become those
// of the extruded surfaces: 10 the inner ring's outer face (r = b), 11 its
// inner face (r = a), 12 its side on y = 0, 13 its other side; 20 the outer
// ring's inner face (r = d), 21 its outer face (r = c), 22 and 23 its sides;
// 30 the rings' bottoms (z = 0) and 31 their tops (z = h).
// The rings as in concentric_rings.geo.
DefineConstant[ a = 0.5, b = 0.6, g = 1e-3, c = 0.7, ni = 20, no = 20,
                nr = 4, angle = 90, h = 0.05 ];
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

// The outer ring. Rings that touch (g = 0) would share their points on
// r = b (gmsh merges coincident points): the outer ring is then built
// turned by 180 degrees about z, extruded, and turned back with automatic
// coherence off (below), two bodies whose faces meet.
f = (g == 0) ? -1 : 1;
Point(6) = {f * d, 0, 0}; Point(7) = {f * c, 0, 0};
Point(8) = {f * c * ca, f * c * sa, 0}; Point(9) = {f * d * ca, f * d * sa, 0};
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

// Extrude gives the top, the volume, then the sides along the curve loop:
// the inner ring's lines 1 (y = 0), 2 (r = b), 3, 4 (r = a), the outer
// ring's 5 (y = 0), 6 (r = c), 7, 8 (r = d).
inner[] = Extrude {0, 0, h} { Surface{1}; Layers{1}; Recombine; };
outer[] = Extrude {0, 0, h} { Surface{2}; Layers{1}; Recombine; };
If (g == 0)
  Geometry.AutoCoherence = 0;
  Rotate {{0, 0, 1}, {0, 0, 0}, Pi} { Volume{outer[1]}; }
EndIf
Physical Volume(1) = {inner[1]};
Physical Volume(2) = {outer[1]};
Physical Surface(10) = {inner[3]};
Physical Surface(11) = {inner[5]};
Physical Surface(12) = {inner[2]};
Physical Surface(13) = {inner[4]};
Physical Surface(20) = {outer[5]};
Physical Surface(21) = {outer[3]};
Physical Surface(22) = {outer[2]};
Physical Surface(23) = {outer[4]};
Physical Surface(30) = {1, 2};
Physical Surface(31) = {inner[0], outer[0]};
