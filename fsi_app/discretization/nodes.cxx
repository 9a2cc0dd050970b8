// SPDX-License-Identifier: BSD-2-Clause
#include "nodes.h"
#include "mesh/mesh.h"

namespace fsi {

PetscErrorCode NodePosition(DM dm, PetscInt point, PetscReal x[3])
{
  Vec                coords;
  DM                 cdm;
  PetscSection       csec;
  PetscInt           vStart, vEnd, np = 1;
  const PetscInt    *pts = &point;
  const PetscScalar *xa;

  PetscFunctionBegin;
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &csec));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  if (point < vStart || point >= vEnd) { /* an edge: the midpoint of its vertices, or a curved edge's node */
    PetscCall(DMPlexGetCone(dm, point, &pts));
    np = 2;
  }
  PetscCall(VecGetArrayRead(coords, &xa));
  x[0] = x[1] = x[2] = 0;
  for (PetscInt k = 0; k < np; k++) {
    PetscInt off;
    PetscCall(PetscSectionGetOffset(csec, pts[k], &off));
    for (int d = 0; d < 3; d++) x[d] += PetscRealPart(xa[off + d]) / np;
  }
  if (np == 2) {
    PetscReal ends[2][3], node[3];
    for (PetscInt k = 0; k < 2; k++) {
      PetscInt off;
      PetscCall(PetscSectionGetOffset(csec, pts[k], &off));
      for (int d = 0; d < 3; d++) ends[k][d] = PetscRealPart(xa[off + d]);
    }
    if (MeshEdgeNode(dm, ends[0], ends[1], node))
      for (int d = 0; d < 3; d++) x[d] = node[d];
  }
  PetscCall(VecRestoreArrayRead(coords, &xa));
  PetscFunctionReturn(0);
}

PetscErrorCode RigidBodyModes(DM dm, PetscInt field, MatNullSpace *nsp)
{
  PetscSection section;
  Vec          local, modes[6];
  PetscInt     pStart, pEnd;

  PetscFunctionBegin;
  PetscCall(DMGetLocalSection(dm, &section));
  PetscCall(PetscSectionGetChart(section, &pStart, &pEnd));
  PetscCall(DMGetLocalVector(dm, &local));
  for (int m = 0; m < 6; m++) {
    PetscScalar *u;
    PetscCall(VecSet(local, 0.0));
    PetscCall(VecGetArray(local, &u));
    for (PetscInt p = pStart; p < pEnd; p++) {
      PetscInt dof, off;
      PetscCall(PetscSectionGetFieldDof(section, p, field, &dof));
      if (dof != 3) continue;
      PetscCall(PetscSectionGetFieldOffset(section, p, field, &off));
      PetscReal x[3];
      PetscCall(NodePosition(dm, p, x));
      const PetscReal r[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-x[1], x[0], 0}, {0, -x[2], x[1]}, {x[2], 0, -x[0]}};
      for (int c = 0; c < 3; c++) u[off + c] = r[m][c];
    }
    PetscCall(VecRestoreArray(local, &u));
    PetscCall(DMCreateGlobalVector(dm, &modes[m]));
    PetscCall(DMLocalToGlobal(dm, local, INSERT_VALUES, modes[m])); /* constrained dofs drop out */
    for (int k = 0; k < m; k++) {                                 /* Gram-Schmidt */
      PetscScalar dot;
      PetscCall(VecDot(modes[m], modes[k], &dot));
      PetscCall(VecAXPY(modes[m], -dot, modes[k]));
    }
    PetscCall(VecNormalize(modes[m], nullptr));
  }
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscCall(MatNullSpaceCreate(PetscObjectComm((PetscObject)dm), PETSC_FALSE, 6, modes, nsp));
  for (auto &v : modes) PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

} // namespace fsi
