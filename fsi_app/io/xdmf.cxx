// SPDX-License-Identifier: BSD-2-Clause
#include "xdmf.h"
#include "discretization/conditions.h"
#include "discretization/nodes.h"
#include "mesh/mesh.h"
#include <petscsf.h>
#include <petscviewerhdf5.h>

namespace fsi {

/* Tetrahedron_10 (as VTK's quadratic tetrahedron): vertices, then edges 01 12 02 03 13 23. */
static const int XdmfNode[10] = {0, 1, 2, 3, 4 + 0, 4 + 3, 4 + 1, 4 + 2, 4 + 4, 4 + 5};

/* Call f(point, global node number, owned) for every point that carries the field. */
template <class F>
static PetscErrorCode ForEachNode(const XdmfPart &s, F f)
{
  PetscFunctionBegin;
  for (PetscInt p = 0; p < (PetscInt)s.node.size(); p++)
    if (s.node[p] >= 0) PetscCall(f(p, s.node[p], (PetscBool)s.owned[p]));
  PetscFunctionReturn(0);
}

/* One part's grid at frame k. */
static void WriteGrid(FILE *fp, const XdmfPart &s, const std::string &h5, size_t k, PetscReal t, const char *indent)
{
  std::fprintf(fp, "%s<Grid Name=\"%s\" GridType=\"Uniform\">\n%s <Time Value=\"%.10g\"/>\n", indent, s.name.c_str(), indent, (double)t);
  std::fprintf(fp, "%s <Topology TopologyType=\"Tetrahedron_10\" NumberOfElements=\"%" PetscInt_FMT "\">\n%s  <DataItem Dimensions=\"%" PetscInt_FMT " 10\" NumberType=\"Int\" Precision=\"%d\" Format=\"HDF\">%s:%s/mesh/topology</DataItem>\n%s </Topology>\n", indent, s.nCells, indent, s.nCells, (int)sizeof(PetscInt), h5.c_str(), s.group.c_str(), indent);
  std::fprintf(fp, "%s <Geometry GeometryType=\"XYZ\">\n%s  <DataItem Dimensions=\"%" PetscInt_FMT " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">%s:%s/mesh/coordinates</DataItem>\n%s </Geometry>\n", indent, indent, s.nNodes, h5.c_str(), s.group.c_str(), indent);
  for (const XdmfField &f : s.fields)
    std::fprintf(fp, "%s <Attribute Name=\"%s\" AttributeType=\"%s\" Center=\"Node\">\n%s  <DataItem Dimensions=\"%" PetscInt_FMT "%s\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">%s:%s/fields/%s_%zu</DataItem>\n%s </Attribute>\n", indent, f.name.c_str(), f.nc == 1 ? "Scalar" : "Vector", indent, s.nNodes, f.nc == 1 ? "" : " 3", h5.c_str(), s.group.c_str(), f.name.c_str(), k, indent);
  std::fprintf(fp, "%s</Grid>\n", indent);
}

/* The series of `parts` in `file`: one part a temporal collection of its grids, several a
   spatial collection per frame. Written to a temporary file and renamed: always whole. */
static PetscErrorCode WriteSeries(const XdmfSeries &s, const std::string &file, const std::vector<const XdmfPart *> &parts)
{
  const std::string h5 = s.h5.substr(s.h5.find_last_of('/') + 1), tmp = file + ".tmp"; /* the data beside the .xdmf */
  FILE             *fp = std::fopen(tmp.c_str(), "w");

  PetscFunctionBegin;
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-output %s: cannot write the file %s", s.xdmf.c_str(), file.c_str());
  std::fprintf(fp, "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n  <Grid Name=\"%s\" GridType=\"Collection\" CollectionType=\"Temporal\">\n", parts.size() == 1 ? parts[0]->name.c_str() : "solution");
  for (size_t k = 0; k < s.times.size(); k++) {
    if (parts.size() == 1) WriteGrid(fp, *parts[0], h5, k, s.times[k], "   ");
    else {
      std::fprintf(fp, "   <Grid Name=\"frame %zu\" GridType=\"Collection\" CollectionType=\"Spatial\">\n    <Time Value=\"%.10g\"/>\n", k, (double)s.times[k]);
      for (const XdmfPart *p : parts) WriteGrid(fp, *p, h5, k, s.times[k], "    ");
      std::fprintf(fp, "   </Grid>\n");
    }
  }
  std::fprintf(fp, "  </Grid>\n </Domain>\n</Xdmf>\n");
  std::fclose(fp);
  PetscCheck(std::rename(tmp.c_str(), file.c_str()) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "-output %s: cannot rename %s", s.xdmf.c_str(), tmp.c_str());
  PetscFunctionReturn(0);
}

/* The whole series and, with several parts, each part alone in <name>_<part>.xdmf: ParaView's
   XDMF reader takes a spatial collection for pieces of one dataset (the wall and the fluid
   merged, their fields mixed), a file of one part for a dataset of its own. */
static PetscErrorCode WriteXdmf(const XdmfSeries &s)
{
  PetscMPIInt                  rank;
  std::vector<const XdmfPart *> all;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(PetscObjectComm((PetscObject)s.dm), &rank));
  if (rank) PetscFunctionReturn(0);
  for (const XdmfPart &p : s.parts) all.push_back(&p);
  PetscCall(WriteSeries(s, s.xdmf, all));
  if (all.size() > 1)
    for (const XdmfPart *p : all) PetscCall(WriteSeries(s, XdmfPartFile(s.xdmf, p->name), {p}));
  PetscFunctionReturn(0);
}

std::string XdmfPartFile(const std::string &xdmf, const std::string &part)
{
  return xdmf.substr(0, xdmf.size() - 5) + "_" + part + ".xdmf";
}

/* The global numbering of the field's nodes: each rank numbers the node points it owns after
   those of lower ranks, and the point SF sends the numbers to the ranks that see them as ghosts. */
static PetscErrorCode NumberNodes(DM dm, XdmfPart &s)
{
  MPI_Comm          comm = PetscObjectComm((PetscObject)dm);
  PetscSection      local;
  PetscSF           sf;
  PetscInt          pStart, pEnd, owned = 0, first = 0;

  PetscFunctionBegin;
  PetscCall(DMGetLocalSection(dm, &local));
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(OwnedPoints(dm, s.owned));
  s.node.assign(pEnd, -1);
  for (PetscInt p = pStart; p < pEnd; p++) {
    PetscInt dof;
    PetscCall(PetscSectionGetFieldDof(local, p, s.cells->field, &dof));
    if (dof && s.owned[p]) s.node[p] = owned++;
  }
  PetscCallMPI(MPI_Exscan(&owned, &first, 1, MPIU_INT, MPI_SUM, comm));
  for (PetscInt &n : s.node)
    if (n >= 0) n += first;
  std::vector<PetscInt> sent(s.node);
  PetscCall(PetscSFBcastBegin(sf, MPIU_INT, sent.data(), s.node.data(), MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(sf, MPIU_INT, sent.data(), s.node.data(), MPI_REPLACE));
  for (XdmfField &f : s.fields) {
    if (!f.point) PetscCall(PetscSectionGetFieldComponents(local, f.field, &f.nc));
    PetscCall(VecCreateMPI(comm, f.nc * owned, PETSC_DETERMINE, &f.values));
    PetscCall(VecSetBlockSize(f.values, f.nc));
  }
  PetscCallMPI(MPIU_Allreduce(&owned, &s.nNodes, 1, MPIU_INT, MPI_SUM, comm));
  PetscFunctionReturn(0);
}

/* Node coordinates and the Tetrahedron_10 connectivity in global node numbers. */
static PetscErrorCode MeshData(DM dm, XdmfPart &s, Vec *coordinates, IS *topology)
{
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  Vec      coords;
  PetscInt rStart;

  PetscFunctionBegin;
  PetscInt owned;
  PetscCall(VecGetLocalSize(s.fields[0].values, &owned));
  PetscCall(VecCreateMPI(comm, 3 * (owned / s.fields[0].nc), PETSC_DETERMINE, &coords)); /* the nodes' ownership */
  PetscCall(VecSetBlockSize(coords, 3));
  PetscCall(PetscObjectSetName((PetscObject)coords, "coordinates"));
  PetscCall(VecGetOwnershipRange(coords, &rStart, nullptr));
  PetscScalar *xa;
  PetscCall(VecGetArray(coords, &xa));
  PetscCall(ForEachNode(s, [&](PetscInt p, PetscInt node, PetscBool own) -> PetscErrorCode {
    PetscReal y[3];
    PetscFunctionBegin;
    if (own) {
      PetscCall(NodePosition(dm, p, y));
      for (int d = 0; d < 3; d++) xa[3 * node - rStart + d] = y[d];
    }
    PetscFunctionReturn(0);
  }));
  PetscCall(VecRestoreArray(coords, &xa));

  std::vector<PetscInt> conn;
  for (PetscInt k = 0; k < s.cells->Size(); k++)
    for (int a = 0; a < 10; a++) conn.push_back(s.node[s.cells->point[10 * k + XdmfNode[a]]]);
  PetscInt nc = (PetscInt)conn.size() / 10;
  PetscCallMPI(MPIU_Allreduce(&nc, &s.nCells, 1, MPIU_INT, MPI_SUM, comm));
  PetscCall(ISCreateGeneral(comm, (PetscInt)conn.size(), conn.data(), PETSC_COPY_VALUES, topology));
  PetscCall(ISSetBlockSize(*topology, 10));
  PetscCall(PetscObjectSetName((PetscObject)*topology, "topology"));
  *coordinates = coords;
  PetscFunctionReturn(0);
}

PetscErrorCode XdmfOpen(const char *file, DM dm, const std::vector<OutputPart> &parts, const std::vector<PetscReal> &times, XdmfSeries &s)
{
  PetscViewer viewer = nullptr;
  std::string f      = file;

  PetscFunctionBegin;
  s.xdmf = f, s.h5 = f.substr(0, f.size() - 5) + ".h5", s.dm = dm, s.times = times;
  if (times.empty()) PetscCall(PetscViewerHDF5Open(PetscObjectComm((PetscObject)dm), s.h5.c_str(), FILE_MODE_WRITE, &viewer)); /* a restart finds the meshes in the file */
  for (const OutputPart &op : parts) {
    XdmfPart p;
    Vec      coords;
    IS       topology;
    p.name = op.name, p.group = parts.size() == 1 ? "" : "/" + op.name, p.cells = op.mesh;
    for (const auto &fl : op.fields) p.fields.push_back({fl.first, fl.second});
    for (const PointField &d : op.derived) p.fields.push_back({d.name, -1, d.nc, nullptr, d.values});
    PetscCall(NumberNodes(dm, p));
    PetscCall(MeshData(dm, p, &coords, &topology));
    if (viewer) {
      PetscCall(PetscViewerHDF5PushGroup(viewer, (p.group + "/mesh").c_str()));
      PetscCall(VecView(coords, viewer));
      PetscCall(ISView(topology, viewer));
      PetscCall(PetscViewerHDF5PopGroup(viewer));
    }
    PetscCall(ISDestroy(&topology));
    PetscCall(VecDestroy(&coords));
    s.parts.push_back(p);
  }
  PetscCall(PetscViewerDestroy(&viewer));
  if (!times.empty()) PetscCall(WriteXdmf(s));
  PetscFunctionReturn(0);
}

/* The values of field f at node point p: its own dofs, or for a P1 field at an edge midpoint
   the mean of the edge's vertices (the linear interpolant there). */
static PetscErrorCode NodeValues(DM dm, PetscSection local, const XdmfField &f, const PetscScalar *xa, PetscInt p, PetscScalar *v)
{
  PetscInt dof, off;

  PetscFunctionBegin;
  PetscCall(PetscSectionGetFieldDof(local, p, f.field, &dof));
  if (dof) {
    PetscCall(PetscSectionGetFieldOffset(local, p, f.field, &off));
    for (PetscInt c = 0; c < f.nc; c++) v[c] = xa[off + c];
    PetscFunctionReturn(0);
  }
  const PetscInt *cone;
  PetscCall(DMPlexGetCone(dm, p, &cone));
  for (PetscInt c = 0; c < f.nc; c++) v[c] = 0;
  for (int e = 0; e < 2; e++) {
    PetscCall(PetscSectionGetFieldOffset(local, cone[e], f.field, &off));
    for (PetscInt c = 0; c < f.nc; c++) v[c] += xa[off + c] / 2;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode XdmfWriteFrame(XdmfSeries &s, PetscReal t, Vec x)
{
  PetscViewer        viewer;
  PetscSection       local;
  Vec                xl;
  const PetscScalar *xa;
  char               dataset[256];

  PetscFunctionBegin;
  PetscCall(DMGetLocalSection(s.dm, &local));
  PetscCall(DMGetLocalVector(s.dm, &xl));
  PetscCall(DMGlobalToLocal(s.dm, x, INSERT_VALUES, xl));
  PetscCall(InsertEssentialValues(s.dm, t, xl));
  PetscCall(VecGetArrayRead(xl, &xa));
  PetscCall(PetscViewerHDF5Open(PetscObjectComm((PetscObject)s.dm), s.h5.c_str(), FILE_MODE_APPEND, &viewer));
  for (XdmfPart &part : s.parts) {
    PetscCall(PetscViewerHDF5PushGroup(viewer, (part.group + "/fields").c_str()));
    for (XdmfField &f : part.fields) {
      PetscInt     rStart;
      PetscScalar *va;
      PetscCall(VecGetOwnershipRange(f.values, &rStart, nullptr));
      PetscCall(VecGetArray(f.values, &va));
      PetscCall(ForEachNode(part, [&](PetscInt p, PetscInt node, PetscBool own) -> PetscErrorCode {
        if (own && f.point)
          for (PetscInt c = 0; c < f.nc; c++) va[f.nc * node - rStart + c] = (*f.point)[f.nc * p + c];
        return own && !f.point ? NodeValues(s.dm, local, f, xa, p, &va[f.nc * node - rStart]) : 0;
      }));
      PetscCall(VecRestoreArray(f.values, &va));
      PetscCall(PetscSNPrintf(dataset, sizeof(dataset), "%s_%zu", f.name.c_str(), s.times.size()));
      PetscCall(PetscObjectSetName((PetscObject)f.values, dataset));
      PetscCall(VecView(f.values, viewer));
    }
    PetscCall(PetscViewerHDF5PopGroup(viewer));
  }
  PetscCall(PetscViewerDestroy(&viewer));
  PetscCall(VecRestoreArrayRead(xl, &xa));
  PetscCall(DMRestoreLocalVector(s.dm, &xl));
  s.times.push_back(t);
  PetscCall(WriteXdmf(s));
  PetscFunctionReturn(0);
}

PetscErrorCode XdmfClose(XdmfSeries &s)
{
  PetscFunctionBegin;
  for (XdmfPart &p : s.parts)
    for (XdmfField &f : p.fields) PetscCall(VecDestroy(&f.values));
  PetscFunctionReturn(0);
}

} // namespace fsi
