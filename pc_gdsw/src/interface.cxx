// SPDX-License-Identifier: BSD-2-Clause
/* Interface: which subdomains share each node (its sharing set), which dofs are Dirichlet
   dofs, the null-space data at each node, and the interface components: nodes with the same
   sharing set of two or more subdomains, split into connected pieces. Components are found by
   every subdomain that contains them, with the same result, because each subdomain of a
   sharing set contains all nodes of the set and the matrix couplings among them. */
#include "gdswimpl.h"
#include <algorithm>
#include <cmath>
#include <map>

using gdsw::CoarseGroup;
using gdsw::Subdomain;

/* Rows whose off-diagonal entries are all zero (MatZeroRows, or eliminated Dirichlet dofs). */
static PetscErrorCode DirichletMaskOwned(Mat A, PetscInt bs, std::vector<PetscInt> &mask, PetscInt *count)
{
  PetscInt rstart, rend;

  PetscFunctionBegin;
  PetscCall(MatGetOwnershipRange(A, &rstart, &rend));
  mask.assign((rend - rstart) / bs, 0);
  *count = 0;
  for (PetscInt r = rstart; r < rend; r++) {
    PetscInt           nc;
    const PetscInt    *cols;
    const PetscScalar *vals;
    PetscBool          offZero = PETSC_TRUE, diag = PETSC_FALSE;
    PetscCall(MatGetRow(A, r, &nc, &cols, &vals));
    for (PetscInt k = 0; k < nc; k++) {
      if (cols[k] == r) diag = (PetscBool)(vals[k] != 0.0);
      else if (vals[k] != 0.0) offZero = PETSC_FALSE;
    }
    PetscCall(MatRestoreRow(A, r, &nc, &cols, &vals));
    if (offZero && diag) {
      mask[(r - rstart) / bs] |= 1 << ((r - rstart) % bs);
      (*count)++;
    }
  }
  PetscFunctionReturn(0);
}

/* Whether the operator's Dirichlet rows differ from those of the last fresh set-up. */
PetscErrorCode GDSWDirichletRowsChanged(PC pc, PetscBool *changed)
{
  PC_GDSW              *gd = (PC_GDSW *)pc->data;
  std::vector<PetscInt> mask;
  PetscInt              count;
  PetscBool             mine;

  PetscFunctionBegin;
  PetscCall(DirichletMaskOwned(gd->A, gd->bs, mask, &count));
  mine = (PetscBool)(mask != *gd->dirichletMask);
  PetscCallMPI(MPIU_Allreduce(&mine, changed, 1, MPIU_BOOL, MPI_LOR, PetscObjectComm((PetscObject)pc)));
  PetscFunctionReturn(0);
}

/* Null-space data of the owned nodes: coordinates (rigid modes are formed per component, about
   its centroid), the operator's near-null space vectors, or nothing (translations). */
static PetscErrorCode NodeDataOwned(PC pc, std::vector<PetscReal> &data)
{
  PC_GDSW     *gd = (PC_GDSW *)pc->data;
  MatNullSpace nsp = nullptr;
  PetscInt     rstart, rend;

  PetscFunctionBegin;
  PetscCall(MatGetOwnershipRange(gd->A, &rstart, &rend));
  const PetscInt nn = (rend - rstart) / gd->bs, bs = gd->bs;
  PetscCall(MatGetNearNullSpace(pc->pmat, &nsp));
  if (!nsp && gd->A != pc->pmat) PetscCall(MatGetNearNullSpace(gd->A, &nsp));
  gd->haveCoords = PETSC_FALSE;
  if (!gd->rotations) {
    gd->nz = bs, gd->dataWidth = 0;
    PetscCall(PetscInfo(pc, "rotations off (GDSW-nr): %" PetscInt_FMT " translations per component\n", bs));
  } else if (nsp) {
    PetscBool  hasConst;
    PetscInt   nv;
    const Vec *v;
    PetscCall(MatNullSpaceGetVecs(nsp, &hasConst, &nv, &v));
    gd->nz = nv + (hasConst ? 1 : 0), gd->dataWidth = gd->nz * bs;
    data.assign(nn * gd->dataWidth, 1.0);
    for (PetscInt k = 0; k < nv; k++) {
      PetscInt           n;
      const PetscScalar *x;
      PetscReal          norm;
      PetscCall(VecGetLocalSize(v[k], &n));
      PetscCheck(n == rend - rstart, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "PCGDSW: near-null space vector %" PetscInt_FMT " has local length %" PetscInt_FMT " but the operator has %" PetscInt_FMT " local rows", k, n, rend - rstart);
      PetscCall(VecNorm(v[k], NORM_1, &norm)); /* collective; a NaN makes it NaN, found below with its row */
      PetscCheck(norm != 0, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_WRONG, "PCGDSW: near-null space vector %" PetscInt_FMT " is zero: each vector of MatSetNearNullSpace() spans coarse functions, so a zero one leaves the coarse space without them; remove it (for elasticity MatNullSpaceCreateRigidBody() builds the rigid-body modes)", k);
      PetscCall(VecGetArrayRead(v[k], &x));
      for (PetscInt a = 0; a < nn; a++)
        for (PetscInt c = 0; c < bs; c++) {
          const PetscReal xv = PetscRealPart(x[a * bs + c]);
          PetscCheck(!PetscIsInfOrNanReal(xv), PETSC_COMM_SELF, PETSC_ERR_FP, "PCGDSW: near-null space vector %" PetscInt_FMT " is not finite (NaN or Inf) in its local row %" PetscInt_FMT " (global row %" PetscInt_FMT "): the coarse space needs finite vectors", k, a * bs + c, rstart + a * bs + c);
          data[a * gd->dataWidth + k * bs + c] = xv;
        }
      PetscCall(VecRestoreArrayRead(v[k], &x));
    }
    PetscCall(PetscInfo(pc, "null space: the operator's near-null space, %" PetscInt_FMT " vectors\n", gd->nz));
  } else if (gd->coords && gd->coordDim != bs && (bs == 2 || bs == 3)) {
    SETERRQ(PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_INCOMP, "PCGDSW: PCSetCoordinates() gave %" PetscInt_FMT "-D coordinates but the operator has %" PetscInt_FMT " dofs per node: the rigid-body modes need %" PetscInt_FMT "-D coordinates (or attach a near-null space with MatSetNearNullSpace(), or -pc_gdsw_rotations 0 for translations only)", gd->coordDim, bs, bs);
  } else if (gd->coords && (bs == 2 || bs == 3)) {
    PetscCheck(gd->nCoordNodes == nn, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "PCGDSW: PCSetCoordinates() gave %" PetscInt_FMT " local nodes but the operator has %" PetscInt_FMT " local nodes of %" PetscInt_FMT " dofs", gd->nCoordNodes, nn, bs);
    gd->haveCoords = PETSC_TRUE;
    gd->nz = bs == 3 ? 6 : 3, gd->dataWidth = bs;
    data.assign(gd->coords, gd->coords + nn * bs);
    PetscCall(PetscInfo(pc, "null space: %" PetscInt_FMT " rigid-body modes from PCSetCoordinates()\n", gd->nz));
  } else {
    gd->nz = bs, gd->dataWidth = 0;
    PetscCall(PetscInfo(pc, "null space: no near-null space and no coordinates, %" PetscInt_FMT " translations per component\n", bs));
  }
  PetscFunctionReturn(0);
}

/* Connected pieces of the interface nodes of one subdomain, grouped by sharing set. */
static PetscErrorCode FindComponents(PC pc, Subdomain &s, std::vector<CoarseGroup> &comps)
{
  PC_GDSW        *gd = (PC_GDSW *)pc->data;
  const PetscInt  bs = gd->bs, nn = (PetscInt)s.nodes.size(), full = (1 << bs) - 1;
  const PetscInt *ia, *ja, *pos;
  PetscInt        nrows;
  PetscBool       done;

  PetscFunctionBegin;
  std::vector<char> onGamma(nn);
  for (PetscInt a = 0; a < nn; a++) onGamma[a] = (*gd->sets)[s.setOf[a]].size() >= 2 && s.dirMask[a] != full;
  PetscCall(MatGetRowIJ(s.Aovl, 0, PETSC_FALSE, PETSC_FALSE, &nrows, &ia, &ja, &done));
  PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_SUP, "PCGDSW: cannot access the rows of a subdomain matrix");
  PetscCall(ISGetIndices(s.nonInOvl, &pos)); /* the rows of Omega~_i's dofs in Aovl */
  std::vector<char>     seen(nn, 0);
  std::vector<PetscInt> stack;
  for (PetscInt a = 0; a < nn; a++) {
    if (!onGamma[a] || seen[a]) continue;
    CoarseGroup c;
    c.sharing = (*gd->sets)[s.setOf[a]];
    stack.assign(1, a);
    seen[a] = 1;
    while (!stack.empty()) {
      const PetscInt b = stack.back();
      stack.pop_back();
      c.support.push_back(b);
      for (PetscInt r = b * bs; r < (b + 1) * bs; r++)
        for (PetscInt k = ia[pos[r]]; k < ia[pos[r] + 1]; k++) {
          const PetscInt d = s.ovlToNon[ja[k]];
          if (d < 0) continue; /* outside Omega~_i */
          const PetscInt m = d / bs;
          if (!seen[m] && onGamma[m] && s.setOf[m] == s.setOf[a]) {
            seen[m] = 1;
            stack.push_back(m);
          }
        }
    }
    std::sort(c.support.begin(), c.support.end());
    c.rep  = s.nodes[c.support[0]];
    c.kind = c.sharing.size() == 2 ? gdsw::FACE : (c.support.size() == 1 ? gdsw::VERTEX : gdsw::EDGE);
    c.weight.assign(c.support.size(), 1.0);
    c.center[0] = c.center[1] = c.center[2] = 0;
    if (gd->haveCoords) {
      for (PetscInt b : c.support)
        for (PetscInt d = 0; d < bs; d++) c.center[d] += s.nodeData[b * bs + d] / c.support.size();
    }
    c.ncols = 0, c.col0 = -1;
    comps.push_back(c);
  }
  PetscCall(ISRestoreIndices(s.nonInOvl, &pos));
  PetscCall(MatRestoreRowIJ(s.Aovl, 0, PETSC_FALSE, PETSC_FALSE, &nrows, &ia, &ja, &done));
  PetscFunctionReturn(0);
}

PetscErrorCode GDSWBuildInterface(PC pc)
{
  PC_GDSW  *gd = (PC_GDSW *)pc->data;
  const PetscInt bs = gd->bs;
  MPI_Comm  comm;
  PetscInt  rstart, rend, nleaves = 0;

  PetscFunctionBegin;
  PetscCall(PetscObjectGetComm((PetscObject)pc, &comm));
  PetscCall(MatGetOwnershipRange(gd->A, &rstart, &rend));
  const PetscInt nn = (rend - rstart) / bs;
  auto &sub = *gd->sub;

  /* the node star forest */
  std::vector<PetscInt> leafNodes, leafGid;
  for (auto &s : sub) {
    s.leaf0 = nleaves;
    nleaves += (PetscInt)s.nodes.size();
    leafNodes.insert(leafNodes.end(), s.nodes.begin(), s.nodes.end());
    leafGid.insert(leafGid.end(), s.nodes.size(), s.gid);
  }
  PetscLayout layout;
  PetscCall(PetscLayoutCreate(comm, &layout));
  PetscCall(PetscLayoutSetLocalSize(layout, nn));
  PetscCall(PetscLayoutSetUp(layout));
  PetscCall(PetscSFCreate(comm, &gd->nodeSF));
  PetscCall(PetscSFSetGraphLayout(gd->nodeSF, layout, nleaves, nullptr, PETSC_COPY_VALUES, leafNodes.data()));
  PetscCall(PetscLayoutDestroy(&layout));
  PetscCall(PetscSFSetUp(gd->nodeSF));

  /* sharing sets: gather subdomain ids at the owner, send each node's sorted set back */
  const PetscInt *degree;
  PetscInt        ndeg = 0, maxdeg = 0, gmaxdeg;
  PetscCall(PetscSFComputeDegreeBegin(gd->nodeSF, &degree));
  PetscCall(PetscSFComputeDegreeEnd(gd->nodeSF, &degree));
  PetscInt uncovered = -1;
  for (PetscInt a = 0; a < nn; a++) {
    ndeg += degree[a], maxdeg = std::max(maxdeg, degree[a]);
    if (!degree[a] && uncovered < 0) uncovered = rstart / bs + a;
  }
  PetscCheck(uncovered < 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "PCGDSW: node %" PetscInt_FMT " (dofs %" PetscInt_FMT "..%" PetscInt_FMT ") lies in no subdomain: the nonoverlapping subdomains must cover every dof", uncovered, uncovered * bs, uncovered * bs + bs - 1);
  std::vector<PetscInt> multi(ndeg);
  PetscCall(PetscSFGatherBegin(gd->nodeSF, MPIU_INT, leafGid.data(), multi.data()));
  PetscCall(PetscSFGatherEnd(gd->nodeSF, MPIU_INT, leafGid.data(), multi.data()));
  PetscCallMPI(MPIU_Allreduce(&maxdeg, &gmaxdeg, 1, MPIU_INT, MPI_MAX, comm));
  const PetscInt W = gmaxdeg + 1;
  std::vector<PetscInt> rootSets(nn * W, -1), leafSets(nleaves * W);
  for (PetscInt a = 0, k = 0; a < nn; k += degree[a], a++) {
    rootSets[a * W] = degree[a];
    std::copy(multi.begin() + k, multi.begin() + k + degree[a], rootSets.begin() + a * W + 1);
    std::sort(rootSets.begin() + a * W + 1, rootSets.begin() + a * W + 1 + degree[a]);
  }
  MPI_Datatype setType, dataType = MPI_DATATYPE_NULL;
  PetscMPIInt width;
  PetscCall(PetscMPIIntCast(W, &width));
  PetscCallMPI(MPI_Type_contiguous(width, MPIU_INT, &setType));
  PetscCallMPI(MPI_Type_commit(&setType));
  PetscCall(PetscSFBcastBegin(gd->nodeSF, setType, rootSets.data(), leafSets.data(), MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(gd->nodeSF, setType, rootSets.data(), leafSets.data(), MPI_REPLACE));
  PetscCallMPI(MPI_Type_free(&setType));

  /* Dirichlet dofs and null-space data */
  std::vector<PetscInt>  rootMask, leafMask(nleaves);
  std::vector<PetscReal> rootData, leafData;
  PetscInt               nDir;
  PetscCall(DirichletMaskOwned(gd->A, bs, rootMask, &nDir));
  *gd->dirichletMask = rootMask;
  PetscCallMPI(MPIU_Allreduce(&nDir, &gd->nDirichletRows, 1, MPIU_INT, MPI_SUM, comm));
  PetscCall(PetscSFBcastBegin(gd->nodeSF, MPIU_INT, rootMask.data(), leafMask.data(), MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(gd->nodeSF, MPIU_INT, rootMask.data(), leafMask.data(), MPI_REPLACE));
  PetscCall(NodeDataOwned(pc, rootData));
  if (gd->dataWidth) {
    leafData.resize(nleaves * gd->dataWidth);
    PetscCall(PetscMPIIntCast(gd->dataWidth, &width));
    PetscCallMPI(MPI_Type_contiguous(width, MPIU_REAL, &dataType));
    PetscCallMPI(MPI_Type_commit(&dataType));
    PetscCall(PetscSFBcastBegin(gd->nodeSF, dataType, rootData.data(), leafData.data(), MPI_REPLACE));
    PetscCall(PetscSFBcastEnd(gd->nodeSF, dataType, rootData.data(), leafData.data(), MPI_REPLACE));
    PetscCallMPI(MPI_Type_free(&dataType));
  }

  /* per subdomain: its view of sets, masks, data; then components */
  std::map<std::vector<PetscInt>, PetscInt> setIndex;
  gd->sets->clear();
  PetscInt local[3] = {0, 0, 0};
  for (size_t i = 0; i < sub.size(); i++) {
    Subdomain &s = sub[i];
    const PetscInt n = (PetscInt)s.nodes.size();
    s.setOf.resize(n);
    s.dirMask.assign(leafMask.begin() + s.leaf0, leafMask.begin() + s.leaf0 + n);
    s.nodeData.assign(leafData.begin() + s.leaf0 * gd->dataWidth, leafData.begin() + (s.leaf0 + n) * gd->dataWidth);
    for (PetscInt a = 0; a < n; a++) {
      const PetscInt *p = &leafSets[(s.leaf0 + a) * W];
      std::vector<PetscInt> set(p + 1, p + 1 + p[0]);
      auto it = setIndex.find(set);
      if (it == setIndex.end()) {
        it = setIndex.emplace(set, (PetscInt)gd->sets->size()).first;
        gd->sets->push_back(set);
      }
      s.setOf[a] = it->second;
    }
    s.groups.clear();
    PetscCall(FindComponents(pc, s, s.groups));
    for (const auto &c : s.groups)
      if (c.sharing[0] == s.gid) local[c.kind]++;
  }
  PetscCallMPI(MPIU_Allreduce(local, gd->counts, 3, MPIU_INT, MPI_SUM, comm));
  PetscFunctionReturn(0);
}
