/* Output for ParaView: a time series of one P2 vector field as quadratic tetrahedra
   (Tetrahedron_10) in HDF5, described by an XDMF file that is rewritten after every frame, so
   it is valid whenever the run stops. Mesh and node numbering are written once; each frame is
   one dataset /fields/<name>_<k>. */
#pragma once

#include "discretization/cells.h"
#include <string>
#include <vector>

namespace fsi {

struct XdmfSeries {
  std::string            xdmf, h5, name;
  DM                     dm     = nullptr;
  const FieldCells         *cells  = nullptr;
  std::vector<PetscInt>  node;             /* per local point: global node number, -1 if no node */
  std::vector<char>      owned;            /* per local point: this rank owns it */
  PetscInt               nNodes = 0, nCells = 0;
  Vec                    values = nullptr; /* 3 per owned node */
  std::vector<PetscReal> times;            /* frames written */
};

/* Open the series `file` (.xdmf; the data go to the same name with .h5) for the field of dm
   on `cells` (kept by reference). With `times` (a restart), the frames already written
   at those times are kept and the series continues. */
PetscErrorCode XdmfOpen(const char *file, DM dm, const FieldCells &cells, const char *name, const std::vector<PetscReal> &times, XdmfSeries &s);
PetscErrorCode XdmfWriteFrame(XdmfSeries &s, PetscReal t, Vec x);
PetscErrorCode XdmfClose(XdmfSeries &s);

} // namespace fsi
