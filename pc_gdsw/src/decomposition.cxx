// SPDX-License-Identifier: BSD-2-Clause
/* Decomposition: the nonoverlapping subdomains Omega~_i (which share their interface nodes,
   as the closures of element sets do) and the overlapping subdomains Omega_i^delta.
   Sources, in order of preference: the caller's element-based sets (PCGDSWSetSubdomains), a
   MATIS operator's local subdomains (split by METIS on their local matrix when the size rule
   asks for more than one per rank), or METIS on each rank's node graph. */
#include "gdswimpl.h"
#include <petscmat.h>
#include <metis.h>
#include <algorithm>
#include <cmath>
#include <memory>

using gdsw::Subdomain;

/* Sorted unique node ids of a dof index set; errors if it does not hold whole nodes. */
static PetscErrorCode NodesOfIS(IS is, PetscInt bs, PetscInt which, std::vector<PetscInt> &nodes)
{
  PetscInt        n;
  const PetscInt *idx;

  PetscFunctionBegin;
  PetscCall(ISGetLocalSize(is, &n));
  PetscCall(ISGetIndices(is, &idx));
  std::vector<PetscInt> dofs(idx, idx + n);
  PetscCall(ISRestoreIndices(is, &idx));
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  nodes.clear();
  for (PetscInt d : dofs)
    if (nodes.empty() || nodes.back() != d / bs) nodes.push_back(d / bs);
  PetscCheck((PetscInt)dofs.size() == (PetscInt)nodes.size() * bs, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
             "PCGDSW: subdomain %" PetscInt_FMT " index set holds %zu dofs on %zu nodes: with block size %" PetscInt_FMT " it must contain every dof of each node it touches",
             which, dofs.size(), nodes.size(), bs);
  PetscFunctionReturn(0);
}

static PetscErrorCode DofISOfNodes(const std::vector<PetscInt> &nodes, PetscInt bs, IS *is)
{
  PetscFunctionBegin;
  PetscCall(ISCreateBlock(PETSC_COMM_SELF, bs, (PetscInt)nodes.size(), nodes.data(), PETSC_COPY_VALUES, is));
  PetscFunctionReturn(0);
}

/* Node graph of the rows this rank owns: adjacency to owned nodes (local ids) and to ghost
   nodes (global ids), from the diagonal and off-diagonal blocks of the (MPI)AIJ operator. */
struct LocalGraph {
  std::vector<PetscInt> xadj, adj;           /* owned-owned, local node ids, no self loops */
  std::vector<PetscInt> gxadj, gadj;         /* owned-ghost, global node ids */
};

/* Node adjacency of the rows of a sequential AIJ block M (one node per bs rows), in CSR: column c
   belongs to column node colNode[c], which is listed as id[colNode[c]]; self loops (a column
   node equal to the row node) are dropped when own. A marker per column node
   keeps each list free of repeats; each list is sorted. */
static PetscErrorCode NodeAdjacency(Mat M, PetscInt bs, const std::vector<PetscInt> &colNode, const std::vector<PetscInt> &id, bool own, std::vector<PetscInt> &xadj, std::vector<PetscInt> &adj)
{
  const PetscInt *ia, *ja;
  PetscInt        nrows;
  PetscBool       done;

  PetscFunctionBegin;
  PetscCall(MatGetRowIJ(M, 0, PETSC_FALSE, PETSC_FALSE, &nrows, &ia, &ja, &done));
  PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_SUP, "PCGDSW: cannot access the rows of the local matrix");
  const PetscInt        nn = nrows / bs;
  std::vector<PetscInt> mark(id.size(), -1);
  xadj.assign(nn + 1, 0);
  adj.clear();
  adj.reserve(ia[nrows] / bs);
  for (PetscInt a = 0; a < nn; a++) {
    for (PetscInt r = a * bs; r < (a + 1) * bs; r++)
      for (PetscInt k = ia[r]; k < ia[r + 1]; k++) {
        const PetscInt b = colNode[ja[k]];
        if (mark[b] == a || (own && b == a)) continue;
        mark[b] = a;
        adj.push_back(id[b]);
      }
    std::sort(adj.begin() + xadj[a], adj.end());
    xadj[a + 1] = (PetscInt)adj.size();
  }
  PetscCall(MatRestoreRowIJ(M, 0, PETSC_FALSE, PETSC_FALSE, &nrows, &ia, &ja, &done));
  PetscFunctionReturn(0);
}

static PetscErrorCode BuildLocalGraph(Mat A, PetscInt bs, LocalGraph &g)
{
  Mat             Ad, Ao = nullptr;
  const PetscInt *garray = nullptr;
  PetscInt        rstart, rend;
  PetscBool       isMPI;

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompare((PetscObject)A, MATMPIAIJ, &isMPI));
  if (isMPI) PetscCall(MatMPIAIJGetSeqAIJ(A, &Ad, &Ao, &garray));
  else Ad = A;
  PetscCall(MatGetOwnershipRange(A, &rstart, &rend));
  const PetscInt        nn = (rend - rstart) / bs;
  std::vector<PetscInt> colNode(nn * bs), id(nn), xadj, adj;
  for (PetscInt c = 0; c < nn * bs; c++) colNode[c] = c / bs;
  for (PetscInt a = 0; a < nn; a++) id[a] = a;
  PetscCall(NodeAdjacency(Ad, bs, colNode, id, true, xadj, adj));
  g.gxadj.assign(nn + 1, 0), g.gadj.clear();
  if (Ao) { /* compressed columns (garray, sorted): a ghost node's dofs are neighbours there */
    PetscInt nc;
    PetscCall(MatGetSize(Ao, nullptr, &nc));
    std::vector<PetscInt> ghostCol(nc), ghostId;
    for (PetscInt c = 0; c < nc; c++) {
      if (ghostId.empty() || ghostId.back() != garray[c] / bs) ghostId.push_back(garray[c] / bs);
      ghostCol[c] = (PetscInt)ghostId.size() - 1;
    }
    PetscCall(NodeAdjacency(Ao, bs, ghostCol, ghostId, false, g.gxadj, g.gadj));
  }
  /* METIS needs a symmetric graph: the union with the transpose (the same graph for the
     structurally symmetric operators of FE) */
  std::vector<PetscInt> txadj(nn + 1, 0), tadj(adj.size()), fill(nn);
  for (PetscInt b : adj) txadj[b + 1]++;
  for (PetscInt a = 0; a < nn; a++) txadj[a + 1] += txadj[a];
  std::copy(txadj.begin(), txadj.end() - 1, fill.begin());
  for (PetscInt a = 0; a < nn; a++)
    for (PetscInt k = xadj[a]; k < xadj[a + 1]; k++) tadj[fill[adj[k]]++] = a; /* each list ascending */
  g.xadj.assign(nn + 1, 0);
  g.adj.clear();
  g.adj.reserve(adj.size());
  for (PetscInt a = 0; a < nn; a++) {
    std::set_union(adj.begin() + xadj[a], adj.begin() + xadj[a + 1], tadj.begin() + txadj[a], tadj.begin() + txadj[a + 1], std::back_inserter(g.adj));
    g.xadj[a + 1] = (PetscInt)g.adj.size();
  }
  PetscFunctionReturn(0);
}

/* Connected subdomains: each piece of a part that is not its largest goes to the neighbouring
   part it shares the most edges with, until every part is connected (a piece with no neighbour,
   on a disconnected graph, stays). METIS's own CONTIG option does the same inside its refinement
   at several times the cost of the partition (2.7 against 0.7 s for 166 parts of 166 k nodes).
   Counts the pieces moved. */
static void MergeIslands(const LocalGraph &g, PetscInt nparts, std::vector<PetscInt> &part, PetscInt *moved)
{
  const PetscInt nn = (PetscInt)part.size();
  std::vector<PetscInt> piece(nn), stack, size, largest(nparts, -1), weight(nparts, 0), touched;

  *moved = 0;
  for (PetscInt round = 0, changed = 1; changed && round < 20; round++) { /* a few rounds suffice; the bound guards a cycle */
    changed = 0;
    PetscInt npieces = 0;
    std::fill(piece.begin(), piece.end(), -1);
    size.clear();
    for (PetscInt a = 0; a < nn; a++) {
      if (piece[a] >= 0) continue;
      piece[a] = npieces;
      size.push_back(0);
      for (stack.assign(1, a); !stack.empty();) {
        const PetscInt b = stack.back();
        stack.pop_back();
        size[npieces]++;
        for (PetscInt k = g.xadj[b]; k < g.xadj[b + 1]; k++) {
          const PetscInt c = g.adj[k];
          if (piece[c] < 0 && part[c] == part[b]) piece[c] = npieces, stack.push_back(c);
        }
      }
      npieces++;
    }
    std::fill(largest.begin(), largest.end(), -1);
    std::vector<PetscInt> first(npieces, -1);
    for (PetscInt a = 0; a < nn; a++) {
      PetscInt &l = largest[part[a]];
      if (first[piece[a]] < 0) first[piece[a]] = a;
      if (l < 0 || size[piece[a]] > size[l]) l = piece[a];
    }
    PetscInt used = 0;
    for (PetscInt l : largest) used += l >= 0;
    if (npieces == used) return;
    for (PetscInt q = 0; q < npieces; q++) {
      const PetscInt a0 = first[q], p = part[a0];
      if (largest[p] == q) continue;
      /* the piece's nodes, and the part it is most connected to */
      std::vector<PetscInt> nodes(1, a0);
      piece[a0] = -1 - q;
      for (size_t t = 0; t < nodes.size(); t++)
        for (PetscInt k = g.xadj[nodes[t]]; k < g.xadj[nodes[t] + 1]; k++) {
          const PetscInt c = g.adj[k];
          if (part[c] == p && piece[c] == q) piece[c] = -1 - q, nodes.push_back(c);
          else if (part[c] != p) {
            if (!weight[part[c]]) touched.push_back(part[c]);
            weight[part[c]]++;
          }
        }
      PetscInt best = -1;
      for (PetscInt t : touched)
        if (best < 0 || weight[t] > weight[best] || (weight[t] == weight[best] && t < best)) best = t;
      for (PetscInt t : touched) weight[t] = 0;
      touched.clear();
      if (best < 0) continue;
      for (PetscInt b : nodes) part[b] = best;
      (*moved)++;
      changed = 1;
    }
  }
}

/* Split the owned nodes into nparts with METIS (k-way), connected parts where the graph allows;
   returns the part of each node. */
static PetscErrorCode PartitionNodes(PC pc, const LocalGraph &g, PetscInt nparts, std::vector<PetscInt> &part)
{
  const PetscInt nn = (PetscInt)g.xadj.size() - 1;
  PetscInt       moved;

  PetscFunctionBegin;
  part.assign(nn, 0);
  if (nparts <= 1 || nn == 0) PetscFunctionReturn(0);
  if (nparts >= nn) { /* one node per part: METIS would refuse */
    for (PetscInt a = 0; a < nn; a++) part[a] = a;
    PetscFunctionReturn(0);
  }
  PetscCall(GDSWCheckMetisSize((PetscCount)g.adj.size()));
  std::vector<idx_t> xadj(g.xadj.begin(), g.xadj.end()), adj(g.adj.begin(), g.adj.end()), p(nn);
  idx_t nv = (idx_t)nn, ncon = 1, np = (idx_t)nparts, cut, options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 7; /* reproducible decompositions */
  int status = METIS_PartGraphKway(&nv, &ncon, xadj.data(), adj.data(), nullptr, nullptr, nullptr, &np, nullptr, nullptr, options, &cut, p.data());
  PetscCheck(status == METIS_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "PCGDSW: METIS_PartGraphKway failed (status %d) splitting %" PetscInt_FMT " nodes into %" PetscInt_FMT " subdomains", status, nn, nparts);
  for (PetscInt a = 0; a < nn; a++) part[a] = p[a];
  MergeIslands(g, nparts, part, &moved);
  if (moved) PetscCall(PetscInfo(pc, "%" PetscInt_FMT " disconnected pieces of METIS's parts joined to a neighbouring part\n", moved));
  PetscFunctionReturn(0);
}

/* How many subdomains a rank's ndofs make: -pc_gdsw_subdomains, or the size rule
   (bench/results/gdsw_subdomains_per_rank): local solves of about subdomainSize dofs balance
   their factorisation cost against the coarse problem's growth. */
static PetscInt RequestedParts(const PC_GDSW *gd, PetscInt ndofs)
{
  if (gd->nsubPerRank != PETSC_DECIDE) return gd->nsubPerRank;
  return std::max<PetscInt>(1, (PetscInt)std::lround((double)ndofs / GDSWSubdomainSizeTarget(gd)));
}

/* Number the nonempty parts 0, 1, ... (METIS may leave parts empty). */
static PetscErrorCode DropEmptyParts(PC pc, std::vector<PetscInt> &part, PetscInt requested, PetscInt *nparts)
{
  std::vector<PetscInt> renum(std::max<PetscInt>(requested, (PetscInt)part.size()) + 1, -1);

  PetscFunctionBegin;
  *nparts = 0;
  for (PetscInt &p : part) {
    if (renum[p] < 0) renum[p] = (*nparts)++;
    p = renum[p];
  }
  if (*nparts < requested) PetscCall(PetscInfo(pc, "%" PetscInt_FMT " of %" PetscInt_FMT " requested subdomains on this rank are empty and dropped\n", requested - *nparts, requested));
  PetscFunctionReturn(0);
}

/* out[r] to rank r, for every r; in: what every rank sent here, in rank order. */
static PetscErrorCode SendToRanks(MPI_Comm comm, const std::vector<std::vector<PetscInt>> &out, std::vector<PetscInt> &in)
{
  const PetscMPIInt size = (PetscMPIInt)out.size();
  std::vector<PetscMPIInt> scount(size), rcount(size), sdispl(size + 1, 0), rdispl(size + 1, 0);
  std::vector<PetscInt>    sbuf;

  PetscFunctionBegin;
  for (PetscMPIInt r = 0; r < size; r++) PetscCall(PetscMPIIntCast((PetscInt)out[r].size(), &scount[r]));
  PetscCallMPI(MPI_Alltoall(scount.data(), 1, MPI_INT, rcount.data(), 1, MPI_INT, comm));
  for (PetscMPIInt r = 0; r < size; r++) {
    const PetscCount s = (PetscCount)sdispl[r] + scount[r], t = (PetscCount)rdispl[r] + rcount[r];
    /* MPI's displacements are ints */
    PetscCheck(s <= PETSC_MPI_INT_MAX && t <= PETSC_MPI_INT_MAX, PETSC_COMM_SELF, PETSC_ERR_SUP, "PCGDSW: more than 2^31 - 1 indices to exchange with the other ranks at once");
    sdispl[r + 1] = (PetscMPIInt)s, rdispl[r + 1] = (PetscMPIInt)t;
    sbuf.insert(sbuf.end(), out[r].begin(), out[r].end());
  }
  in.resize(rdispl[size]);
  PetscCallMPI(MPI_Alltoallv(sbuf.data(), scount.data(), sdispl.data(), MPIU_INT, in.data(), rcount.data(), rdispl.data(), MPIU_INT, comm));
  PetscFunctionReturn(0);
}

/* Global subdomain id of every owned node, and the number of subdomains: METIS parts of the
   rank's node graph, numbered rank after rank; or, with -pc_gdsw_repartition, the parts of a
   parallel partitioner (MatPartitioning, prefix -pc_gdsw_) of the whole node graph, for ranks
   whose rows are not compact in the mesh (a plate split through its thickness). */
static PetscErrorCode PartOfOwnedNodes(PC pc, const LocalGraph &g, PetscInt n0, std::vector<PetscInt> &gpart, PetscInt *ntotal)
{
  PC_GDSW       *gd = (PC_GDSW *)pc->data;
  const PetscInt nn = (PetscInt)g.xadj.size() - 1;
  MPI_Comm       comm;

  PetscFunctionBegin;
  PetscCall(PetscObjectGetComm((PetscObject)pc, &comm));
  if (!gd->repartition) {
    const PetscInt requested = RequestedParts(gd, nn * gd->bs);
    PetscInt       nparts, first;
    PetscCall(PartitionNodes(pc, g, requested, gpart));
    PetscCall(DropEmptyParts(pc, gpart, requested, &nparts));
    PetscCallMPI(MPI_Scan(&nparts, &first, 1, MPIU_INT, MPI_SUM, comm));
    first -= nparts;
    for (PetscInt &p : gpart) p += first;
    PetscCallMPI(MPIU_Allreduce(&nparts, ntotal, 1, MPIU_INT, MPI_SUM, comm));
    PetscFunctionReturn(0);
  }
  PetscInt    nnodes, ndofs;
  PetscMPIInt size;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(MatGetSize(gd->A, &ndofs, nullptr));
  nnodes                 = ndofs / gd->bs;
  /* the size rule on all rows, or the count per rank times the ranks */
  const PetscInt request = std::min(nnodes, RequestedParts(gd, ndofs) * (gd->nsubPerRank != PETSC_DECIDE ? size : 1));
  /* the node graph in global ids, each row the sorted union of its owned and ghost neighbours */
  PetscInt *ia, *ja;
  PetscCall(PetscMalloc1(nn + 1, &ia));
  PetscCall(PetscMalloc1(g.adj.size() + g.gadj.size(), &ja));
  ia[0] = 0;
  for (PetscInt a = 0; a < nn; a++) {
    PetscInt *end = ja + ia[a];
    for (PetscInt k = g.xadj[a]; k < g.xadj[a + 1]; k++) *end++ = n0 + g.adj[k];
    end = std::copy(g.gadj.begin() + g.gxadj[a], g.gadj.begin() + g.gxadj[a + 1], end);
    std::sort(ja + ia[a], end);
    ia[a + 1] = (PetscInt)(end - ja);
  }
  Mat             adj;
  MatPartitioning mp;
  IS              is;
  const PetscInt *p;
  const char     *prefix, *type;
  PetscCall(MatCreateMPIAdj(comm, nn, nnodes, ia, ja, nullptr, &adj)); /* takes ia, ja */
  PetscCall(MatPartitioningCreate(comm, &mp));
  PetscCall(MatPartitioningSetAdjacency(mp, adj));
  PetscCall(MatPartitioningSetNParts(mp, request));
  PetscCall(PCGetOptionsPrefix(pc, &prefix));
  PetscCall(PetscObjectSetOptionsPrefix((PetscObject)mp, prefix));
  PetscCall(PetscObjectAppendOptionsPrefix((PetscObject)mp, "pc_gdsw_"));
  PetscCall(MatPartitioningSetFromOptions(mp));
  PetscCall(MatPartitioningGetType(mp, &type));
  PetscCall(MatPartitioningApply(mp, &is));
  PetscCall(PetscStrncpy(gd->partitioner, type, sizeof(gd->partitioner)));
  PetscCall(ISGetIndices(is, &p));
  gpart.assign(p, p + nn);
  PetscCall(ISRestoreIndices(is, &p));
  PetscCall(ISDestroy(&is));
  PetscCall(MatPartitioningDestroy(&mp));
  PetscCall(MatDestroy(&adj));
  /* number the nonempty parts 0, 1, ... in their order */
  std::vector<PetscInt> count(request, 0);
  for (PetscInt q : gpart) count[q]++;
  PetscMPIInt nrequest;
  PetscCall(PetscMPIIntCast(request, &nrequest));
  PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, count.data(), nrequest, MPIU_INT, MPI_SUM, comm));
  *ntotal = 0;
  for (PetscInt &c : count) c = c ? (*ntotal)++ : -1;
  for (PetscInt &q : gpart) q = count[q];
  PetscCall(PetscInfo(pc, "%" PetscInt_FMT " subdomains from %s's partition of the whole node graph (%" PetscInt_FMT " requested)\n", *ntotal, gd->partitioner, request));
  PetscFunctionReturn(0);
}

/* Algebraic subdomains: parts P_i of the nodes, and Omega~_i = P_i plus the neighbours that
   belong to subdomains of larger id. The interface is then one layer of nodes, shared by a
   subdomain and its lower-numbered neighbours, as with element-based subdomains. Subdomain i
   lives on the rank that owns its nodes (METIS within the rank) or, repartitioned, on rank
   floor(i size / N): the owners of its nodes send them there. */
static PetscErrorCode AlgebraicSubdomains(PC pc, std::vector<std::vector<PetscInt>> &parts)
{
  PC_GDSW   *gd = (PC_GDSW *)pc->data;
  Mat        A  = gd->A;
  const PetscInt bs = gd->bs;
  LocalGraph g;
  std::vector<PetscInt> gpart;
  PetscInt   rstart, rend, ntotal;
  MPI_Comm   comm;
  PetscMPIInt size, rank;

  PetscFunctionBegin;
  PetscCall(PetscObjectGetComm((PetscObject)pc, &comm));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(MatGetOwnershipRange(A, &rstart, &rend));
  PetscCall(BuildLocalGraph(A, bs, g));
  const PetscInt nn = (rend - rstart) / bs, n0 = rstart / bs;
  PetscCall(PartOfOwnedNodes(pc, g, n0, gpart, &ntotal));

  /* subdomain id of every owned dof, and of the ghost neighbours */
  Vec      sid, ghostSid;
  IS       ghostIS;
  VecScatter sc;
  PetscCall(MatCreateVecs(A, &sid, nullptr));
  {
    PetscScalar *s;
    PetscCall(VecGetArray(sid, &s));
    for (PetscInt a = 0; a < nn; a++)
      for (PetscInt c = 0; c < bs; c++) s[a * bs + c] = (PetscScalar)gpart[a];
    PetscCall(VecRestoreArray(sid, &s));
  }
  std::vector<PetscInt> ghostNodes(g.gadj);
  std::sort(ghostNodes.begin(), ghostNodes.end());
  ghostNodes.erase(std::unique(ghostNodes.begin(), ghostNodes.end()), ghostNodes.end());
  std::vector<PetscInt> ghostDofs;
  for (PetscInt m : ghostNodes) ghostDofs.push_back(m * bs);
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)ghostDofs.size(), ghostDofs.data(), PETSC_USE_POINTER, &ghostIS));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, (PetscInt)ghostDofs.size(), &ghostSid));
  PetscCall(VecScatterCreate(sid, ghostIS, ghostSid, nullptr, &sc));
  PetscCall(VecScatterBegin(sc, sid, ghostSid, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, sid, ghostSid, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar *gs;
  PetscCall(VecGetArrayRead(ghostSid, &gs));

  /* records (i, node, in P_i) for the rank of subdomain i */
  auto owner = [&](PetscInt i) { return gd->repartition ? (PetscMPIInt)(((long long)i * size) / ntotal) : rank; };
  std::vector<std::vector<PetscInt>> out(size);
  auto put = [](std::vector<PetscInt> &o, PetscInt i, PetscInt node, PetscInt inP) { o.push_back(i), o.push_back(node), o.push_back(inP); };
  for (PetscInt a = 0; a < nn; a++) {
    const PetscInt i = gpart[a];
    auto          &o = out[owner(i)];
    put(o, i, n0 + a, 1);
    for (PetscInt k = g.xadj[a]; k < g.xadj[a + 1]; k++)
      if (gpart[g.adj[k]] > i) put(o, i, n0 + g.adj[k], 0);
    for (PetscInt k = g.gxadj[a]; k < g.gxadj[a + 1]; k++) {
      const PetscInt m = g.gadj[k];
      const PetscInt s = (PetscInt)PetscRealPart(gs[std::lower_bound(ghostNodes.begin(), ghostNodes.end(), m) - ghostNodes.begin()]);
      if (s > i) put(o, i, m, 0);
    }
  }
  PetscCall(VecRestoreArrayRead(ghostSid, &gs));
  PetscCall(VecScatterDestroy(&sc));
  PetscCall(VecDestroy(&ghostSid));
  PetscCall(ISDestroy(&ghostIS));
  PetscCall(VecDestroy(&sid));
  std::vector<PetscInt> rec;
  if (gd->repartition) PetscCall(SendToRanks(comm, out, rec));
  else rec.swap(out[rank]);

  std::vector<PetscInt> ids; /* every subdomain has nodes in P_i */
  for (size_t k = 0; k < rec.size(); k += 3)
    if (rec[k + 2]) ids.push_back(rec[k]);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  const PetscInt nloc = (PetscInt)ids.size();
  parts.assign(nloc, {});
  std::vector<std::vector<PetscInt>> omega(nloc);
  for (size_t k = 0; k < rec.size(); k += 3) {
    const PetscInt i = (PetscInt)(std::lower_bound(ids.begin(), ids.end(), rec[k]) - ids.begin());
    omega[i].push_back(rec[k + 1]);
    if (rec[k + 2]) parts[i].push_back(rec[k + 1]);
  }
  gd->sub->assign(nloc, Subdomain());
  for (PetscInt i = 0; i < nloc; i++) {
    auto &o = omega[i];
    std::sort(o.begin(), o.end());
    o.erase(std::unique(o.begin(), o.end()), o.end());
    std::sort(parts[i].begin(), parts[i].end());
    (*gd->sub)[i].gid   = ids[i];
    (*gd->sub)[i].nodes = o;
  }
  PetscFunctionReturn(0);
}

/* Rows unbalanced over the ranks (ksp/tutorials/ex56 puts every row on rank 0) would leave the
   other ranks idle. When the heaviest rank's subdomains hold more than 1.5 times the mean number
   of nodes, the subdomains (ids consecutive, rank after rank) are cut into contiguous runs of
   about equal nodes, one run per rank, and sent there with their node sets Omega~_i and P_i; the
   rows stay where they are (the extraction and the scatters reach them). Returns whether it
   moved any. */
static PetscErrorCode BalanceSubdomains(PC pc, std::vector<std::vector<PetscInt>> &parts, PetscBool *moved)
{
  PC_GDSW    *gd  = (PC_GDSW *)pc->data;
  auto       &sub = *gd->sub;
  MPI_Comm    comm;
  PetscMPIInt size, rank;

  PetscFunctionBegin;
  *moved = PETSC_FALSE;
  PetscCall(PetscObjectGetComm((PetscObject)pc, &comm));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (size == 1) PetscFunctionReturn(0);
  PetscMPIInt nloc;
  PetscCall(PetscMPIIntCast((PetscInt)sub.size(), &nloc));
  std::vector<PetscMPIInt> count(size), displ(size + 1, 0);
  PetscCallMPI(MPI_Allgather(&nloc, 1, MPI_INT, count.data(), 1, MPI_INT, comm));
  for (PetscMPIInt r = 0; r < size; r++) displ[r + 1] = displ[r] + count[r];
  std::vector<PetscInt> mine(nloc), w(displ[size]);
  for (PetscMPIInt i = 0; i < nloc; i++) mine[i] = (PetscInt)sub[i].nodes.size();
  PetscCallMPI(MPI_Allgatherv(mine.data(), nloc, MPIU_INT, w.data(), count.data(), displ.data(), MPIU_INT, comm));
  double total = 0, heaviest = 0;
  for (PetscMPIInt r = 0; r < size; r++) {
    double load = 0;
    for (PetscMPIInt j = displ[r]; j < displ[r + 1]; j++) load += (double)w[j];
    total += load, heaviest = std::max(heaviest, load);
  }
  if (heaviest <= 1.5 * total / size) PetscFunctionReturn(0);
  /* destination of each subdomain: the rank whose share of the nodes contains its middle */
  std::vector<std::vector<PetscInt>> out(size);
  double before = 0;
  for (PetscMPIInt j = 0; j < displ[size]; j++) {
    const PetscMPIInt dest = std::min<PetscMPIInt>(size - 1, (PetscMPIInt)(size * (before + 0.5 * (double)w[j]) / total));
    before += (double)w[j];
    if (j < displ[rank] || j >= displ[rank + 1]) continue;
    const PetscInt i = j - displ[rank];
    auto          &o = out[dest];
    o.push_back(sub[i].gid);
    o.push_back((PetscInt)sub[i].nodes.size());
    o.insert(o.end(), sub[i].nodes.begin(), sub[i].nodes.end());
    o.push_back((PetscInt)parts[i].size());
    o.insert(o.end(), parts[i].begin(), parts[i].end());
  }
  std::vector<PetscInt> rbuf;
  PetscCall(SendToRanks(comm, out, rbuf));
  /* sources in rank order and each in its order: the ids stay ascending */
  sub.clear(), parts.clear();
  for (size_t k = 0; k < rbuf.size();) {
    Subdomain s;
    s.gid = rbuf[k++];
    s.nodes.assign(rbuf.begin() + k + 1, rbuf.begin() + k + 1 + rbuf[k]);
    k += 1 + rbuf[k];
    parts.emplace_back(rbuf.begin() + k + 1, rbuf.begin() + k + 1 + rbuf[k]);
    k += 1 + rbuf[k];
    sub.push_back(std::move(s));
  }
  PetscCall(PetscInfo(pc, "the ranks' rows are unbalanced (the heaviest holds %.2f times the mean of the subdomains' nodes): the subdomains are redistributed, %zu on this rank\n", heaviest * size / total, sub.size()));
  *moved = PETSC_TRUE;
  PetscFunctionReturn(0);
}

/* A MATIS operator: each rank's subdomain (the rows of its local matrix) split like a rank's
   rows of an AIJ operator (the size rule or -pc_gdsw_subdomains, METIS on the local matrix's node
   graph, each part closed by its neighbours in parts of larger number), as global dof sets. The
   rank's interface with the other ranks stays an interface: its nodes lie in subdomains of both.
   The local rows of a node must be contiguous (MATIS from a DM); otherwise the subdomain stays
   whole. The parts P_p (sorted global nodes) are the base of the overlap, as for an AIJ operator. */
static PetscErrorCode MatISSubdomains(PC pc, std::vector<IS> &non, std::vector<std::vector<PetscInt>> &parts)
{
  PC_GDSW               *gd = (PC_GDSW *)pc->data;
  const PetscInt         bs = gd->bs;
  ISLocalToGlobalMapping l2g;
  Mat                    lA, lAij;
  PetscInt               n;
  const PetscInt        *idx;
  PetscBool              isAIJ;

  PetscFunctionBegin;
  PetscCall(MatISGetLocalToGlobalMapping(pc->pmat, &l2g, nullptr));
  PetscCall(ISLocalToGlobalMappingGetSize(l2g, &n));
  PetscCall(ISLocalToGlobalMappingGetIndices(l2g, &idx));
  const PetscInt requested = RequestedParts(gd, n), nn = n / bs;
  bool           nodewise  = n % bs == 0;
  for (PetscInt a = 0; a < nn && nodewise; a++)
    for (PetscInt c = 0; c < bs; c++) nodewise = nodewise && idx[a * bs + c] == idx[a * bs] + c && idx[a * bs] % bs == 0;
  if (requested == 1 || !nodewise) {
    if (requested > 1) PetscCall(PetscInfo(pc, "the MATIS subdomain of this rank is not split: the local rows of a node are not contiguous\n"));
    non.resize(1);
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, n, idx, PETSC_COPY_VALUES, &non[0]));
    PetscCall(ISLocalToGlobalMappingRestoreIndices(l2g, &idx));
    PetscFunctionReturn(0);
  }
  LocalGraph            g;
  std::vector<PetscInt> part;
  PetscInt              nparts;
  PetscCall(MatISGetLocalMat(pc->pmat, &lA));
  PetscCall(PetscObjectTypeCompare((PetscObject)lA, MATSEQAIJ, &isAIJ));
  if (isAIJ) {
    PetscCall(PetscObjectReference((PetscObject)lA));
    lAij = lA;
  } else PetscCall(MatConvert(lA, MATSEQAIJ, MAT_INITIAL_MATRIX, &lAij));
  PetscCall(MatISRestoreLocalMat(pc->pmat, &lA));
  PetscCall(BuildLocalGraph(lAij, bs, g));
  PetscCall(MatDestroy(&lAij));
  PetscCall(PartitionNodes(pc, g, requested, part));
  PetscCall(DropEmptyParts(pc, part, requested, &nparts));
  std::vector<std::vector<PetscInt>> omega(nparts);
  parts.assign(nparts, {});
  for (PetscInt a = 0; a < nn; a++) {
    parts[part[a]].push_back(idx[a * bs] / bs);
    omega[part[a]].push_back(idx[a * bs] / bs);
    for (PetscInt k = g.xadj[a]; k < g.xadj[a + 1]; k++)
      if (part[g.adj[k]] > part[a]) omega[part[a]].push_back(idx[g.adj[k] * bs] / bs);
  }
  PetscCall(ISLocalToGlobalMappingRestoreIndices(l2g, &idx));
  non.resize(nparts);
  for (PetscInt p = 0; p < nparts; p++) {
    std::sort(parts[p].begin(), parts[p].end());
    std::sort(omega[p].begin(), omega[p].end());
    omega[p].erase(std::unique(omega[p].begin(), omega[p].end()), omega[p].end());
    PetscCall(DofISOfNodes(omega[p], bs, &non[p]));
  }
  PetscCall(PetscInfo(pc, "the MATIS subdomain of this rank (%" PetscInt_FMT " dofs) split into %" PetscInt_FMT "\n", n, nparts));
  PetscFunctionReturn(0);
}

/* The application's index sets must name rows of the operator: a wrong one would otherwise end
   in PETSc's generic hash error or, negative, in a crash. */
static PetscErrorCode CheckGivenIndices(PC pc, PetscInt n, IS sets[], const char *kind)
{
  PetscInt    N;
  PetscMPIInt rank;

  PetscFunctionBegin;
  PetscCall(MatGetSize(pc->pmat, &N, nullptr));
  PetscCallMPI(MPI_Comm_rank(PetscObjectComm((PetscObject)pc), &rank));
  for (PetscInt i = 0; i < n; i++) {
    PetscInt        m;
    const PetscInt *idx;
    PetscCall(ISGetLocalSize(sets[i], &m));
    PetscCall(ISGetIndices(sets[i], &idx));
    for (PetscInt k = 0; k < m; k++)
      PetscCheck(idx[k] >= 0 && idx[k] < N, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
                 "PCGDSWSetSubdomains(): the %s index set of subdomain %" PetscInt_FMT " on rank %d holds the index %" PetscInt_FMT " at position %" PetscInt_FMT "; the operator's global rows are 0 .. %" PetscInt_FMT,
                 kind, i, rank, idx[k], k, N - 1);
    PetscCall(ISRestoreIndices(sets[i], &idx));
  }
  PetscFunctionReturn(0);
}

/* Element-based subdomains from the caller or a MATIS operator. */
static PetscErrorCode GivenSubdomains(PC pc, PetscInt n, IS non[], std::vector<PetscInt> &origin)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;
  std::vector<std::vector<PetscInt>> nodes;
  PetscInt first;

  PetscFunctionBegin;
  for (PetscInt i = 0; i < n; i++) {
    std::vector<PetscInt> nd;
    PetscCall(NodesOfIS(non[i], gd->bs, i, nd));
    if (nd.empty()) PetscCall(PetscInfo(pc, "subdomain %" PetscInt_FMT " on this rank is empty and dropped\n", i));
    else nodes.push_back(nd), origin.push_back(i);
  }
  const PetscInt nk = (PetscInt)nodes.size();
  PetscCallMPI(MPI_Scan(&nk, &first, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)pc)));
  first -= nk;
  gd->sub->assign(nk, Subdomain());
  for (PetscInt i = 0; i < nk; i++) {
    (*gd->sub)[i].gid   = first + i;
    (*gd->sub)[i].nodes = nodes[i];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode GDSWBuildDecomposition(PC pc)
{
  PC_GDSW  *gd = (PC_GDSW *)pc->data;
  PetscBool isIS;
  std::vector<std::vector<PetscInt>> parts; /* algebraic or split MATIS: the disjoint P_i, base of the overlap */
  std::vector<PetscInt> origin;             /* given: index of each kept subdomain in the input */
  MPI_Comm  comm;

  PetscFunctionBegin;
  PetscCall(PetscObjectGetComm((PetscObject)pc, &comm));
  PetscCall(PetscObjectTypeCompare((PetscObject)pc->pmat, MATIS, &isIS));
  const PetscBool haveUser = (PetscBool)(gd->nUser >= 0);
  gd->balanced             = PETSC_FALSE;
  if (haveUser) {
    PetscCall(CheckGivenIndices(pc, gd->nUser, gd->userNon, "nonoverlapping"));
    if (gd->userOvl) PetscCall(CheckGivenIndices(pc, gd->nUser, gd->userOvl, "overlapping"));
    PetscCall(GivenSubdomains(pc, gd->nUser, gd->userNon, origin));
  } else if (isIS) {
    std::vector<IS> non;
    PetscCall(MatISSubdomains(pc, non, parts));
    PetscCall(GivenSubdomains(pc, (PetscInt)non.size(), non.data(), origin));
    for (IS &is : non) PetscCall(ISDestroy(&is));
  } else {
    PetscBool moved;
    PetscCall(AlgebraicSubdomains(pc, parts));
    PetscCall(BalanceSubdomains(pc, parts, &moved));
    PetscCallMPI(MPIU_Allreduce(&moved, &gd->balanced, 1, MPIU_BOOL, MPI_LOR, comm));
  }
  PetscInt nloc = (PetscInt)gd->sub->size();
  PetscCallMPI(MPIU_Allreduce(&nloc, &gd->nGlobalSubdomains, 1, MPIU_INT, MPI_SUM, comm));
  gd->nsubRank0 = nloc;
  PetscCallMPI(MPI_Bcast(&gd->nsubRank0, 1, MPIU_INT, 0, comm));
  PetscCheck(gd->nGlobalSubdomains > 0, comm, PETSC_ERR_ARG_WRONG, "PCGDSW: the decomposition has no nonempty subdomain");

  /* overlapping subdomains: the caller's, or graph layers around P_i (algebraic, split MATIS) or Omega~_i */
  std::vector<IS> ovl(nloc);
  for (PetscInt i = 0; i < nloc; i++) {
    gdsw::Subdomain &s = (*gd->sub)[i];
    PetscCall(DofISOfNodes(s.nodes, gd->bs, &s.nonoverlap));
    if (haveUser && gd->userOvl) PetscCall(ISDuplicate(gd->userOvl[origin[i]], &ovl[i])); /* merged with Omega~_i below */
    else if (!parts.empty()) PetscCall(DofISOfNodes(parts[i], gd->bs, &ovl[i]));
    else PetscCall(ISDuplicate(s.nonoverlap, &ovl[i]));
  }
  const PetscBool layers = (PetscBool)!(haveUser && gd->userOvl);
  if (layers && gd->overlap > 0) {
    /* MatIncreaseOverlap() is collective but returns early on ranks with no index set */
    IS dummy = nullptr;
    if (!nloc) PetscCall(ISCreateGeneral(PETSC_COMM_SELF, 0, nullptr, PETSC_COPY_VALUES, &dummy));
    PetscCall(MatIncreaseOverlap(gd->A, nloc ? nloc : 1, nloc ? ovl.data() : &dummy, gd->overlap));
    PetscCall(ISDestroy(&dummy));
  }
  for (PetscInt i = 0; i < nloc; i++) {
    gdsw::Subdomain &s = (*gd->sub)[i];
    std::vector<PetscInt> nd;
    PetscCall(NodesOfIS(ovl[i], 1, i, nd)); /* dof ids, sorted */
    std::vector<PetscInt> nodes;
    for (PetscInt d : nd)
      if (nodes.empty() || nodes.back() != d / gd->bs) nodes.push_back(d / gd->bs);
    std::vector<PetscInt> merged;
    std::set_union(nodes.begin(), nodes.end(), s.nodes.begin(), s.nodes.end(), std::back_inserter(merged));
    PetscCall(DofISOfNodes(merged, gd->bs, &s.overlap));
    PetscCall(ISDestroy(&ovl[i]));
  }
  PetscFunctionReturn(0);
}

/* The arrays of a submatrix made by GDSWSubmatrix(); j and a are left uninitialised (filled once:
   zeroing them first was a second pass over fresh pages). */
struct HugeDelete {
  void operator()(void *p) const { GDSWHugeFree(p); }
};
struct CSR {
  std::vector<PetscInt>                      i;
  std::unique_ptr<PetscInt[], HugeDelete>    j;
  std::unique_ptr<PetscScalar[], HugeDelete> a;
};

static PetscErrorCode DestroyCSR(void *ctx)
{
  PetscFunctionBegin;
  delete (CSR *)ctx;
  PetscFunctionReturn(0);
}

/* S = M(rows, cols) for a sequential AIJ M and sorted positions: a marker per column of M maps
   it to its column of S, so a row costs its length. (MatCreateSubMatrices() with one index set per
   subdomain made a pass over the rank's rows per set, and MatCreateSubMatrix() sorts every row:
   2.1 of 10.8 s of the set-up with 85 subdomains per rank.) With MAT_REUSE_MATRIX the values of S
   are refreshed in place (the same pattern). bs > 1 is S's block size when it holds whole nodes. */
PetscErrorCode GDSWSubmatrix(Mat M, IS rows, IS cols, PetscInt bs, MatReuse reuse, Mat *S)
{
  const PetscInt    *ia, *ja, *r, *c;
  const PetscScalar *va;
  PetscInt           m, ncolsM, nr, nc;
  PetscBool          done;

  PetscFunctionBegin;
  PetscCall(MatGetSize(M, nullptr, &ncolsM));
  PetscCall(ISGetLocalSize(rows, &nr));
  PetscCall(ISGetLocalSize(cols, &nc));
  PetscCall(ISGetIndices(rows, &r));
  PetscCall(ISGetIndices(cols, &c));
  std::vector<PetscInt> map(ncolsM, -1);
  for (PetscInt j = 0; j < nc; j++) map[c[j]] = j;
  PetscCall(MatGetRowIJ(M, 0, PETSC_FALSE, PETSC_FALSE, &m, &ia, &ja, &done));
  PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_SUP, "PCGDSW: cannot access the rows of a local matrix");
  PetscCall(MatSeqAIJGetArrayRead(M, &va));
  if (reuse == MAT_INITIAL_MATRIX) {
    /* S uses the arrays of a CSR object composed with it (freed with S): MatSeqAIJSetPreallocationCSR()
       inserted row by row and took 1.3 of 9.2 s of the set-up */
    auto *csr = new CSR;
    csr->i.assign(nr + 1, 0);
    for (PetscInt k = 0; k < nr; k++) { /* row lengths first: growing the arrays moved them repeatedly */
      PetscInt len = 0;
      for (PetscInt e = ia[r[k]]; e < ia[r[k] + 1]; e++) len += map[ja[e]] >= 0;
      csr->i[k + 1] = csr->i[k] + len;
    }
    const PetscInt nnz = std::max<PetscInt>(csr->i[nr], 1); /* nonnull arrays */
    csr->j.reset((PetscInt *)GDSWHugeMalloc(nnz * sizeof(PetscInt)));
    csr->a.reset((PetscScalar *)GDSWHugeMalloc(nnz * sizeof(PetscScalar)));
    if (!csr->j || !csr->a) {
      delete csr;
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_MEM, "PCGDSW: out of memory for a subdomain matrix of %" PetscInt_FMT " nonzeros", nnz);
    }
    for (PetscInt k = 0, p = 0; k < nr; k++)
      for (PetscInt e = ia[r[k]]; e < ia[r[k] + 1]; e++)
        if (map[ja[e]] >= 0) csr->j[p] = map[ja[e]], csr->a[p++] = va[e];
    PetscContainer container;
    PetscCall(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, nr, nc, csr->i.data(), csr->j.get(), csr->a.get(), S));
    PetscCall(PetscContainerCreate(PETSC_COMM_SELF, &container));
    PetscCall(PetscContainerSetPointer(container, csr));
    PetscCall(PetscContainerSetUserDestroy(container, DestroyCSR));
    PetscCall(PetscObjectCompose((PetscObject)*S, "PCGDSW_CSR", (PetscObject)container));
    PetscCall(PetscContainerDestroy(&container));
    if (bs > 1) PetscCall(MatSetBlockSize(*S, bs));
  } else {
    PetscScalar *sa;
    PetscInt     p = 0;
    PetscCall(MatSeqAIJGetArrayWrite(*S, &sa));
    for (PetscInt k = 0; k < nr; k++)
      for (PetscInt e = ia[r[k]]; e < ia[r[k] + 1]; e++)
        if (map[ja[e]] >= 0) sa[p++] = va[e];
    PetscCall(MatSeqAIJRestoreArrayWrite(*S, &sa));
  }
  PetscCall(MatSeqAIJRestoreArrayRead(M, &va));
  PetscCall(MatRestoreRowIJ(M, 0, PETSC_FALSE, PETSC_FALSE, &m, &ia, &ja, &done));
  PetscCall(ISRestoreIndices(rows, &r));
  PetscCall(ISRestoreIndices(cols, &c));
  PetscFunctionReturn(0);
}

/* Positions of the sorted dofs of sub within the sorted dofs of all. */
static PetscErrorCode PositionsIn(IS sub, const std::vector<PetscInt> &all, IS *pos)
{
  PetscInt        n;
  const PetscInt *idx;

  PetscFunctionBegin;
  PetscCall(ISGetLocalSize(sub, &n));
  PetscCall(ISGetIndices(sub, &idx));
  std::vector<PetscInt> p(n);
  for (PetscInt k = 0; k < n; k++) p[k] = (PetscInt)(std::lower_bound(all.begin(), all.end(), idx[k]) - all.begin());
  PetscCall(ISRestoreIndices(sub, &idx));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, n, p.data(), PETSC_COPY_VALUES, pos));
  PetscFunctionReturn(0);
}

/* A(Omega_i^delta, Omega_i^delta): one parallel extraction of the rank's union U of overlapping
   subdomains, A(U, U), then each subdomain's matrix from it. A(Omega~_i, Omega~_i) is not
   copied: it is read in the rows of Omega~_i (inside Omega_i^delta) through ovlToNon (its copies
   were 350 MiB of the 4.99 GiB peak on the seed-size wall). A(U, U) is as large as the rank's
   part of A; it is kept for the set-ups with the same pattern, which refresh its values in place
   (the first extraction's allocations and page faults were 1.5 s of each Newton step's set-up on
   the P2 wall of tube #1 at the benchmark's size). On one rank A itself is A(U, U). */
PetscErrorCode GDSWExtractSubdomainMatrices(PC pc, MatReuse reuse)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;
  auto    &sub = *gd->sub;
  Mat       AU;
  PetscBool sequential;

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompare((PetscObject)gd->A, MATSEQAIJ, &sequential));
  if (reuse == MAT_INITIAL_MATRIX && !sequential) { /* U, and each Omega_i^delta's positions in it */
    std::vector<PetscInt> U;
    for (auto &s : sub) {
      PetscInt        no;
      const PetscInt *ov;
      PetscCall(ISGetLocalSize(s.overlap, &no));
      PetscCall(ISGetIndices(s.overlap, &ov));
      U.insert(U.end(), ov, ov + no);
      PetscCall(ISRestoreIndices(s.overlap, &ov));
    }
    std::sort(U.begin(), U.end());
    U.erase(std::unique(U.begin(), U.end()), U.end());
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)U.size(), U.data(), PETSC_COPY_VALUES, &gd->isU));
    PetscCall(ISSetInfo(gd->isU, IS_SORTED, IS_LOCAL, PETSC_TRUE, PETSC_TRUE));
    for (auto &s : sub) PetscCall(PositionsIn(s.overlap, U, &s.ovlInU));
  }
  if (sequential) AU = gd->A; /* one rank: U is every row, A(U, U) is A */
  else {
    PetscCall(MatCreateSubMatrices(gd->A, 1, &gd->isU, &gd->isU, gd->AU ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &gd->AU));
    AU = gd->AU[0];
  }
  for (auto &s : sub) {
    IS rows = sequential ? s.overlap : s.ovlInU;
    PetscCall(GDSWSubmatrix(AU, rows, rows, gd->bs, reuse, &s.Aovl));
    if (reuse == MAT_INITIAL_MATRIX) {
      const PetscInt *ov;
      PetscInt        no;
      PetscCall(ISGetLocalSize(s.overlap, &no));
      PetscCall(ISGetIndices(s.overlap, &ov));
      PetscCall(PositionsIn(s.nonoverlap, std::vector<PetscInt>(ov, ov + no), &s.nonInOvl));
      PetscCall(ISRestoreIndices(s.overlap, &ov));
      const PetscInt *pos;
      PetscInt        nn;
      PetscCall(ISGetLocalSize(s.nonInOvl, &nn));
      PetscCall(ISGetIndices(s.nonInOvl, &pos));
      s.ovlToNon.assign(no, -1);
      for (PetscInt r = 0; r < nn; r++) s.ovlToNon[pos[r]] = r;
      PetscCall(ISRestoreIndices(s.nonInOvl, &pos));
    }
  }
  PetscFunctionReturn(0);
}
