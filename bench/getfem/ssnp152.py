#!/usr/bin/python3
# SSNP152 (two concentric elastic rings in frictionless contact) with GetFEM 5.4
# ============================================================================
# An independent comparison model for the benchmark of ring_contact: the same
# problems as its modelisations B and C on the seed mesh (doc/intro.md,
# prm/ssnp152b.prm, prm/ssnp152c.prm), solved by GetFEM 5.4
# (Debian package python3-getfem, run with Debian's /usr/bin/python3).
#
# Usage:  /usr/bin/python3 bench/getfem/ssnp152.py b     (or c)
#         bash bench/getfem/run     (installs python3-getfem, median wall times)
#
# What it models
# - Geometry: outer ring 0.6 <= r <= 1.0, inner ring 0.2 <= r <= 0.6, two
#   separate GetFEM meshes (the interface nodes are duplicated, one copy per
#   ring), structured: 40 elements around (first vertex at angle 0) x 3
#   radially per ring, bilinear quadrilaterals (GT_QK(2,1): straight edges),
#   built vertex by vertex with Mesh.add_convex.
# - Material: Saint Venant-Kirchhoff (total Lagrangian, Green-Lagrange strain),
#   GetFEM's add_finite_strain_elasticity_brick('SaintVenant Kirchhoff'),
#   E = 1e9 Pa, nu = 0.2 in both rings, FEM_QK(2,1), 2x2 Gauss points.
#   B: plane strain (the brick's 2D law). C: plane stress, the same law with
#   lambda* = 2 lambda mu / (lambda + 2 mu).
#   Stresses are in units of SU = 1e9 Pa inside the model (E = 1): GetFEM's
#   Newton solver mixes the force residual with the constraint residuals
#   (in m^2) in one L1 norm, and in Pa its step control rejects correct
#   Newton steps (it does not converge at all with E = 1e9 in Pa).
# - Loads: imposed displacements only, from the analytic small-strain
#   solution: on r = R1 u = f(R1)(cos th, sin th); on r = R3 u = f(R3)(cos th,
#   sin th) (B: ramp p = 1e6 10^(t - 1.1), t = 0.1 k, k = 1..21) or, C,
#   p = 1e7 from the first step and the inner boundary turned by
#   alpha = (2 pi / 40) s, s = k/100, k = 1..100:
#   u = (R3 + f(R3))(cos(th + alpha), sin(th + alpha)) - (X, Y).
#   Imposed with add_Dirichlet_condition_with_multipliers (multiplier of
#   degree 1) and a data field on the displacement's mesh_fem, updated at
#   every step (nodal values = the formulas above at the boundary nodes).
# - Contact: frictionless (friction coefficient 0), GetFEM's
#   add_integral_large_sliding_contact_brick_raytracing (non-symmetric
#   version 0, augmentation r = 100 SU/m = 1e11 Pa/m, about 10 E/h, release
#   distance 0.1 m). r matters here: the frictionless projection asks for a
#   zero tangential multiplier relative to each slave segment's own normal,
#   which a continuous nodal multiplier cannot meet on a faceted circle (the
#   normals of two segments differ by 9 degrees at a node); the equation
#   (1/r) lambda_t + g n = 0 (weakly) then leaves gaps of the order of
#   sin(4.5 deg) |lambda| / r. Observed, B at p = 1e7 (Cauchy): -0.79 % with
#   r = 1, -0.50 % with 10, -0.476 % with 100, -0.473 % with 1000; but with
#   r = 1000 the Newton solver no longer converges in C. Slave =
#   inner ring's outer boundary (r = R2), master = outer ring's inner
#   boundary; the multiplier is a vector field (FEM_QK(2,1) restricted to the
#   slave boundary): the nominal traction, force per reference length.
#   The condition is integrated with Gauss points on the slave segments: 3 per
#   segment in B, 2 in C (the original's "Gauss" schemes of B and C).
#   Large sliding: the contact pairs are recomputed at every assembly.
#   Differences from ring_contact and the original: GetFEM pairs by ray
#   tracing along the current *slave* normal (not closest-point projection
#   onto the master with the master normal), the master normals are not
#   smoothed, the condition is the weighted (integral) Alart-Curnier one,
#   not nodal; and there is no nodal scheme here, one Gauss scheme per run.
# - Solver: Model.solve (GetFEM's Newton with step control, its default),
#   max_res 1e-8 (L1 residual relative to GetFEM's "external load" norm),
#   max_iter 50, default (direct, MUMPS for this size) linear solver,
#   'noisy' off. Every step starts from the previous solution.
# - Output: the contact pressure at node A (slave node at (0.6, 0)) at each
#   step (B) or at s = 1 (C): the nominal pressure -lambda.n (force per
#   reference length, what the multiplier is; n = current outward normal of
#   the slave at A) and the Cauchy pressure (divided by the stretch of the
#   slave surface at A, force per current length, what ring_contact reports
#   by default), their relative errors against the analytic sigma_n
#   (9 259 259.26 Pa at p = 1e7), the number of steps and of Newton
#   iterations, and the script's own times (import of numpy and getfem,
#   setup, steps; the interpreter's start is outside them: measure the
#   whole process with the shell, bench/getfem/run).
import math
import sys
import time

t_start = time.perf_counter()
import numpy as np
import getfem as gf

t_import = time.perf_counter()
gf.util_trace_level(1)

if len(sys.argv) != 2 or sys.argv[1] not in ('b', 'c'):
    sys.exit('usage: /usr/bin/python3 ssnp152.py b|c')
case = sys.argv[1]

# --- data ----------------------------------------------------------------
E, NU = 1.0e9, 0.2            # both rings [Pa]
R1, R2, R3 = 1.0, 0.6, 0.2    # radii [m]
NE, NR = 40, 3                # elements around, radially per ring
SU = 1.0e9                    # stress unit inside the model [Pa]
PLANE_STRAIN = case == 'b'
N_GAUSS = 3 if case == 'b' else 2   # Gauss points per slave segment
R_AUG = 100.0                # augmentation parameter [SU/m] (1e11 Pa/m)
RELEASE = 0.1                 # release distance of the ray tracing [m]
MAX_RES, MAX_ITER = 1e-8, 50

lam = E * NU / ((1 + NU) * (1 - 2 * NU)) / SU
mu = E / (2 * (1 + NU)) / SU
if not PLANE_STRAIN:
    lam = 2 * lam * mu / (lam + 2 * mu)


def analytic(p):
    """Small-strain solution for the equivalent pressure p: sigma_n, f(R1), f(R3)."""
    Ee, ne = (E / (1 - NU**2), NU / (1 - NU)) if PLANE_STRAIN else (E, NU)
    a, b, c = R1**2, R2**2, R3**2
    sn = 2 * p * a / (a * (1 + ne) + b * (1 - ne)
                      + (a - b) / (b - c) * (b * (1 - ne) + c * (1 + ne)))
    A1, B1 = (sn * b - p * a) / (a - b), (sn - p) * a * b / (a - b)
    A2, B2 = -sn * b / (b - c), -sn * b * c / (b - c)
    f1 = (A1 * (1 - ne) * R1 + B1 * (1 + ne) / R1) / Ee
    f3 = (A2 * (1 - ne) * R3 + B2 * (1 + ne) / R3) / Ee
    return sn, f1, f3


# --- meshes: one per ring, region 1 = r_in, region 2 = r_out -------------
GT = gf.GeoTrans('GT_QK(2,1)')
R_IN, R_OUT = 1, 2


def ring(rin, rout):
    m = gf.Mesh('empty', 2)
    rs = np.linspace(rin, rout, NR + 1)
    inner, outer = [], []
    for j in range(NE):
        t0, t1 = 2 * math.pi * j / NE, 2 * math.pi * ((j + 1) % NE) / NE
        for i in range(NR):
            # QK(2,1) vertex order: (xi, eta) = (0,0), (1,0), (0,1), (1,1),
            # with xi along r and eta along theta (positive Jacobian).
            P = [(rs[i], t0), (rs[i + 1], t0), (rs[i], t1), (rs[i + 1], t1)]
            pts = np.array([[r * math.cos(t) for r, t in P],
                            [r * math.sin(t) for r, t in P]])
            cv = int(m.add_convex(GT, pts)[0])
            if i == 0:
                inner.append([cv, 1])        # face 1: xi = 0
            if i == NR - 1:
                outer.append([cv, 0])        # face 0: xi = 1
    m.set_region(R_IN, np.array(inner).T)
    m.set_region(R_OUT, np.array(outer).T)
    assert m.nbpts() == NE * (NR + 1) and m.nbcvs() == NE * NR
    return m


m1 = ring(R2, R1)   # outer ring: R_IN = master (r = R2), R_OUT = S1R1
m2 = ring(R3, R2)   # inner ring: R_IN = S2R3, R_OUT = slave (r = R2)

mfu1 = gf.MeshFem(m1, 2); mfu1.set_classical_fem(1)
mfu2 = gf.MeshFem(m2, 2); mfu2.set_classical_fem(1)
mim1 = gf.MeshIm(m1, gf.Integ('IM_GAUSS_PARALLELEPIPED(2,3)'))
mim2 = gf.MeshIm(m2, gf.Integ('IM_GAUSS_PARALLELEPIPED(2,3)'))
# Faces of IM_GAUSS_PARALLELEPIPED(2,k) use IM_GAUSS1D(k): k = 2n-1 -> n points.
imc = gf.Integ('IM_GAUSS_PARALLELEPIPED(2,%d)' % (2 * N_GAUSS - 1))
mimc1, mimc2 = gf.MeshIm(m1, imc), gf.MeshIm(m2, imc)

# --- model ---------------------------------------------------------------
md = gf.Model('real')
md.add_fem_variable('u1', mfu1)
md.add_fem_variable('u2', mfu2)
md.add_initialized_data('params', [lam, mu])
md.add_finite_strain_elasticity_brick(mim1, 'u1', 'SaintVenant Kirchhoff', 'params')
md.add_finite_strain_elasticity_brick(mim2, 'u2', 'SaintVenant Kirchhoff', 'params')
md.add_fem_data('g1', mfu1)
md.add_fem_data('g2', mfu2)
md.add_Dirichlet_condition_with_multipliers(mim1, 'u1', 1, R_OUT, 'g1')
md.add_Dirichlet_condition_with_multipliers(mim2, 'u2', 1, R_IN, 'g2')

pre_mfl = gf.MeshFem(m2, 2); pre_mfl.set_classical_fem(1)
slave_dofs = pre_mfl.basic_dof_on_region(R_OUT)
mfl = gf.MeshFem('partial', pre_mfl, slave_dofs)
md.add_fem_variable('lambda', mfl)
md.add_initialized_data('r', [R_AUG])
md.add_initialized_data('fr', [0.0])
ib = md.add_integral_large_sliding_contact_brick_raytracing('r', RELEASE, 'fr', '', 0)
md.add_slave_contact_boundary_to_large_sliding_contact_brick(ib, mimc2, R_OUT, 'u2', 'lambda', '')
md.add_master_contact_boundary_to_large_sliding_contact_brick(ib, mimc1, R_IN, 'u1', '')

# --- imposed displacements at the dofs ----------------------------------
X1, X2 = mfu1.basic_dof_nodes(), mfu2.basic_dof_nodes()
comp1, comp2 = np.arange(mfu1.nbdof()) % 2, np.arange(mfu2.nbdof()) % 2


def imposed(X, comp, f, alpha=0.0):
    th, r = np.arctan2(X[1], X[0]), np.hypot(X[0], X[1])
    x = (r + f) * np.cos(th + alpha) - X[0]
    y = (r + f) * np.sin(th + alpha) - X[1]
    return np.where(comp == 0, x, y)


# --- node A and its two neighbours on the slave boundary ----------------
def node_dofs(X, x, y):
    d = np.nonzero(np.hypot(X[0] - x, X[1] - y) < 1e-9)[0]
    assert len(d) == 2
    return d


XL = pre_mfl.basic_dof_nodes()[:, slave_dofs]   # nodes of the reduced dofs
dA = node_dofs(XL, R2, 0.0)                      # lambda dofs at A
h = 2 * math.pi / NE
nodes = [(R2 * math.cos(a), R2 * math.sin(a)) for a in (-h, 0.0, h)]
du = [node_dofs(X2, x, y) for x, y in nodes]     # u2 dofs at A-, A, A+


def pressure_at_A():
    """Nominal and Cauchy contact pressure at A [Pa]."""
    L = md.variable('lambda')[dA] * SU
    U = md.variable('u2')
    x = [np.array(p) + U[d] for p, d in zip(nodes, du)]
    chord0 = 2 * R2 * math.sin(h / 2)
    stretch = 0.5 * (np.linalg.norm(x[1] - x[0]) + np.linalg.norm(x[2] - x[1])) / chord0
    n = np.zeros(2)
    for a, b in ((x[0], x[1]), (x[1], x[2])):     # outward segment normals
        t = (b - a) / np.linalg.norm(b - a)
        n += np.array([t[1], -t[0]])
    n /= np.linalg.norm(n)
    nominal = -float(L @ n)
    return nominal, nominal / stretch


newton = 0


def solve_step():
    global newton
    nit, converged = md.solve('max_res', MAX_RES, 'max_iter', MAX_ITER)
    newton += nit
    if not converged:
        sys.exit('Newton did not converge (%d iterations)' % nit)
    return nit


t_setup = time.perf_counter()
print('GetFEM SSNP152 %s: %s, %d unknowns, %d Gauss points per slave segment'
      % (case.upper(), 'plane strain' if PLANE_STRAIN else 'plane stress',
         md.nbdof(), N_GAUSS))
print('%5s %12s %7s %14s %14s %9s %9s' % ('step', 'p [Pa]', 'Newton', 'sigma_n [Pa]',
                                          'Cauchy [Pa]', 'err Cau.', 'err nom.'))
if case == 'b':
    steps = [(k, 1e6 * 10**(0.1 * k - 1.1), 0.0) for k in range(1, 22)]
else:
    steps = [(k, 1e7, k / 100.0) for k in range(1, 101)]
for k, p, s in steps:
    sn, f1, f3 = analytic(p)
    md.set_variable('g1', imposed(X1, comp1, f1))
    md.set_variable('g2', imposed(X2, comp2, f3, 2 * math.pi / NE * s))
    nit = solve_step()
    nominal, cauchy = pressure_at_A()
    if case == 'b' or k in (1, 25, 50, 75, 100):
        print('%5d %12.6g %7d %14.2f %14.2f %8.3f%% %8.3f%%'
              % (k, p, nit, sn, cauchy, 100 * (cauchy / sn - 1), 100 * (nominal / sn - 1)))
t_end = time.perf_counter()

print('model %s: %d steps, %d Newton iterations' % (case.upper(), len(steps), newton))
print('pressure at A (%s): Cauchy %.2f Pa (%+.3f %%), nominal %.2f Pa (%+.3f %%), '
      'analytic %.2f Pa' % ('step 21, p = 1e7' if case == 'b' else 's = 1', cauchy,
                            100 * (cauchy / sn - 1), nominal, 100 * (nominal / sn - 1), sn))
print('time in the script: import %.3f s, setup %.3f s, steps %.3f s, total %.3f s'
      % (t_import - t_start, t_setup - t_import, t_end - t_setup, t_end - t_start))
