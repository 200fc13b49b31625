#include "mesh/SurfaceSimplification.h"

#include "common/Error.h"
#include "common/Progress.h"
#include "mesh/CgalSurfaceMesh.h"
#include "mesh/SurfaceCheck.h"
#include "mesh/SurfaceRepair.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Bounded_distance_placement.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Bounded_normal_change_filter.h>
#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <chrono>
#include <cstdint>
#include <cmath>
#include <sstream>
#include <unordered_map>

namespace geolattice {

namespace {

using K = cgal::Kernel;
using Mesh = cgal::SurfaceMesh;
namespace SMS = CGAL::Surface_mesh_simplification;
namespace PMP = CGAL::Polygon_mesh_processing;

/// Counts the collapses for progress and abort (CGAL calls OnCollapsed after each one).
struct CollapseVisitor : SMS::Edge_collapse_visitor_base<Mesh> {
  CollapseVisitor(const ProgressReporter& report, double expected, bool& aborted)
      : report_(&report), expected_(std::max(1.0, expected)), aborted_(&aborted) {}
  void OnCollapsed(const SMS::Edge_profile<Mesh>&, Mesh::Vertex_index) {
    if (++collapses_ % 4096 == 0 && !*aborted_) {
      try {
        report_->report(std::min(1.0, static_cast<double>(collapses_) / expected_));
      } catch (const GeoLatticeError&) {
        *aborted_ = true;  // the stop predicate ends the collapse; rethrown after it
      }
    }
  }
  const ProgressReporter* report_;
  double expected_;
  bool* aborted_;
  long long collapses_ = 0;
};

/// The edge count target, or an abort.
struct StopPredicate {
  template <class Profile>
  bool operator()(const double&, const Profile&, std::size_t, std::size_t current) const {
    return *aborted || current <= edges;
  }
  std::size_t edges;
  const bool* aborted;
};

double area(const TriangleSurface& s) {
  double a = 0;
  for (const auto& t : s.triangles) {
    a += 0.5 * (s.points[t[1]] - s.points[t[0]]).cross(s.points[t[2]] - s.points[t[0]]).norm();
  }
  return a;
}

/// Remeshings after the first, each with the input vertices the last one left too far pinned,
/// when those are at most this fraction of the input's vertices (a tip or a ridge, not a
/// surface the edge length cannot follow anywhere).
constexpr int kPinRounds = 2;
constexpr double kMostPinnedFraction = 0.02;
/// Remeshing edges tried before the collapse: the target's, then shorter by factors of sqrt 2 down
/// to a third of it.
constexpr int kRemeshEdges = 4;

/// True when more than a tenth of the triangles have an angle under 10 degrees (needles and caps
/// of CAD exports), which TetGen refines around.
bool slivery(const TriangleSurface& s) {
  const double cosLimit = std::cos(10 * M_PI / 180);
  size_t bad = 0;
  for (const auto& t : s.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = (s.points[t[(k + 1) % 3]] - s.points[t[k]]).normalized();
      const Vec3 v = (s.points[t[(k + 2) % 3]] - s.points[t[k]]).normalized();
      if (u.dot(v) > cosLimit) {
        ++bad;
        break;
      }
    }
  }
  return 10 * bad > s.triangles.size();
}

/// Pins the vertices of `mesh` within `reach` of one of the points `around` (e.g. far vertices:
/// they and the input around them, as one pinned vertex alone leaves its neighbours to be cut off
/// in the next remeshing). A hash grid of reach-sized cells keeps it linear.
template <class PinMap>
void pinAround(const Mesh& mesh, const std::vector<K::Point_3>& around, double reach,
               PinMap& pinned) {
  auto cell = [reach](const K::Point_3& p, int dx, int dy, int dz) {
    const auto index = [reach](double x, int d) {
      return (static_cast<std::int64_t>(std::floor(x / reach)) + d) & 0x1FFFFF;
    };
    return (index(p.x(), dx) << 42) | (index(p.y(), dy) << 21) | index(p.z(), dz);
  };
  std::unordered_map<std::int64_t, std::vector<K::Point_3>> grid;
  for (const K::Point_3& f : around) {
    grid[cell(f, 0, 0, 0)].push_back(f);
  }
  for (Mesh::Vertex_index v : mesh.vertices()) {
    const K::Point_3& p = mesh.point(v);
    for (int n = 0; n < 27 && !pinned[v]; ++n) {
      const auto it = grid.find(cell(p, n % 3 - 1, n / 3 % 3 - 1, n / 9 - 1));
      if (it == grid.end()) {
        continue;
      }
      for (const K::Point_3& q : it->second) {
        if (CGAL::squared_distance(p, q) <= reach * reach) {
          pinned[v] = true;
          break;
        }
      }
    }
  }
}

/// Garland-Heckbert edge collapse of `mesh` to about `target` triangles (see the header).
void simplify(Mesh& mesh, double target, const SimplificationOptions& o,
              const ProgressReporter report) {
  const double tolerance = o.tolerance > 0 ? o.tolerance : 0.25 * o.targetEdgeLength;
  using GH = SMS::GarlandHeckbert_plane_policies<Mesh, K>;
  GH policies(mesh);
  SMS::Bounded_distance_placement<GH::Get_placement, K> placement(tolerance,
                                                                  policies.get_placement());
  SMS::Bounded_normal_change_filter<> filter;
  const size_t edges = static_cast<size_t>(1.5 * std::max(4.0, target));
  bool aborted = false;
  CollapseVisitor visitor(report, (static_cast<double>(mesh.number_of_edges()) - edges) / 3.0,
                          aborted);  // a collapse removes three edges
  SMS::edge_collapse(mesh, StopPredicate{edges, &aborted},
                     CGAL::parameters::get_cost(policies.get_cost())
                         .get_placement(placement)
                         .filter(filter)
                         .visitor(visitor));
  if (aborted) {
    throw GeoLatticeError("surface simplification aborted");
  }
}

}  // namespace

double meanEdgeLength(const TriangleSurface& s) {
  double sum = 0;
  for (const auto& t : s.triangles) {
    for (int k = 0; k < 3; ++k) {
      sum += (s.points[t[(k + 1) % 3]] - s.points[t[k]]).norm();
    }
  }
  return s.triangles.empty() ? 0.0 : sum / (3.0 * s.triangles.size());
}

SimplificationResult simplifySurface(const TriangleSurface& surface,
                                     const SimplificationOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!(o.targetEdgeLength > 0) || !std::isfinite(o.targetEdgeLength) || !(o.tolerance >= 0) ||
      !(o.finerThan > 0)) {
    std::ostringstream m;
    m << "surface simplification: the target edge length must be > 0 mm (got " << o.targetEdgeLength
      << ") and the tolerance >= 0 mm (got " << o.tolerance << ")";
    throw GeoLatticeError(m.str());
  }
  SimplificationResult r;
  r.inputTriangles = surface.triangles.size();
  r.inputMeanEdge = meanEdgeLength(surface);
  r.surface = surface;
  r.outputTriangles = r.inputTriangles;
  r.outputMeanEdge = r.inputMeanEdge;
  auto done = [&]() -> SimplificationResult& {
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
  };
  // An equilateral triangle of edge L has area √3/4 L²: the triangle count of the target.
  const double target =
      area(surface) / (std::sqrt(3.0) / 4.0 * o.targetEdgeLength * o.targetEdgeLength);
  const bool finer = r.inputMeanEdge < o.finerThan * o.targetEdgeLength &&
                     static_cast<double>(r.inputTriangles) >= 2.0 * target;
  const bool remesh = o.method == SimplificationMethod::IsotropicRemeshing;
  if (!finer && !(remesh && slivery(surface))) {
    return done();
  }
  const Mesh input = cgal::toSurfaceMesh(surface, "surface simplification");
  const double tolerance = o.tolerance > 0 ? o.tolerance : 0.25 * o.targetEdgeLength;
  const ProgressReporter report(o.progress, o.shouldAbort, "surface simplification");
  // The part stands on its lowest point, the base the layers grow from. A remeshed or collapsed
  // vertex near the base's rim can land under it (a 10 mm gear with a rounded rim: 164 vertices
  // up to 0.1 mm below, and the base found at the lowest one alone); no vertex may: the input has
  // nothing there, so lifting them onto the base plane only brings them closer to it.
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec3& p : surface.points) {
    lowest = std::min(lowest, p.z());
  }
  auto liftOntoTheBase = [lowest](Mesh& mesh) {
    for (auto v : mesh.vertices()) {
      const K::Point_3& p = mesh.point(v);
      if (p.z() < lowest) {
        mesh.point(v) = K::Point_3(p.x(), p.y(), lowest);
      }
    }
  };
  // The one-sided distance of the input from `mesh` (its vertices under the base lifted onto
  // it) when it is usable (closed, not self-intersecting, within the tolerance when remeshing),
  // else a reason in r.refused and, when `far` is given, where it went wrong: the input
  // vertices farther than the tolerance, or the corners of the triangles that cross each other.
  auto accept = [&](Mesh& mesh, const char* what, bool collapsed,
                    std::vector<K::Point_3>* far = nullptr) {
    mesh.collect_garbage();
    liftOntoTheBase(mesh);
    if (PMP::does_self_intersect(mesh)) {
      r.refused = std::string("the ") + what + " surface self-intersects";
      if (far) {
        std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> crossing;
        PMP::self_intersections(faces(mesh), mesh, std::back_inserter(crossing));
        for (const auto& [a, b] : crossing) {
          for (const Mesh::Face_index f : {a, b}) {
            for (const Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
              far->push_back(mesh.point(v));
            }
          }
        }
      }
      return false;
    }
    using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
    CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> tree(faces(mesh).first, faces(mesh).second,
                                                          mesh);
    tree.accelerate_distance_queries();
    double h2 = 0;
    for (auto v : input.vertices()) {
      const double d2 = CGAL::to_double(tree.squared_distance(input.point(v)));
      h2 = std::max(h2, d2);
      if (far && d2 > tolerance * tolerance) {
        far->push_back(input.point(v));
      }
    }
    if (remesh && std::sqrt(h2) > tolerance) {
      std::ostringstream m;
      m << "the " << what << " surface is " << std::sqrt(h2) << " mm off the input (more than "
        << tolerance << " mm)";
      r.refused = m.str();
      return false;
    }
    TriangleSurface result = cgal::toTriangleSurface(mesh);
    // A remeshing or a collapse can leave slivers of area ~0 (a gear turned upside down on its
    // pedestal: 3 of 50k triangles), which the mesh stage would refuse, naming triangles the
    // user never made: mended here, and where that fails the result is refused.
    removeDegenerateTriangles(result);
    if (const SurfaceCheckReport check = checkSurface(result);
        check.degenerateTriangles > 0 || check.boundaryEdges > 0 || check.nonManifoldEdges > 0) {
      r.refused = std::string("the ") + what + " surface " +
                  (check.degenerateTriangles > 0
                       ? "has " + std::to_string(check.degenerateTriangles) + " zero-area triangles"
                       : std::string("is not closed and manifold"));
      return false;
    }
    // The collapse keeps the distance by sliding vertices along flat directions: on a cone or
    // a cylinder it leaves needles from end to end, which TetGen refines far below the target
    // edge (a generated 100 mm spire at 2 mm: 1,702 triangles, two thirds of them needles, gave
    // 242k tets in 4.2 s; its input as it is, 117k in 1.7 s). When remeshing was asked for,
    // such a result is refused unless the input was no better.
    if (collapsed && remesh && slivery(result) && !slivery(surface)) {
      r.refused = std::string("the ") + what + " surface is full of slivers";
      return false;
    }
    r.surface = std::move(result);
    r.simplified = true;
    r.outputTriangles = r.surface.triangles.size();
    r.outputMeanEdge = meanEdgeLength(r.surface);
    r.hausdorff = std::sqrt(h2);
    return true;
  };
  if (remesh) {
    // Input vertices that a remeshing left farther than the tolerance (a sharp tip or a thin
    // ridge it cut off), and those around triangles it made cross (the filled bunny scan turned
    // by the orientation search: every edge refused so, 331k tets from the collapse's surface, 82k
    // with these pins), stay where they are in the next one (at most kPinRounds more): a
    // generated 100 mm spire with a 1 mm tip, remeshed for 2 mm, was 0.6 mm off at its tip, and
    // the collapse that ran instead gave needles. Where that is not enough (rounded features
    // narrower than the edge all over: a gear's teeth, a cone's rounded tip), the surface is
    // remeshed for a shorter edge, within the same tolerance: its well-shaped triangles mesh
    // near the asked count, where the collapse's needles made TetGen refine (a cone on its tip at
    // 15k tets: 220k after the collapse, 19k remeshed for 1/sqrt 2 of the edge).
    std::string firstRefusal;
    for (int shorter = 0; shorter < kRemeshEdges; ++shorter) {
      const double edge = o.remeshEdgeFactor * o.targetEdgeLength * std::pow(M_SQRT1_2, shorter);
      Mesh base = input;
      auto pinned = base.add_property_map<Mesh::Vertex_index, bool>("v:pinned", false).first;
      for (int round = 0;; ++round) {
        Mesh mesh = base;
        auto sharp = mesh.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
        PMP::detect_sharp_edges(mesh, o.sharpAngleDeg, sharp);
        PMP::isotropic_remeshing(
            faces(mesh), edge, mesh,
            CGAL::parameters::number_of_iterations(3)
                .edge_is_constrained_map(sharp)
                .vertex_is_constrained_map(
                    mesh.property_map<Mesh::Vertex_index, bool>("v:pinned").first));
        std::vector<K::Point_3> far;  // where it went wrong: the input is kept around there
        if (accept(mesh, "remeshed", false, &far)) {
          r.refused = firstRefusal;  // the target edge's, if it was refused
          r.remeshEdgeLength = edge;
          report.report(1.0);
          return done();
        }
        if (far.empty() || round == kPinRounds ||
            static_cast<double>(far.size()) > kMostPinnedFraction * input.number_of_vertices()) {
          break;  // still too far or crossing, or in too many places
        }
        pinAround(base, far, edge, pinned);
      }
      if (firstRefusal.empty()) {
        firstRefusal = r.refused;
      }
      report.report((finer ? 0.5 : 1.0) * (shorter + 1) / kRemeshEdges);
    }
    r.refused = firstRefusal;
    if (!finer) {
      return done();  // a coarse input that remeshing would change too much stays as it is
    }
  }
  // The edge collapse (also when the remeshed surface was refused).
  const std::string remeshRefused = r.refused;
  Mesh mesh = input;
  simplify(mesh, target, o, remesh ? report.part(0.5, 1.0) : report);
  if (!accept(mesh, "simplified", true) && remesh) {
    r.refused = remeshRefused + "; " + r.refused;
  }
  return done();
}

}  // namespace geolattice
