#include "elasticity.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "cut_cell.h"
#include "elasticity_impl.h"
#include "error.h"

namespace pumpd::global
{
  using namespace dealii;

  double ElasticMaterial::mu() const { return youngs_modulus / (2. * (1. + poisson_ratio)); }

  double ElasticMaterial::lambda() const
  {
    const double l = youngs_modulus * poisson_ratio / ((1. + poisson_ratio) * (1. - 2. * poisson_ratio));
    return plane_strain ? l : 2. * l * mu() / (l + 2. * mu());
  }

  double ElasticMaterial::effective_modulus() const
  {
    return plane_strain ? youngs_modulus / (1. - poisson_ratio * poisson_ratio) : youngs_modulus;
  }

  double ElasticMaterial::kolosov() const
  {
    return plane_strain ? 3. - 4. * poisson_ratio : (3. - poisson_ratio) / (1. + poisson_ratio);
  }

  EnrichedElasticity::EnrichedElasticity(Triangulation<2, 2> &tria, const ElasticMaterial &material,
                                         const EnrichmentSettings &settings)
    : impl(std::make_unique<Impl>(tria, material, settings))
  {
    require_positive("Young's modulus", material.youngs_modulus);
    require_range("Poisson's ratio", material.poisson_ratio, 0., 0.5 - 1e-12,
                  "must be in [0, 0.5) (0.5 is incompressible: locking)");
    // Q1 elements in plane strain lock as lambda / mu = 2 nu / (1 - 2 nu) grows (50 at nu = 0.49,
    // 5000 at 0.4999): the computed field is too stiff, K_I too small, with no error raised.
    if (material.plane_strain && material.poisson_ratio > 0.49)
      {
        std::ostringstream w;
        w << "warning: Poisson's ratio = " << material.poisson_ratio
          << " in plane strain: the bilinear (Q1) elements suffer volumetric locking above 0.49 "
             "(lambda / mu = "
          << 2. * material.poisson_ratio / (1. - 2. * material.poisson_ratio)
          << "); displacements and stress intensity factors will be too small. Remedy: use nu <= 0.49, or plane "
             "stress, or a much finer mesh";
        warning_list.push_back(w.str());
      }
  }

  EnrichedElasticity::~EnrichedElasticity() = default;

  void EnrichedElasticity::set_crack(std::optional<Crack> crack)
  {
    set_cracks(crack ? std::vector<Crack>{std::move(*crack)} : std::vector<Crack>{});
  }

  const std::optional<Crack> &EnrichedElasticity::crack() const { return impl->single_crack; }

  void EnrichedElasticity::set_cracks(std::vector<Crack> cracks)
  {
    impl->single_crack.reset();
    if (cracks.size() == 1)
      impl->single_crack = cracks.front();
    impl->cracks = std::move(cracks);
  }

  const std::vector<Crack> &EnrichedElasticity::cracks() const { return impl->cracks; }

  void EnrichedElasticity::add_dirichlet(unsigned int id, SidedField value, bool fix_x, bool fix_y)
  {
    impl->dirichlet.push_back({id, std::move(value), fix_x, fix_y});
  }

  void EnrichedElasticity::add_dirichlet_vertex(geometry::Point at, geometry::Point value, bool fix_x, bool fix_y)
  {
    impl->vertex_dirichlet.push_back({at, value, fix_x, fix_y});
  }

  void EnrichedElasticity::add_dirichlet_region(unsigned int material_id,
                                                std::function<geometry::Point(geometry::Point)> value, bool fix_x,
                                                bool fix_y)
  {
    impl->region_dirichlet.push_back({material_id, std::move(value), fix_x, fix_y});
  }

  void EnrichedElasticity::add_traction(unsigned int id, std::function<geometry::Point(geometry::Point)> t)
  {
    impl->tractions.push_back({id, [t = std::move(t)](geometry::Point x, geometry::Point) { return t(x); }});
  }

  void EnrichedElasticity::add_traction(unsigned int id,
                                        std::function<geometry::Point(geometry::Point, geometry::Point)> t)
  {
    impl->tractions.push_back({id, std::move(t)});
  }

  void EnrichedElasticity::add_point_load(geometry::Point at, geometry::Point force)
  {
    impl->point_loads.push_back({at, force});
  }

  void EnrichedElasticity::set_body_force(std::function<geometry::Point(geometry::Point)> f)
  {
    impl->body_force = std::move(f);
  }

  void EnrichedElasticity::setup() { impl->setup(); }
  void EnrichedElasticity::assemble() { impl->assemble(); }
  SolveReport EnrichedElasticity::solve(const SolverSettings &solver) { return impl->solve(solver); }

  void EnrichedElasticity::scale_solution(double factor) { impl->solution *= factor; }

  unsigned int EnrichedElasticity::n_dofs() const { return impl->n_dofs; }
  unsigned int EnrichedElasticity::n_enriched_dofs() const { return impl->n_dofs - 2 * impl->nodes.size(); }
  unsigned int EnrichedElasticity::n_heaviside_nodes() const { return impl->count(NodeKind::heaviside); }
  unsigned int EnrichedElasticity::n_tip_nodes() const { return impl->count(NodeKind::tip); }

  geometry::Point EnrichedElasticity::displacement(geometry::Point x, int side) const
  {
    return impl->displacement(x, side);
  }

  geometry::Point EnrichedElasticity::mean_displacement(unsigned int boundary_id) const
  {
    const auto nodes = impl->boundary_nodes(boundary_id);
    if (nodes.empty())
      throw InvalidParameter("Displacement boundary id", std::to_string(boundary_id), "no boundary face has it");
    geometry::Point sum;
    for (const auto p : nodes)
      sum = sum + geometry::Point{impl->solution(2 * p), impl->solution(2 * p + 1)};
    return (1. / nodes.size()) * sum;
  }

  geometry::Point EnrichedElasticity::reaction(unsigned int boundary_id) const
  {
    const auto nodes = impl->boundary_nodes(boundary_id);
    if (nodes.empty())
      throw InvalidParameter("Reaction boundary id", std::to_string(boundary_id), "no boundary face has it");
    return impl->reaction(nodes);
  }

  geometry::Point EnrichedElasticity::reaction_at(geometry::Point vertex) const
  {
    const double tol = 1e-6 * GridTools::minimal_cell_diameter(impl->tria);
    for (unsigned int p = 0; p < impl->nodes.size(); ++p)
      if (geometry::norm(to_point(impl->support[impl->nodes[p]]) - vertex) <= tol)
        return impl->reaction({p});
    throw InvalidParameter("Reaction vertex", "(" + std::to_string(vertex.x) + ", " + std::to_string(vertex.y) + ")",
                           "must be a vertex of the mesh");
  }

  void EnrichedElasticity::prepare_point_evaluation(const std::vector<geometry::Point> &points,
                                                    const std::vector<int>             &side)
  {
    impl->prepare_point_evaluation(points, side);
  }

  std::vector<geometry::Point> EnrichedElasticity::evaluate_points() const { return impl->evaluate_points(); }

  ErrorNorms EnrichedElasticity::errors(const SidedField &exact,
                                        const std::function<std::array<double, 4>(geometry::Point, int)> &grad) const
  {
    return impl->errors(exact, grad);
  }

  std::vector<StressIntensity> EnrichedElasticity::stress_intensity_factors(double radius_factor) const
  {
    return impl->stress_intensity_factors(radius_factor);
  }

  double EnrichedElasticity::strain_energy() const { return impl->strain_energy(); }

  void EnrichedElasticity::write_vtu(const std::string &filename) const { impl->write_vtu(filename); }
} // namespace pumpd::global
