// SSNP152: two concentric rings with duplicated interface nodes.
//
// The program meshes it itself when it is the 'Mesh file' (gmsh's library,
// in 2d, with the element order of the displacement degrees); the numbers
// below can be set from the .prm:
//
//   set Mesh file      = ssnp152.geo
//   set Geo parameters = Ne = 80, Nr1 = 6, Nr2 = 6
//
// or on gmsh's command line (-setnumber NAME VALUE), e.g. the seed mesh
//   gmsh -2 -format msh22 ssnp152.geo -setnumber Ne 40 -o rings-40.msh
//
// Parameters:
//   Ne          elements around every circle (a multiple of 4), first
//               vertex at angle 0
//   Nr1, Nr2    elements across the outer (R2 <= r <= R1) and the inner
//               ring (R3 <= r <= R2)
//   R1, R2, R3  the radii [m] (the .prm's must be the same: the program
//               checks the boundaries against them)
//   order       element order for gmsh's command line: 1 (4-node quads) or
//               2 (9-node quads, mid-side nodes on the circles); the program
//               sets the order itself
// Physical tags, as the original Code_Aster test: 100 outer ring (C1),
// 101 inner ring (C2), 200 r = R1 (S1R1), 300 outer ring at r = R2 (S1R2),
// 400 inner ring at r = R2 (S2R2), 500 r = R3 (S2R3).
// The two rings are separate bodies: each has its own points and curves on
// r = R2, and automatic coherence is off so that gmsh does not merge them.
SetFactory("Built-in");
Geometry.AutoCoherence = 0;

DefineConstant[ Ne = 40, Nr1 = 3, Nr2 = 3, order = 1 ];
DefineConstant[ R1 = 1.0, R2 = 0.6, R3 = 0.2 ];

If (Ne % 4 != 0)
  Error("Ne = %g: the number of elements around must be a multiple of 4", Ne);
  Abort;
EndIf

r_in[]      = {R2, R3};
r_out[]     = {R1, R2};
n_radial[]  = {Nr1, Nr2};
tag_body[]  = {100, 101};
tag_in[]    = {300, 500};
tag_out[]   = {200, 400};

For ring In {0:1}
  center = newp; Point(center) = {0, 0, 0};
  For q In {0:3}
    p_in[q]  = newp; Point(p_in[q])  = {r_in[ring] * Cos(q * Pi / 2),
                                        r_in[ring] * Sin(q * Pi / 2), 0};
    p_out[q] = newp; Point(p_out[q]) = {r_out[ring] * Cos(q * Pi / 2),
                                        r_out[ring] * Sin(q * Pi / 2), 0};
  EndFor
  For q In {0:3}
    arc_in[q]  = newl; Circle(arc_in[q])  = {p_in[q], center, p_in[(q + 1) % 4]};
    arc_out[q] = newl; Circle(arc_out[q]) = {p_out[q], center, p_out[(q + 1) % 4]};
    radial[q]  = newl; Line(radial[q])    = {p_in[q], p_out[q]};
  EndFor
  surfaces[] = {};
  For q In {0:3}
    loop = newll;
    Curve Loop(loop) = {radial[q], arc_out[q], -radial[(q + 1) % 4], -arc_in[q]};
    s = news; Plane Surface(s) = {loop};
    surfaces[] += s;
  EndFor
  Transfinite Curve{arc_in[], arc_out[]} = Ne / 4 + 1;
  Transfinite Curve{radial[]} = n_radial[ring] + 1;
  Transfinite Surface{surfaces[]};
  Recombine Surface{surfaces[]};
  Physical Surface(tag_body[ring]) = surfaces[];
  Physical Curve(tag_in[ring])     = arc_in[];
  Physical Curve(tag_out[ring])    = arc_out[];
EndFor

Mesh.ElementOrder = order;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
