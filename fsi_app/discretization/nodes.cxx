#include "nodes.h"
#include "mesh/mesh.h"
#include <petscds.h>

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
  if (point < vStart || point >= vEnd) { /* an edge: the midpoint of its vertices */
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
  PetscCall(VecRestoreArrayRead(coords, &xa));
  PetscFunctionReturn(0);
}

/* The constrained nodes of a DM, found once (label closures and node positions cost more than
   a residual) and kept on the DM: per boundary condition, the local offsets, components and
   positions of its nodes. */
struct EssentialNodes {
  struct Condition {
    PetscErrorCode (*g)(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *);
    void                  *ctx;
    std::vector<PetscInt>  comps;                 /* empty: every component */
    std::vector<PetscInt>  offset, dof;           /* per node */
    std::vector<PetscReal> x;                     /* 3 per node */
  };
  std::vector<Condition> conditions;
};

static PetscErrorCode DestroyEssentialNodes(void *ctx)
{
  delete (EssentialNodes *)ctx;
  return 0;
}

static PetscErrorCode GetEssentialNodes(DM dm, EssentialNodes **nodes)
{
  PetscContainer container;
  PetscDS        ds;
  PetscSection   section;
  PetscInt       nb;

  PetscFunctionBegin;
  PetscCall(PetscObjectQuery((PetscObject)dm, "fsi_essential_nodes", (PetscObject *)&container));
  if (container) {
    PetscCall(PetscContainerGetPointer(container, (void **)nodes));
    PetscFunctionReturn(0);
  }
  auto *en = new EssentialNodes;
  PetscCall(DMGetDS(dm, &ds));
  PetscCall(DMGetLocalSection(dm, &section));
  PetscCall(PetscDSGetNumBoundary(ds, &nb));
  for (PetscInt b = 0; b < nb; b++) {
    DMBoundaryConditionType type;
    DMLabel                 label;
    PetscInt                nv, field, nc;
    const PetscInt         *values, *comps;
    void (*func)(void), (*func_t)(void);
    void                     *ctx;
    EssentialNodes::Condition c;
    PetscCall(PetscDSGetBoundary(ds, b, nullptr, &type, nullptr, &label, &nv, &values, &field, &nc, &comps, &func, &func_t, &ctx));
    if (type != DM_BC_ESSENTIAL || !func) continue;
    c.g = (PetscErrorCode(*)(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *))func, c.ctx = ctx;
    c.comps.assign(comps, comps + nc);
    PetscCall(ForEachLabelPoint(label, std::vector<PetscInt>(values, values + nv), [&](PetscInt point) -> PetscErrorCode {
      PetscInt *closure = nullptr, ncl;
      PetscFunctionBegin;
      PetscCall(DMPlexGetTransitiveClosure(dm, point, PETSC_TRUE, &ncl, &closure));
      for (PetscInt j = 0; j < ncl; j++) {
        const PetscInt q = closure[2 * j];
        PetscInt       dof, off;
        PetscReal      x[3];
        PetscCall(PetscSectionGetFieldDof(section, q, field, &dof));
        if (!dof) continue;
        PetscCall(PetscSectionGetFieldOffset(section, q, field, &off));
        PetscCall(NodePosition(dm, q, x));
        c.offset.push_back(off), c.dof.push_back(dof), c.x.insert(c.x.end(), x, x + 3);
      }
      PetscCall(DMPlexRestoreTransitiveClosure(dm, point, PETSC_TRUE, &ncl, &closure));
      PetscFunctionReturn(0);
    }));
    en->conditions.push_back(c);
  }
  PetscCall(PetscContainerCreate(PetscObjectComm((PetscObject)dm), &container));
  PetscCall(PetscContainerSetPointer(container, en));
  PetscCall(PetscContainerSetUserDestroy(container, DestroyEssentialNodes));
  PetscCall(PetscObjectCompose((PetscObject)dm, "fsi_essential_nodes", (PetscObject)container));
  PetscCall(PetscContainerDestroy(&container));
  *nodes = en;
  PetscFunctionReturn(0);
}

PetscErrorCode InsertEssentialValues(DM dm, PetscReal t, Vec local)
{
  EssentialNodes *en;
  PetscScalar    *u;

  PetscFunctionBegin;
  PetscCall(GetEssentialNodes(dm, &en));
  PetscCall(VecGetArray(local, &u));
  for (const auto &c : en->conditions)
    for (size_t k = 0; k < c.offset.size(); k++) {
      PetscScalar val[3];
      PetscCall(c.g(3, t, &c.x[3 * k], c.dof[k], val, c.ctx));
      if (c.comps.empty())
        for (PetscInt i = 0; i < c.dof[k]; i++) u[c.offset[k] + i] = val[i];
      else /* only the listed components are constrained */
        for (PetscInt i : c.comps) u[c.offset[k] + i] = val[i];
    }
  PetscCall(VecRestoreArray(local, &u));
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
