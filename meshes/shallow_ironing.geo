// Shallow ironing (Code_Aster SSNP153; Fischer & Wriggers 2006; Hartmann,
// Oliver et al. 2009; Poulios & Renard 2015; Yastrebov 2011), plane strain:
// an elastic block with a rounded bottom pressed into an elastic foundation
// and slid along it (prm/shallow_ironing.prm).
//
// Body 1 (physical surface 1): the foundation [0, 12] x [0, 4].
// Body 2 (physical surface 2): the indenter, x in [0.2, 1.4], its top at
// y = 5.4, its vertical sides from y = 4.5 to 5.4, its bottom the circular
// arc of radius 0.75 centred at (0.8, 4.95) through (0.2, 4.5), (0.8, 4.2)
// and (1.4, 4.5): an initial gap of 0.2 above the foundation. These are the
// numbers of solids4foam's system/blockMeshDict.m4 (h1 unused, h2 = 4,
// a1 = 0.3, a2 = 0.2, a3 = 0.9, d1 = 0.2, d2 = 1.2, d3 = 10.6, r = 0.75;
// lengths in mm there, convertToMeters 0.001) and of Code_Aster's SSNP153,
// whose mesh is in these numbers taken as metres (see
// doc/data/shallow_ironing/reference/README.md).
//
// Boundary tags (physical curves):
//   10 the indenter's arc (contact slave),  11 its top (imposed motion),
//   12 its left side (x = 0.2),             13 its right side (x = 1.4),
//   20 the foundation's top (master),       21 its bottom (fixed),
//   22 its left side (x = 0),               23 its right side (x = 12).
//
// Structured quadrilaterals (transfinite, recombined): nx x ny in the
// foundation (solids4foam: 120 x 30), its rows shrinking towards the top by
// the factor 1/gy per row (gy = 1: uniform); na segments along the arc and
// across the top of the indenter, nh along its sides (solids4foam: 12 x 6).
// Every number can be set from the .prm: Mesh/Geo parameters = nx = 240.
DefineConstant[ nx = 120, ny = 30, gy = 1, na = 24, nh = 12 ];

// The foundation
Point(1) = {0, 0, 0};
Point(2) = {12, 0, 0};
Point(3) = {12, 4, 0};
Point(4) = {0, 4, 0};
Line(1) = {1, 2};   // bottom
Line(2) = {2, 3};   // right side, upwards
Line(3) = {3, 4};   // top
Line(4) = {4, 1};   // left side, downwards
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{2} = ny + 1 Using Progression 1 / gy;
Transfinite Curve{4} = ny + 1 Using Progression gy;
Transfinite Surface{1};
Recombine Surface{1};

// The indenter
Point(5) = {0.2, 4.5, 0};
Point(6) = {1.4, 4.5, 0};
Point(7) = {1.4, 5.4, 0};
Point(8) = {0.2, 5.4, 0};
Point(9) = {0.8, 4.95, 0};  // centre of the arc
Circle(5) = {5, 9, 6};      // the rounded bottom, through (0.8, 4.2)
Line(6) = {6, 7};           // right side
Line(7) = {7, 8};           // top
Line(8) = {8, 5};           // left side
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Transfinite Curve{5, 7} = na + 1;
Transfinite Curve{6, 8} = nh + 1;
Transfinite Surface{2};
Recombine Surface{2};

Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Curve(10) = {5};
Physical Curve(11) = {7};
Physical Curve(12) = {8};
Physical Curve(13) = {6};
Physical Curve(20) = {3};
Physical Curve(21) = {1};
Physical Curve(22) = {4};
Physical Curve(23) = {2};
