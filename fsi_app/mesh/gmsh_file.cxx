// SPDX-License-Identifier: BSD-2-Clause
#include "gmsh_file.h"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sys/stat.h>
#include <map>
#include <set>
#include <tuple>
#include <vector>

namespace fsi {

/* Nodes of the element types fsi_app reads: points, lines, triangles, tetrahedra, first order
   and second order (gmsh -order 2: 3-node lines, 6-node triangles, 10-node tetrahedra). */
static const std::map<long long, size_t> ElementNodes = {{15, 1}, {1, 2}, {2, 3}, {4, 4}, {8, 3}, {9, 6}, {11, 10}};

static bool Integer(const std::string &t, long long &x)
{
  char *end;
  x = std::strtoll(t.c_str(), &end, 10);
  return end != t.c_str() && !*end;
}

static bool Real(const std::string &t, double &x)
{
  char *end;
  x = std::strtod(t.c_str(), &end);
  return end != t.c_str() && !*end;
}

/* The file line by line, split into tokens; errors name the file and the line. */
struct GmshScan {
  std::string                               file, section, line;
  std::vector<std::string>                  tok;
  std::ifstream                             in;
  long                                      number  = 0;
  bool                                      partial = false; /* the last line read ends without a newline */
  std::set<std::pair<long long, long long>> entities;        /* (dimension, tag) of $Entities */
  std::map<std::pair<long long, long long>, std::vector<long long>> physical; /* (dimension, entity tag) -> its physical tags */
  std::map<std::pair<long long, long long>, long long>              count;    /* (dimension, entity tag) -> its elements */
  std::vector<GmshGroup>                                            names;    /* $PhysicalNames, elements 0 until counted */
  std::vector<long long>                                            nameTags; /* the physical tag of each name */
  bool                                      hasEntities = false;
  long long                                 bytes = 0; /* the file's size */
  long long                                 nodeMin = 1, tetrahedra = 0, curved = 0; /* first- and second-order tetrahedra */
  std::vector<bool>                         node; /* node[tag - nodeMin]: defined in $Nodes */
  std::vector<double>                       xyz;  /* its coordinates, 3 per tag */
  std::vector<double>                      *bent = nullptr; /* the curved edges of second-order tetrahedra (CurvedEdge: 9 each), if asked */

  explicit GmshScan(const std::string &f) : file(f), in(f) { }

  bool Next()
  {
    if (!std::getline(in, line)) return false;
    number++, partial = in.eof();
    if (!line.empty() && line.back() == '\r') line.pop_back();
    tok.clear();
    for (size_t b = line.find_first_not_of(" \t"); b != std::string::npos;) {
      const size_t e = line.find_first_of(" \t", b);
      tok.push_back(line.substr(b, e == std::string::npos ? e : e - b));
      b = e == std::string::npos ? e : line.find_first_not_of(" \t", e);
    }
    return true;
  }
  std::string Cut() const { return "mesh file '" + file + "' ends inside " + section + " (line " + std::to_string(number) + "): the file is truncated"; }
  std::string At(const std::string &what) const { return partial ? Cut() : "mesh file '" + file + "' line " + std::to_string(number) + ": " + what; }
  /* the line's first n tokens as integers; false if there are fewer or one is not an integer */
  bool Integers(size_t n, std::vector<long long> &v) const
  {
    v.resize(n);
    for (size_t i = 0; i < n; i++)
      if (i >= tok.size() || !Integer(tok[i], v[i])) return false;
    return true;
  }
  std::string End(const std::string &marker)
  {
    if (!Next()) return Cut();
    return line == marker ? "" : At("expected " + marker + ", found '" + line + "': the section holds more than its header announces");
  }
  std::string Entity(long long dim, long long tag) const
  {
    if (!hasEntities || entities.count({dim, tag})) return "";
    return At("the block names the entity " + std::to_string(tag) + " of dimension " + std::to_string(dim) + ", which $Entities does not define");
  }
  bool Defined(long long tag) const { return tag >= nodeMin && tag - nodeMin < (long long)node.size() && node[tag - nodeMin]; }
  /* |6 volume| of the tetrahedron with these node tags at most 1e-12 of its longest edge cubed */
  bool Flat(const long long *t) const
  {
    const double *p[4];
    double        e[3][3], longest = 0;
    for (int k = 0; k < 4; k++) p[k] = &xyz[3 * (t[k] - nodeMin)];
    for (int k = 0; k < 3; k++)
      for (int c = 0; c < 3; c++) e[k][c] = p[k + 1][c] - p[0][c];
    for (int a = 0; a < 4; a++)
      for (int b = a + 1; b < 4; b++) longest = std::max(longest, std::hypot(p[a][0] - p[b][0], p[a][1] - p[b][1], p[a][2] - p[b][2]));
    const double vol6 = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    return std::fabs(vol6) <= 1e-12 * longest * longest * longest;
  }

  /* The edges of a second-order tetrahedron (node tags t[0..9]) whose node is off their midpoint:
     each edge node belongs to the vertex pair whose midpoint is nearest (the file's node order
     is not assumed), and gmsh places the nodes of straight edges at their midpoints. */
  void Bent(const long long *t) const
  {
    for (int k = 4; k < 10; k++) {
      const double *x = &xyz[3 * (t[k] - nodeMin)], *a = nullptr, *b = nullptr;
      double        best = INFINITY;
      for (int i = 0; i < 4; i++)
        for (int j = i + 1; j < 4; j++) {
          const double *p = &xyz[3 * (t[i] - nodeMin)], *q = &xyz[3 * (t[j] - nodeMin)];
          const double  d = std::hypot(x[0] - (p[0] + q[0]) / 2, x[1] - (p[1] + q[1]) / 2, x[2] - (p[2] + q[2]) / 2);
          if (d < best) best = d, a = p, b = q;
        }
      if (best <= 1e-12 * std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2])) continue;
      if (std::lexicographical_compare(b, b + 3, a, a + 3)) std::swap(a, b);
      bent->insert(bent->end(), a, a + 3), bent->insert(bent->end(), b, b + 3), bent->insert(bent->end(), x, x + 3);
    }
  }

  std::string Format();
  std::string PhysicalNames();
  std::string Entities();
  std::string Nodes();
  std::string Elements();
  std::string Skip();
};

std::string GmshScan::Format()
{
  if (!Next()) return Cut();
  if (tok.size() < 2 || tok[0] != "4.1" || tok[1] != "0") return "mesh file '" + file + "' is gmsh format " + (tok.empty() ? "?" : tok[0]) + (tok.size() > 1 && tok[1] == "1" ? " binary" : "") + ": fsi_app reads format 4.1 ASCII (gmsh -format msh41; scripts/make-meshes writes it)";
  return End("$EndMeshFormat");
}

std::string GmshScan::PhysicalNames()
{
  std::vector<long long> n, h;

  if (!Next()) return Cut();
  if (!Integers(1, n) || n[0] < 0) return At("the $PhysicalNames header must be: numPhysicalNames");
  for (long long i = 0; i < n[0]; i++) {
    if (!Next()) return Cut();
    const size_t open = line.find('"'), close = line.rfind('"');
    if (!Integers(2, h) || h[0] < 0 || h[0] > 3 || open == std::string::npos || close == open) return At("a physical name's line must be: dimension tag \"name\"");
    names.push_back({line.substr(open + 1, close - open - 1), (int)h[0], 0}), nameTags.push_back(h[1]);
  }
  return End("$EndPhysicalNames");
}

std::string GmshScan::Entities()
{
  std::vector<long long> count, tag;

  if (!Next()) return Cut();
  if (!Integers(4, count)) return At("the $Entities header must be: numPoints numCurves numSurfaces numVolumes");
  for (long long dim = 0; dim < 4; dim++)
    for (long long i = 0; i < count[dim]; i++) {
      if (!Next()) return Cut();
      /* a point: tag x y z, a curve, surface or volume: tag and its bounding box; then the
         number of physical tags and the tags */
      const size_t at = dim ? 7 : 4;
      if (!Integers(1, tag)) return At("an entity line starts with its tag");
      std::vector<long long> &p = physical[{dim, tag[0]}];
      long long               n;
      if (tok.size() <= at || !Integer(tok[at], n) || n < 0 || tok.size() <= at + n) return At("the entity's number of physical tags and the tags must follow its coordinates");
      for (long long k = 0; k < n; k++)
        if (!Integer(tok[at + 1 + k], p.emplace_back())) return At("physical tag '" + tok[at + 1 + k] + "' is not an integer");
      entities.insert({dim, tag[0]});
    }
  hasEntities = true;
  return End("$EndEntities");
}

std::string GmshScan::Nodes()
{
  std::vector<long long> h, t;
  long long              seen = 0;

  if (!Next()) return Cut();
  if (!Integers(4, h) || h[0] < 0 || h[1] < 0) return At("the $Nodes header must be: numEntityBlocks numNodes minNodeTag maxNodeTag");
  if (h[1] && (h[2] < 1 || h[3] < h[2] || h[3] - h[2] >= (1LL << 31))) return At("node tags " + std::to_string(h[2]) + " to " + std::to_string(h[3]) + ": tags are positive and span less than 2^31");
  const long long blocks = h[0], total = h[1];
  /* bound what the header makes this allocate: a node takes at least 8 bytes of the file */
  if (total > bytes / 8 + 1) return At("the $Nodes header announces " + std::to_string(total) + " nodes, more than a file of " + std::to_string(bytes) + " bytes can hold");
  if (total && h[3] - h[2] + 1 > 16 * total + 1000) return At("node tags " + std::to_string(h[2]) + " to " + std::to_string(h[3]) + " for " + std::to_string(total) + " nodes: the tags are too sparse to be read; renumber the nodes (gmsh -renumber)");
  nodeMin = h[2], node.assign(total ? h[3] - h[2] + 1 : 0, false), xyz.assign(3 * node.size(), 0.0);
  for (long long b = 0; b < blocks; b++) {
    if (!Next()) return Cut();
    if (!Integers(4, h) || h[3] < 0) return At("a node block starts with: entityDim entityTag parametric numNodesInBlock");
    if (const std::string e = Entity(h[0], h[1]); !e.empty()) return e;
    const long long n = h[3], values = 3 + (h[2] ? h[0] : 0); /* x y z, and u v w up to the entity's dimension if parametric */
    std::vector<long long> tags(n);
    for (long long i = 0; i < n; i++) {
      if (!Next()) return Cut();
      if (!Integers(1, t) || tok.size() != 1) return At("expected a node tag, found '" + line + "'");
      if (t[0] < nodeMin || t[0] - nodeMin >= (long long)node.size()) return At("node tag " + tok[0] + " lies outside the range of the $Nodes header");
      if (node[t[0] - nodeMin]) return At("node " + tok[0] + " is defined twice");
      node[t[0] - nodeMin] = true, tags[i] = t[0];
    }
    for (long long i = 0; i < n; i++) {
      double x;
      if (!Next()) return Cut();
      if ((long long)tok.size() != values) return At("node " + std::to_string(tags[i]) + ": expected " + std::to_string(values) + " coordinates, found " + std::to_string(tok.size()));
      for (size_t c = 0; c < tok.size(); c++) {
        if (!Real(tok[c], x) || !std::isfinite(x)) return At("node " + std::to_string(tags[i]) + " has the coordinate '" + tok[c] + "': coordinates must be finite numbers");
        /* a cell's volume is a product of three coordinate differences: beyond 1e100 it overflows */
        if (std::fabs(x) > 1e100) return At("node " + std::to_string(tags[i]) + " has the coordinate '" + tok[c] + "': coordinates must be at most 1e100 in size (volumes of larger ones overflow); rescale the mesh's units");
        if (c < 3) xyz[3 * (tags[i] - nodeMin) + c] = x;
      }
    }
    if ((seen += n) > total) return At("the node blocks hold more nodes than the $Nodes header announces (" + std::to_string(total) + ")");
  }
  if (seen != total) return At("the $Nodes header announces " + std::to_string(total) + " nodes, its blocks hold " + std::to_string(seen));
  /* two nodes at one point: the cells on either side are not connected there (a crack) */
  std::vector<long long> order;
  for (long long k = 0; k < (long long)node.size(); k++)
    if (node[k]) order.push_back(k);
  auto point = [&](long long k) { return std::make_tuple(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]); };
  std::sort(order.begin(), order.end(), [&](long long a, long long b) { return point(a) < point(b); });
  for (size_t k = 1; k < order.size(); k++)
    if (point(order[k]) == point(order[k - 1])) {
      char where[96];
      std::snprintf(where, sizeof(where), "(%.17g, %.17g, %.17g)", xyz[3 * order[k]], xyz[3 * order[k] + 1], xyz[3 * order[k] + 2]);
      return "mesh file '" + file + "': nodes " + std::to_string(std::min(order[k], order[k - 1]) + nodeMin) + " and " + std::to_string(std::max(order[k], order[k - 1]) + nodeMin) + " are both at " + where +
             ": the cells on either side would not be connected there (a crack); merge them (gmsh: Coherence Mesh)";
    }
  return End("$EndNodes");
}

std::string GmshScan::Elements()
{
  std::vector<long long> h, e;

  if (!Next()) return Cut();
  if (!Integers(4, h) || h[0] < 0 || h[1] < 0) return At("the $Elements header must be: numEntityBlocks numElements minElementTag maxElementTag");
  const long long blocks = h[0], total = h[1];
  long long       seen = 0;
  for (long long b = 0; b < blocks; b++) {
    if (!Next()) return Cut();
    if (!Integers(4, h) || h[3] < 0) return At("an element block starts with: entityDim entityTag elementType numElementsInBlock");
    if (const std::string s = Entity(h[0], h[1]); !s.empty()) return s;
    const auto type = ElementNodes.find(h[2]);
    if (type == ElementNodes.end()) return At("element type " + std::to_string(h[2]) + ": fsi_app reads tetrahedra of first order (type 4, with triangles 2 and lines 1) or second order (11, with 9 and 8), and points (15); mesh with gmsh -order 1 or -order 2");
    count[{h[0], h[1]}] += h[3];
    if (h[2] == 4) tetrahedra += h[3];
    if (h[2] == 11) curved += h[3];
    if (tetrahedra && curved) return At("the file has tetrahedra of first order (type 4) and of second order (11): mesh it with one -order");
    for (long long i = 0, n = h[3]; i < n; i++) {
      if (!Next()) return Cut();
      if (!Integers(1 + type->second, e) || tok.size() != 1 + type->second) return At("expected an element tag and its " + std::to_string(type->second) + " nodes, found '" + line + "'");
      for (size_t k = 1; k <= type->second; k++)
        if (!Defined(e[k])) return At("element " + tok[0] + " names node " + tok[k] + ", which $Nodes does not define");
      if (h[2] == 11 && bent) Bent(&e[1]);
      if ((h[2] == 4 || h[2] == 11) && Flat(&e[1])) return At("tetrahedron " + tok[0] + " (nodes " + tok[1] + " " + tok[2] + " " + tok[3] + " " + tok[4] + ") has no volume: its nodes lie in a plane");
    }
    if ((seen += h[3]) > total) return At("the element blocks hold more elements than the $Elements header announces (" + std::to_string(total) + ")");
  }
  if (seen != total) return At("the $Elements header announces " + std::to_string(total) + " elements, its blocks hold " + std::to_string(seen));
  return End("$EndElements");
}

/* A section fsi_app does not check ($Comments, $Periodic, ...): up to its end marker. */
std::string GmshScan::Skip()
{
  const std::string marker = "$End" + section.substr(1);
  while (Next())
    if (line == marker) return "";
  return Cut();
}

std::string GmshFileProblem(const std::string &file, int *order, std::vector<double> *bent, std::vector<GmshGroup> *groups)
{
  struct stat st;
  /* a FIFO would block the open, a device (/dev/zero) feed one endless line */
  if (stat(file.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) return "mesh file '" + file + "' is not a regular file (a " + (S_ISDIR(st.st_mode) ? "directory" : S_ISFIFO(st.st_mode) ? "FIFO" : "device or socket") + "): give a gmsh .msh file (option -mesh)";
  GmshScan    s(file);
  s.bent = bent, s.bytes = st.st_size;
  std::string why;
  bool        nodes = false, elements = false;

  if (!s.in) return "mesh file '" + file + "' does not exist or cannot be read (option -mesh); scripts/make-meshes makes the tube, cube and cylinder meshes";
  if (!s.Next() || s.line.rfind("$MeshFormat", 0) != 0) return "mesh file '" + file + "' is not a gmsh .msh file: it must start with $MeshFormat";
  s.section = "$MeshFormat";
  if (!(why = s.Format()).empty()) return why;
  while (why.empty() && s.Next()) {
    if (s.line.empty()) continue;
    if (s.line[0] != '$') return s.At("expected a section ($Name), found '" + s.line + "'");
    s.section = s.line;
    if (s.line == "$PhysicalNames") why = s.PhysicalNames();
    else if (s.line == "$Entities") why = s.Entities();
    else if (s.line == "$Nodes") why = s.Nodes(), nodes = true;
    else if (s.line == "$Elements") why = nodes ? s.Elements() : s.At("$Elements before $Nodes"), elements = true;
    else why = s.Skip();
  }
  if (!why.empty()) return why;
  if (!nodes || !elements) return "mesh file '" + file + "' has no " + (nodes ? "$Elements" : "$Nodes") + " section: the file is truncated or not a mesh";
  if (!s.tetrahedra && !s.curved) return "mesh file '" + file + "' has no tetrahedra (element type 4 or 11): fsi_app solves on 3-D tetrahedral meshes";
  if (order) *order = s.curved ? 2 : 1;
  if (groups) { /* a group's elements: those of the entities of its dimension that carry its tag */
    for (size_t g = 0; g < s.names.size(); g++)
      for (const auto &[entity, tags] : s.physical)
        if (entity.first == s.names[g].dim && std::count(tags.begin(), tags.end(), s.nameTags[g])) s.names[g].elements += s.count[entity];
    *groups = s.names;
  }
  return "";
}

} // namespace fsi
