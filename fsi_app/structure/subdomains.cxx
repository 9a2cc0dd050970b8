// SPDX-License-Identifier: BSD-2-Clause
#include "subdomains.h"
#include "discretization/nodes.h"
#include <petscgdsw.h>
#include <metis.h>
#include <algorithm>
#include <string>
#include <vector>

namespace fsi {

/* Local cells of the region and the dual graph between them (cells sharing a face). */
static PetscErrorCode RegionCells(DM dm, const char *region, std::vector<PetscInt> &cells, std::vector<idx_t> &xadj, std::vector<idx_t> &adj)
{
  PetscInt cStart, cEnd;
  DMLabel  label = nullptr;

  PetscFunctionBegin;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  if (region && region[0]) PetscCall(DMGetLabel(dm, (std::string("region_") + region).c_str(), &label));
  std::vector<PetscInt> local(cEnd - cStart, -1);
  for (PetscInt c = cStart; c < cEnd; c++) {
    PetscInt v = 1;
    if (label) PetscCall(DMLabelGetValue(label, c, &v));
    if (v == 1) local[c - cStart] = (PetscInt)cells.size(), cells.push_back(c);
  }
  xadj.assign(1, 0);
  for (PetscInt c : cells) {
    const PetscInt *faces;
    PetscInt        nf;
    PetscCall(DMPlexGetConeSize(dm, c, &nf));
    PetscCall(DMPlexGetCone(dm, c, &faces));
    for (PetscInt f = 0; f < nf; f++) {
      const PetscInt *support;
      PetscInt        ns;
      PetscCall(DMPlexGetSupportSize(dm, faces[f], &ns));
      PetscCall(DMPlexGetSupport(dm, faces[f], &support));
      for (PetscInt s = 0; s < ns; s++)
        if (support[s] != c && local[support[s] - cStart] >= 0) adj.push_back((idx_t)local[support[s] - cStart]);
    }
    xadj.push_back((idx_t)adj.size());
  }
  PetscFunctionReturn(0);
}

/* One (x, y, z) per node in the order of dm's global dofs: what PCSetCoordinates() expects
   of a 3-component field (clamped nodes drop out with their dofs). Nothing if some node is
   constrained in only some components (a symmetry plane): gdsw then takes the matrix's
   block size. */
static PetscErrorCode SetNodeCoordinates(PC pc, DM dm)
{
  PetscSection section;
  Vec          local, global;
  PetscInt     pStart, pEnd, n;
  PetscBool    partial = PETSC_FALSE;

  PetscFunctionBegin;
  PetscCall(DMGetLocalSection(dm, &section));
  PetscCall(PetscSectionGetChart(section, &pStart, &pEnd));
  for (PetscInt p = pStart; p < pEnd; p++) {
    PetscInt cdof;
    PetscCall(PetscSectionGetConstraintDof(section, p, &cdof));
    if (cdof == 1 || cdof == 2) partial = PETSC_TRUE;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &partial, 1, MPIU_BOOL, MPI_LOR, PetscObjectComm((PetscObject)dm)));
  if (partial) PetscFunctionReturn(0);
  PetscCall(DMGetLocalVector(dm, &local));
  PetscCall(DMGetGlobalVector(dm, &global));
  PetscScalar *x;
  PetscCall(VecGetArray(local, &x));
  for (PetscInt p = pStart; p < pEnd; p++) {
    PetscInt dof, off;
    PetscCall(PetscSectionGetDof(section, p, &dof));
    if (dof != 3) continue;
    PetscCall(PetscSectionGetOffset(section, p, &off));
    PetscReal xp[3];
    PetscCall(NodePosition(dm, p, xp));
    for (int c = 0; c < 3; c++) x[off + c] = xp[c];
  }
  PetscCall(VecRestoreArray(local, &x));
  PetscCall(DMLocalToGlobal(dm, local, INSERT_VALUES, global));
  PetscCall(VecGetLocalSize(global, &n));
  PetscCall(VecGetArray(global, &x));
  std::vector<PetscReal> coords(n);
  for (PetscInt i = 0; i < n; i++) coords[i] = PetscRealPart(x[i]);
  PetscCall(VecRestoreArray(global, &x));
  PetscCall(PCSetCoordinates(pc, 3, n / 3, coords.data()));
  PetscCall(DMRestoreGlobalVector(dm, &global));
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscFunctionReturn(0);
}

PetscErrorCode ConfigureGDSW(PC pc, DM dm, const char *region, PetscInt perRank)
{
  PetscBool isGDSW;

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCGDSW, &isGDSW));
  if (!isGDSW) PetscFunctionReturn(0);
  PetscCall(SetNodeCoordinates(pc, dm));
  std::vector<PetscInt> cells;
  std::vector<idx_t>    xadj, adj;
  PetscCall(RegionCells(dm, region, cells, xadj, adj));
  const PetscInt nc = (PetscInt)cells.size(), nparts = std::max<PetscInt>(1, std::min(perRank, nc));
  std::vector<idx_t> part(nc, 0);
  if (nparts > 1) {
    idx_t n = (idx_t)nc, ncon = 1, np = (idx_t)nparts, cut, options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_SEED] = 7;
    const int status = METIS_PartGraphKway(&n, &ncon, xadj.data(), adj.data(), nullptr, nullptr, nullptr, &np, nullptr, nullptr, options, &cut, part.data());
    PetscCheck(status == METIS_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "METIS could not split %" PetscInt_FMT " cells into %" PetscInt_FMT " subdomains (status %d)", nc, nparts, status);
  }
  PetscSection local, global;
  PetscCall(DMGetLocalSection(dm, &local));
  PetscCall(DMGetGlobalSection(dm, &global));
  std::vector<std::vector<PetscInt>> dofs(nparts);
  for (PetscInt k = 0; k < nc; k++) {
    PetscInt  n, *idx;
    PetscCall(DMPlexGetClosureIndices(dm, local, global, cells[k], PETSC_TRUE, &n, &idx, nullptr, nullptr));
    for (PetscInt i = 0; i < n; i++)
      if (idx[i] >= 0) dofs[part[k]].push_back(idx[i]); /* negative: constrained (Dirichlet) dofs */
    PetscCall(DMPlexRestoreClosureIndices(dm, local, global, cells[k], PETSC_TRUE, &n, &idx, nullptr, nullptr));
  }
  std::vector<IS> is(nparts);
  for (PetscInt p = 0; p < nparts; p++) {
    std::sort(dofs[p].begin(), dofs[p].end());
    dofs[p].erase(std::unique(dofs[p].begin(), dofs[p].end()), dofs[p].end());
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)dofs[p].size(), dofs[p].data(), PETSC_COPY_VALUES, &is[p]));
  }
  PetscCall(PCGDSWSetSubdomains(pc, nparts, is.data(), nullptr));
  for (auto &i : is) PetscCall(ISDestroy(&i));
  PetscFunctionReturn(0);
}

} // namespace fsi
