/* Output for ParaView: a time series of fields on quadratic tetrahedra (Tetrahedron_10) in
   HDF5, described by an XDMF file that is rewritten after every frame, so it is valid whenever
   the run stops. The mesh and its node numbering come from one P2 field's cells and are written
   once; each frame holds one dataset /fields/<name>_<k> per field: P2 fields at their nodes, P1
   fields (pressure) at the vertices and, linearly, at the edge midpoints. */
#pragma once

#include "discretization/cells.h"
#include <string>
#include <vector>

namespace fsi {

struct XdmfField {
  std::string name;
  PetscInt    field, nc = 0;
  Vec         values = nullptr; /* nc per owned node */
};

struct XdmfSeries {
  std::string            xdmf, h5;
  std::vector<XdmfField> fields;
  DM                     dm     = nullptr;
  const FieldCells         *cells  = nullptr;
  std::vector<PetscInt>  node;             /* per local point: global node number, -1 if no node */
  std::vector<char>      owned;            /* per local point: this rank owns it */
  PetscInt               nNodes = 0, nCells = 0;
  std::vector<PetscReal> times;            /* frames written */
};

/* Open the series `file` (.xdmf; the data go to the same name with .h5) on the mesh of the P2
   `cells` (kept by reference) for the fields {name, field number} of dm. With `times` (a
   restart), the frames already written at those times are kept and the series continues. */
PetscErrorCode XdmfOpen(const char *file, DM dm, const FieldCells &cells, const std::vector<std::pair<std::string, PetscInt>> &fields, const std::vector<PetscReal> &times, XdmfSeries &s);
PetscErrorCode XdmfWriteFrame(XdmfSeries &s, PetscReal t, Vec x);
PetscErrorCode XdmfClose(XdmfSeries &s);

} // namespace fsi
