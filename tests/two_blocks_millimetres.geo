// The two blocks of meshes/two_blocks.geo (angle 0, no gap, nl = 5,
// nu = 7, nh = 3) drawn in millimetres, with the factor gmsh applies when
// it saves a mesh: the model is the one in metres
// (tests/two_blocks_millimetres.prm.in).
Mesh.ScalingFactor = 0.001;
Point(1) = {0, -500, 0};    Point(2) = {1000, -500, 0};
Point(3) = {1000, 0, 0};    Point(4) = {0, 0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Point(5) = {0, 0, 0};       Point(6) = {1000, 0, 0};
Point(7) = {1000, 500, 0};  Point(8) = {0, 500, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{1, 3} = 6; Transfinite Curve{2, 4} = 4;
Transfinite Curve{5, 7} = 8; Transfinite Curve{6, 8} = 4;
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
