// SPDX-License-Identifier: BSD-2-Clause
/* Output for ParaView: a time series of fields on quadratic tetrahedra (Tetrahedron_10) in
   HDF5, described by an XDMF file that is rewritten after every frame, so it is valid whenever
   the run stops. A series has one part per region (the fluid, the wall), each a mesh with its
   node numbering from one P2 field's cells, written once, and per frame one dataset
   <part>/fields/<name>_<k> per field: P2 fields at their nodes, P1 fields (pressure) at the
   vertices and, linearly, at the edge midpoints. Several parts are a spatial collection per
   frame; one part has no group prefix. With several parts each is also written alone,
   <name>_<part>.xdmf (XdmfPartFile): ParaView's reader takes a spatial collection for pieces of
   one dataset, a file of one part for a dataset of its own. */
#pragma once

#include "discretization/cells.h"
#include <string>
#include <vector>

namespace fsi {

/* A quantity computed from the solution rather than solved for (the wall shear stress): nc
   values per point of the DM's chart, zero where it has none, refreshed before each frame. */
struct PointField {
  std::string                   name;
  PetscInt                      nc;
  const std::vector<PetscReal> *values;
};

/* Fields written on the P2 cells of one region: one part of the XDMF output. */
struct OutputPart {
  std::string                                   name; /* "fluid", "wall" */
  const FieldCells                             *mesh = nullptr;
  std::vector<std::pair<std::string, PetscInt>> fields;
  std::vector<PointField>                       derived;
};


struct XdmfField {
  std::string                   name;
  PetscInt                      field, nc = 0;
  Vec                           values = nullptr; /* nc per owned node */
  const std::vector<PetscReal> *point  = nullptr; /* a PointField's values; field is then -1 */
};

struct XdmfPart {
  std::string            name, group;     /* group: "" (one part) or "/<name>" in the HDF5 file */
  const FieldCells      *cells = nullptr;
  std::vector<XdmfField> fields;
  std::vector<PetscInt>  node;            /* per local point: global node number, -1 if no node */
  std::vector<char>      owned;           /* per local point: this rank owns it */
  PetscInt               nNodes = 0, nCells = 0;
};

struct XdmfSeries {
  std::string            xdmf, h5;
  DM                     dm = nullptr;
  std::vector<XdmfPart>  parts;
  std::vector<PetscReal> times; /* frames written */
};

/* Open the series `file` (<name>.xdmf, as ReadScene checks; the data go to <name>.h5) of dm's
   fields on the parts {name, P2 cells (kept by reference), {field name, field number}}. With
   `times` (a restart), the frames already written at those times are kept and the series
   continues. */
PetscErrorCode XdmfOpen(const char *file, DM dm, const std::vector<OutputPart> &parts, const std::vector<PetscReal> &times, XdmfSeries &s);
PetscErrorCode XdmfWriteFrame(XdmfSeries &s, PetscReal t, Vec x);
/* The file of one part of the series `xdmf`: <name>_<part>.xdmf. */
std::string XdmfPartFile(const std::string &xdmf, const std::string &part);
PetscErrorCode XdmfClose(XdmfSeries &s);

} // namespace fsi
