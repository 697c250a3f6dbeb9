// Three blocks stacked, two contact interfaces: the lower block [0, 1] x
// [-0.5, 0] (physical surface 1), the middle one [0, 1] x [0, 0.5] (2) and
// the upper one [0, 1] x [0.5, 1] (3), with nl, nm and nu elements along
// their length (non-matching at both interfaces) and nh across. Tags: 20
// the lower block's top, 10 the middle block's bottom, 40 its top, 30 the
// upper block's bottom; 21 the lower block's bottom, 31 the upper block's
// top; 22, 12, 32 the left sides (x = 0) and 23, 13, 33 the right sides.
DefineConstant[ nl = 5, nm = 7, nu = 4, nh = 3 ];
For b In {0 : 2}
  y0 = -0.5 + 0.5 * b;
  p = newp;
  Point(p) = {0, y0, 0};     Point(p + 1) = {1, y0, 0};
  Point(p + 2) = {1, y0 + 0.5, 0}; Point(p + 3) = {0, y0 + 0.5, 0};
  l = newl;
  Line(l) = {p, p + 1}; Line(l + 1) = {p + 1, p + 2};
  Line(l + 2) = {p + 2, p + 3}; Line(l + 3) = {p + 3, p};
  Curve Loop(b + 1) = {l, l + 1, l + 2, l + 3};
  Plane Surface(b + 1) = {b + 1};
  n = (b == 0) ? nl : ((b == 1) ? nm : nu);
  Transfinite Curve{l, l + 2} = n + 1;
  Transfinite Curve{l + 1, l + 3} = nh + 1;
  Transfinite Surface{b + 1};
  Recombine Surface{b + 1};
  Physical Surface(b + 1) = {b + 1};
  bottom[b] = l; right[b] = l + 1; top[b] = l + 2; left[b] = l + 3;
EndFor
Physical Curve(21) = {bottom[0]}; Physical Curve(20) = {top[0]};
Physical Curve(22) = {left[0]};   Physical Curve(23) = {right[0]};
Physical Curve(10) = {bottom[1]}; Physical Curve(40) = {top[1]};
Physical Curve(12) = {left[1]};   Physical Curve(13) = {right[1]};
Physical Curve(30) = {bottom[2]}; Physical Curve(31) = {top[2]};
Physical Curve(32) = {left[2]};   Physical Curve(33) = {right[2]};
