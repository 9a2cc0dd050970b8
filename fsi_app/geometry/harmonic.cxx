#include "harmonic.h"
#include "discretization/fields.h"
#include "discretization/nodes.h"

namespace fsi {

void HarmonicQuadraticSolution(const PetscReal x[3], const void *ctx, PetscReal u[3], PetscReal G[9])
{
  const PetscReal a = *(const PetscReal *)ctx;
  u[0] = a * (x[0] * x[0] - x[1] * x[1]), u[1] = -2 * a * x[0] * x[1], u[2] = 0;
  for (int k = 0; k < 9; k++) G[k] = 0;
  G[0] = 2 * a * x[0], G[1] = -2 * a * x[1], G[3] = -2 * a * x[1], G[4] = -2 * a * x[0];
}

PetscErrorCode HarmonicQuadratic(PetscInt, PetscReal, const PetscReal x[], PetscInt nc, PetscScalar *u, void *ctx)
{
  PetscReal v[3], G[9];
  HarmonicQuadraticSolution(x, ctx, v, G);
  for (PetscInt c = 0; c < nc; c++) u[c] = v[c];
  return 0;
}

/* R(d)(v) = int grad d : grad v, component by component (the residual of a linear problem is
   its operator applied: Newton converges in one step). */
static PetscErrorCode GeometryResidual(DM dm, Vec Xl, Vec Fl, void *ctx)
{
  const GeometryBlock &gb = *(GeometryBlock *)ctx;
  const PetscScalar   *x;
  PetscScalar         *f;

  PetscFunctionBegin;
  PetscCall(InsertEssentialValues(dm, 0.0, Xl));
  PetscCall(VecZeroEntries(Fl));
  PetscCall(VecGetArrayRead(Xl, &x));
  PetscCall(VecGetArray(Fl, &f));
  for (PetscInt k = 0; k < gb.cells.Size(); k++) {
    const CellGeometry &g = gb.cells.geom[k];
    PetscReal           de[30], re[30] = {0};
    Gather(gb.cells, k, x, de);
    for (PetscInt q = 0; q < gb.rule.nq; q++) {
      PetscReal dN[10][3], G[3][3] = {{0}};
      P2Gradients(g, &gb.rule.lambda[4 * q], dN);
      for (int a = 0; a < 10; a++)
        for (int i = 0; i < 3; i++)
          for (int j = 0; j < 3; j++) G[i][j] += de[3 * a + i] * dN[a][j];
      const PetscReal w = gb.rule.w[q] * g.detE;
      for (int a = 0; a < 10; a++)
        for (int i = 0; i < 3; i++) re[3 * a + i] += w * (G[i][0] * dN[a][0] + G[i][1] * dN[a][1] + G[i][2] * dN[a][2]);
    }
    Scatter(gb.cells, k, re, f);
  }
  PetscCall(VecRestoreArray(Fl, &f));
  PetscCall(VecRestoreArrayRead(Xl, &x));
  PetscFunctionReturn(0);
}

static PetscErrorCode GeometryJacobian(DM dm, Vec, Mat J, Mat P, void *ctx)
{
  const GeometryBlock &gb = *(GeometryBlock *)ctx;

  PetscFunctionBegin;
  PetscCall(MatZeroEntries(P));
  for (PetscInt k = 0; k < gb.cells.Size(); k++) {
    const CellGeometry &g = gb.cells.geom[k];
    PetscReal           K[900] = {0};
    for (PetscInt q = 0; q < gb.rule.nq; q++) {
      PetscReal dN[10][3];
      P2Gradients(g, &gb.rule.lambda[4 * q], dN);
      const PetscReal w = gb.rule.w[q] * g.detE;
      for (int a = 0; a < 10; a++)
        for (int b = 0; b < 10; b++) {
          const PetscReal v = w * (dN[a][0] * dN[b][0] + dN[a][1] * dN[b][1] + dN[a][2] * dN[b][2]);
          for (int i = 0; i < 3; i++) K[(3 * a + i) * 30 + 3 * b + i] += v;
        }
    }
    PetscCall(MatSetValues(P, 30, &gb.cells.global[30 * k], 30, &gb.cells.global[30 * k], K, ADD_VALUES));
  }
  PetscCall(AssembleOperators(J, P));
  PetscFunctionReturn(0);
}

PetscErrorCode SetUpGeometry(const Scene &sc, DM dm, GeometryBlock &gb, PetscInt *field)
{
  DMLabel region, interface;

  PetscFunctionBegin;
  PetscCall(AddLagrangeField(dm, "geometry", sc.fluidRegion, 3, 2, field));
  PetscCall(DMCreateDS(dm));
  PetscCall(DMGetLabel(dm, sc.interface, &interface));
  { /* d_f = the interface displacement on the interface (here: the verification field) */
    std::vector<PetscInt> ids;
    PetscCall(LabelValues(interface, ids));
    PetscCall(DMAddBoundary(dm, DM_BC_ESSENTIAL, "interface displacement", interface, (PetscInt)ids.size(), ids.data(), *field, 0, nullptr, (void (*)(void))HarmonicQuadratic, nullptr, (void *)&sc.geometryAmplitude, nullptr));
  }
  PetscCall(AddZeroDirichlet(dm, sc.slip, *field, "-geometry_slip"));
  PetscCall(DMGetLabel(dm, (std::string("region_") + sc.fluidRegion).c_str(), &region));
  PetscCall(FieldCellsCreate(dm, region, *field, gb.cells));
  PetscCall(CreateP2Rule(2, gb.rule));
  PetscCall(DMSNESSetFunctionLocal(dm, GeometryResidual, &gb));
  PetscCall(DMSNESSetJacobianLocal(dm, GeometryJacobian, &gb));
  PetscFunctionReturn(0);
}

} // namespace fsi
