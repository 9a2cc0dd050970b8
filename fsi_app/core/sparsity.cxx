// SPDX-License-Identifier: BSD-2-Clause
#include "sparsity.h"
#include <algorithm>

namespace fsi {

Sparsity::Sparsity(PetscLayout rows, PetscLayout cols) : rmap(rows), cStart(cols->rstart), cEnd(cols->rend) {}

/* owned columns are their offset in the column range; the others are numbered after them */
PetscInt Sparsity::Compact(PetscInt col)
{
  if (col < 0) return -1;
  if (col >= cStart && col < cEnd) return col - cStart;
  auto it = ghostIndex.find(col);
  if (it != ghostIndex.end()) return it->second;
  const PetscInt c = (cEnd - cStart) + (PetscInt)ghostCols.size();
  ghostCols.push_back(col);
  ghostIndex.emplace(col, c);
  return c;
}

void Sparsity::Couple(PetscInt nr, const PetscInt rows[], PetscInt nc, const PetscInt cols[])
{
  stamps.push_back(nr);
  stamps.push_back(nc);
  stamps.insert(stamps.end(), rows, rows + nr);
  for (PetscInt j = 0; j < nc; j++) stamps.push_back(Compact(cols[j]));
}

/* Calls f(s, rows, nr, cols, nc) for every stamp (s: its offset in stamps). */
template <class F>
static void ForEachStamp(const std::vector<PetscInt> &stamps, F f)
{
  for (size_t pos = 0; pos < stamps.size(); pos += 2 + stamps[pos] + stamps[pos + 1]) f(pos, &stamps[pos + 2], stamps[pos], &stamps[pos + 2 + stamps[pos]], stamps[pos + 1]);
}

PetscErrorCode Sparsity::LayOut(Mat P)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)P);
  PetscMPIInt size;
  const PetscInt rStart = rmap->rstart, m = rmap->rend - rmap->rstart, nOwn = cEnd - cStart;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  /* the stamps of each owned row (CSR), and of each row another rank owns */
  std::vector<size_t>                               rowStart(m + 1, 0), rowStamp;
  std::unordered_map<PetscInt, std::vector<size_t>> ghostRows;
  ForEachStamp(stamps, [&](size_t s, const PetscInt *rows, PetscInt nr, const PetscInt *, PetscInt) {
    for (PetscInt i = 0; i < nr; i++) {
      if (rows[i] < 0) continue;
      if (rows[i] >= rStart && rows[i] < rStart + m) rowStart[rows[i] - rStart + 1]++;
      else ghostRows[rows[i]].push_back(s);
    }
  });
  for (PetscInt i = 0; i < m; i++) rowStart[i + 1] += rowStart[i];
  rowStamp.resize(rowStart[m]);
  {
    std::vector<size_t> next(rowStart.begin(), rowStart.end() - 1);
    ForEachStamp(stamps, [&](size_t s, const PetscInt *rows, PetscInt nr, const PetscInt *, PetscInt) {
      for (PetscInt i = 0; i < nr; i++)
        if (rows[i] >= rStart && rows[i] < rStart + m) rowStamp[next[rows[i] - rStart]++] = s;
    });
  }

  /* the distinct columns of one row, by a marker per compact column */
  std::vector<PetscInt> mark;
  auto columns = [&](PetscInt tag, const size_t *s, size_t ns, const PetscInt *extra, size_t ne, std::vector<PetscInt> &out) {
    out.clear();
    auto add = [&](PetscInt c) {
      if (c >= 0 && mark[c] != tag) mark[c] = tag, out.push_back(c);
    };
    for (size_t k = 0; k < ns; k++) {
      const PetscInt *st = &stamps[s[k]], *cols = st + 2 + st[0];
      for (PetscInt j = 0; j < st[1]; j++) add(cols[j]);
    }
    for (size_t k = 0; k < ne; k++) add(extra[k]);
  };
  auto global = [&](PetscInt c) { return c < nOwn ? c + cStart : ghostCols[c - nOwn]; };

  /* rows of other ranks: (row, n, n global columns) to their owners */
  std::vector<std::vector<PetscInt>> out(size);
  {
    std::vector<PetscInt> cols;
    mark.assign(nOwn + ghostCols.size(), -1);
    PetscInt tag = 0;
    for (const auto &g : ghostRows) {
      PetscMPIInt owner;
      PetscCall(PetscLayoutFindOwner(rmap, g.first, &owner));
      columns(tag++, g.second.data(), g.second.size(), nullptr, 0, cols);
      out[owner].push_back(g.first);
      out[owner].push_back((PetscInt)cols.size());
      for (PetscInt c : cols) out[owner].push_back(global(c));
    }
  }
  std::vector<PetscMPIInt> sendCount(size), recvCount(size), sendOff(size + 1, 0), recvOff(size + 1, 0);
  for (PetscMPIInt r = 0; r < size; r++) sendCount[r] = (PetscMPIInt)out[r].size();
  PetscCallMPI(MPI_Alltoall(sendCount.data(), 1, MPI_INT, recvCount.data(), 1, MPI_INT, comm));
  for (PetscMPIInt r = 0; r < size; r++) sendOff[r + 1] = sendOff[r] + sendCount[r], recvOff[r + 1] = recvOff[r] + recvCount[r];
  std::vector<PetscInt> sendBuf(sendOff[size]), recvBuf(recvOff[size]);
  for (PetscMPIInt r = 0; r < size; r++) std::copy(out[r].begin(), out[r].end(), sendBuf.begin() + sendOff[r]);
  out.clear();
  PetscCallMPI(MPI_Alltoallv(sendBuf.data(), sendCount.data(), sendOff.data(), MPIU_INT, recvBuf.data(), recvCount.data(), recvOff.data(), MPIU_INT, comm));

  /* the received columns of each owned row (CSR, compact numbering) */
  std::vector<size_t>   extraStart(m + 1, 0);
  std::vector<PetscInt> extra;
  for (size_t pos = 0; pos < recvBuf.size(); pos += 2 + recvBuf[pos + 1]) {
    PetscCheck(recvBuf[pos] >= rStart && recvBuf[pos] < rStart + m, comm, PETSC_ERR_PLIB, "row %" PetscInt_FMT " was sent to a rank that does not own it", recvBuf[pos]);
    extraStart[recvBuf[pos] - rStart + 1] += recvBuf[pos + 1];
  }
  for (PetscInt i = 0; i < m; i++) extraStart[i + 1] += extraStart[i];
  extra.resize(extraStart[m]);
  {
    std::vector<size_t> next(extraStart.begin(), extraStart.end() - 1);
    for (size_t pos = 0; pos < recvBuf.size(); pos += 2 + recvBuf[pos + 1])
      for (PetscInt j = 0; j < recvBuf[pos + 1]; j++) extra[next[recvBuf[pos] - rStart]++] = Compact(recvBuf[pos + 2 + j]);
  }

  /* each owned row's distinct columns, sorted: counts for the preallocation, then the entries */
  std::vector<PetscInt> dnnz(m), onnz(m), ja, cols;
  std::vector<size_t>   ia(m + 1, 0);
  mark.assign(nOwn + ghostCols.size(), -1);
  for (PetscInt i = 0; i < m; i++) {
    columns(i, rowStamp.data() + rowStart[i], rowStart[i + 1] - rowStart[i], extra.data() + extraStart[i], extraStart[i + 1] - extraStart[i], cols);
    dnnz[i] = onnz[i] = 0;
    for (PetscInt &c : cols) {
      if (c < nOwn) dnnz[i]++;
      else onnz[i]++;
      c = global(c);
    }
    std::sort(cols.begin(), cols.end());
    ja.insert(ja.end(), cols.begin(), cols.end());
    ia[i + 1] = ja.size();
  }
  rowStamp.clear(), extra.clear();
  PetscCall(MatSeqAIJSetPreallocation(P, 0, dnnz.data()));
  PetscCall(MatMPIAIJSetPreallocation(P, 0, dnnz.data(), 0, onnz.data()));
  PetscInt widest = 0;
  for (PetscInt i = 0; i < m; i++) widest = std::max(widest, dnnz[i] + onnz[i]);
  std::vector<PetscScalar> zeros(widest, 0.0);
  for (PetscInt i = 0; i < m; i++) {
    const PetscInt row = rStart + i;
    PetscCall(MatSetValues(P, 1, &row, (PetscInt)(ia[i + 1] - ia[i]), ja.data() + ia[i], zeros.data(), INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatSetOption(P, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  PetscFunctionReturn(0);
}

} // namespace fsi
