#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""PCGDSW from petsc4py: Q1 linear elasticity on the unit cube, clamped at x = 0, under gravity,
with the rigid-body modes as the operator's near-null space -- the problem of elasticity.cxx, so
the two give the same iteration counts. The solver comes from the options:

  mpiexec -n 2 python3 elasticity.py -dll_append <prefix>/lib/libpetscgdsw.so -pc_type gdsw

-dll_append loads the library into PETSc, which registers PCGDSW; any other -ksp_*/-pc_* option
works as in a C program (-ksp_view, -pc_gdsw_coarse_space rgdsw, ...).
Options: -n <8> elements per direction, -nu <0.3> Poisson ratio (Young's modulus 1)."""
import sys

import petsc4py

petsc4py.init(sys.argv)
from petsc4py import PETSc  # noqa: E402 (after init: PETSc reads the options there)
import numpy as np  # noqa: E402


def element_stiffness(h, nu):
    """Stiffness of the element [0, h]^3 for E = 1: 2 x 2 x 2 Gauss points, exact for Q1. Dofs
    node by node (3 a + i for component i of corner a); corner a sits at (a & 1, a >> 1 & 1,
    a >> 2 & 1) h."""
    lam, mu = nu / ((1 + nu) * (1 - 2 * nu)), 1 / (2 * (1 + nu))
    sign = np.array([[1.0 if a >> d & 1 else -1.0 for d in range(3)] for a in range(8)])
    K = np.zeros((24, 24))
    for q in range(8):
        xi = sign[q] / np.sqrt(3)
        # gradients of the 8 trilinear shape functions at xi (d/dx = 2/h d/dxi)
        dN = np.array([[sign[a, d] / 8 * np.prod([1 + sign[a, e] * xi[e] for e in range(3) if e != d]) * 2 / h
                        for d in range(3)] for a in range(8)])
        B = np.zeros((6, 24))
        for a in range(8):
            x, y, z = dN[a]
            B[:, 3 * a:3 * a + 3] = [[x, 0, 0], [0, y, 0], [0, 0, z], [y, x, 0], [0, z, y], [z, 0, x]]
        D = np.zeros((6, 6))
        D[:3, :3] = lam
        D[range(3), range(3)] += 2 * mu
        D[range(3, 6), range(3, 6)] = mu
        K += (h / 2) ** 3 * B.T @ D @ B
    return K


def fail(message):
    """Stop every rank with exit status 1; rank 0 alone prints why (each rank reaches the same
    verdict, and a message per rank would repeat it)."""
    if PETSc.COMM_WORLD.getRank() == 0:
        print(message, file=sys.stderr, flush=True)
    sys.exit(1)


def main():
    opts = PETSc.Options()
    n, nu = opts.getInt("n", 8), opts.getReal("nu", 0.3)
    if n < 1 or not 0 <= nu < 0.5:
        fail(f"elasticity.py: -n {n} -nu {nu}: need at least one element and 0 <= nu < 0.5")
    comm = PETSc.COMM_WORLD
    rank, size = comm.getRank(), comm.getSize()
    layer = (n + 1) ** 2
    k0, k1 = (n + 1) * rank // size, (n + 1) * (rank + 1) // size  # node layers in z this rank owns
    nloc = (k1 - k0) * layer

    A = PETSc.Mat().createAIJ(((3 * nloc, None), (3 * nloc, None)), bsize=3, nnz=(81, 81), comm=comm)
    b = A.createVecLeft()
    h = 1.0 / n
    K = element_stiffness(h, nu)
    fe = np.tile([0.0, 0.0, -h ** 3 / 8], 8)
    for k in range(k0, min(k1, n)):  # element layers whose lower nodes this rank owns
        for j in range(n):
            for i in range(n):
                nodes = [i + (a & 1) + (n + 1) * (j + (a >> 1 & 1) + (n + 1) * (k + (a >> 2 & 1))) for a in range(8)]
                rows = np.array([3 * v + d for v in nodes for d in range(3)], dtype=PETSc.IntType)
                A.setValues(rows, rows, K, addv=PETSc.InsertMode.ADD_VALUES)
                b.setValues(rows, fe, addv=PETSc.InsertMode.ADD_VALUES)
    A.assemble()
    b.assemble()

    # the rigid-body modes from the owned nodes' coordinates
    g = np.arange(k0 * layer, k1 * layer)
    xyz = np.stack([g % (n + 1), g // (n + 1) % (n + 1), g // layer], axis=1) * h
    coords = PETSc.Vec().createWithArray(xyz.ravel(), bsize=3, comm=comm)
    A.setNearNullSpace(PETSc.NullSpace().createRigidBody(coords))

    x = A.createVecRight()
    clamped = np.array([3 * v + d for v in g[g % (n + 1) == 0] for d in range(3)], dtype=PETSc.IntType)
    A.zeroRowsColumns(clamped, 1.0, x, b)

    ksp = PETSc.KSP().create(comm)
    ksp.setOperators(A)
    ksp.setType("cg")
    ksp.setTolerances(rtol=1e-8, max_it=1000)
    ksp.setFromOptions()
    ksp.solve(b, x)
    r = b.duplicate()
    A.mult(x, r)
    r.aypx(-1.0, b)
    PETSc.Sys.Print(f"dofs {A.getSize()[0]} ranks {size} pc {ksp.getPC().getType()} iterations {ksp.getIterationNumber()} "
                    f"reason {ksp.getConvergedReason()} residual {r.norm() / b.norm():.3e}", comm=comm)
    if ksp.getConvergedReason() < 0:
        fail(f"elasticity.py: the solve diverged (KSPConvergedReason {ksp.getConvergedReason()})")


if __name__ == "__main__":
    main()
