#include "global_problem.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <stdexcept>

#include "crack_network.h"
#include "elasticity.h"
#include "mesh.h"
#include "error.h"
#include "global_conditions.h"

namespace pumpd::coupling
{
  namespace Patterns = dealii::Patterns;

  void GlobalSettings::add_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Global");
    prm.add_parameter("Tip enrichment radius", tip_radius,
                      "Nodes within this distance of a tip carry the branch functions [m]; at least the diameter of "
                      "the cell at the tip. The interaction integral lies within it.",
                      Patterns::Double(1e-300));
    prm.add_parameter("Refinement levels near the tip", refinement_levels,
                      "Cells near a tip are refined this often (each level halves them); the refinement follows the "
                      "tip (Refinement trail).",
                      Patterns::Integer(0, 6));
    prm.add_parameter("Refinement radius", refinement_radius, "Refine the cells within this distance of a tip [m].",
                      Patterns::Double(1e-300));
    prm.add_parameter("Refinement trail", refinement_trail,
                      "The cells refined at earlier positions of a tip stay refined within this distance of a "
                      "current tip [m]; farther behind, the crack runs through the mesh's own cells (the Heaviside "
                      "enrichment carries its opening there). A length beyond the body keeps the whole path refined.",
                      Patterns::Double(0.));
    prm.add_parameter("Linear solver", linear_solver,
                      "direct: sparse Cholesky (CHOLMOD; UMFPACK's LU if the matrix is not numerically positive "
                      "definite); cg-amg: conjugate gradients with AMG (Trilinos ML, rigid-body modes) on the "
                      "standard unknowns and a direct solve on the enriched ones, for large meshes.",
                      Patterns::Selection("direct|cg-amg"));
    prm.add_parameter("Reference load factor", reference_load_factor,
                      "The load factor lambda the problem is solved at; every field is then scaled (linear "
                      "elasticity), so it changes the results in their last bits only.",
                      Patterns::Double(1e-30, 1e30));
    prm.leave_subsection();
  }

  double crack_tolerance(const Scene &scene)
  {
    const auto &box = scene.body.bounding_box();
    return 1e-8 * std::max(box.width(), box.height());
  }

  std::vector<global::Crack> enriched_cracks(const std::vector<geometry::Polyline> &polylines, const Scene &scene)
  {
    std::vector<global::Crack> cracks;
    for (const auto &line : polylines)
      cracks.emplace_back(line, scene.body, crack_tolerance(scene));
    global::join_touching(cracks, crack_tolerance(scene));
    return cracks;
  }

  void check_tip_radius(const Scene &scene, const GlobalSettings &settings)
  {
    for (const auto &crack : enriched_cracks(scene.cracks, scene))
      for (const auto &tip : crack.tips())
        {
          if (const double clearance = scene.body.clearance(tip.position); clearance <= settings.tip_radius)
            throw InvalidParameter("Tip enrichment radius", to_text(settings.tip_radius),
                                   "must be less than the distance from each initial tip to the body's outline and "
                                   "holes (the tip at " +
                                     to_text(tip.position) + " lies " + to_text(clearance) +
                                     " m from it): the interaction integral's domain would cross that boundary");
          // The cell at the tip once refined (GlobalProblem::refine halves it at each level).
          const auto cell =
            dealii::GridTools::find_active_cell_around_point(*scene.mesh, dealii::Point<2>(tip.position.x, tip.position.y));
          const double at_tip = cell->diameter() / std::pow(2., settings.refinement_levels);
          if (const std::string why = global::unresolved_tip_separation(crack, at_tip); !why.empty())
            throw InvalidParameter("Initial cracks", geometry::to_text(crack.vertices()),
                                   why + "; refine the mesh at the tips (Mesh size, Refinement levels near the tip)");
        }
  }

  double estimated_cells(const Scene &scene, const GlobalSettings &settings)
  {
    double area = scene.body.outline().area();
    for (const auto &hole : scene.body.holes())
      area -= hole.area();
    const double pi    = std::acos(-1.);
    const double cells = double(scene.mesh->n_active_cells());
    const double r     = settings.refinement_radius;
    std::size_t  tips  = 0;
    for (const auto &crack : enriched_cracks(scene.cracks, scene))
      tips += crack.tips().size();
    const double refined =
      std::min(area, double(std::max<std::size_t>(tips, 1)) * (pi * r * r + 2. * r * settings.refinement_trail));
    return cells + cells * refined / area * (std::pow(4., settings.refinement_levels) - 1.);
  }

  void check_refinement(const Scene &scene, const GlobalSettings &settings, double max_cells)
  {
    const double      r         = settings.refinement_radius;
    const double      estimated = estimated_cells(scene, settings);
    const std::string name = "Refinement levels near the tip", value = std::to_string(settings.refinement_levels);
    const std::string what = "with Refinement radius = " + to_text(r) + " m and Refinement trail = " +
                             to_text(settings.refinement_trail) + " m the mesh would have about " +
                             to_text(estimated, 3) + " cells";
    const std::string remedy = ": fewer levels or a smaller radius";
    if (estimated > max_cells)
      throw InvalidParameter(name, value, what + ", more than Maximum cells = " + to_text(max_cells, 3) + remedy);
    global::check_memory(estimated, name, value, what, remedy);
  }

  GlobalProblem::GlobalProblem(const Scene &s, const GlobalSettings &g)
    : scene(s)
    , settings(g)
    , tria(std::make_unique<dealii::Triangulation<2>>())
  {
    tria->copy_triangulation(*scene.mesh);
    make_problem();
    for (const auto &w : problem->warnings())
      std::cerr << w << std::endl;
  }

  GlobalProblem::~GlobalProblem() = default;

  void GlobalProblem::make_problem()
  {
    global::EnrichmentSettings enrichment;
    enrichment.tip_radius = settings.tip_radius;
    problem               = std::make_unique<global::EnrichedElasticity>(
      *tria,
      global::ElasticMaterial{scene.material.youngs_modulus, scene.material.poisson_ratio, scene.material.plane_strain},
      enrichment);
    global::apply(scene.conditions, *problem, settings.reference_load_factor);
  }

  void GlobalProblem::mesh_for(const std::vector<geometry::Point> &tips)
  {
    std::vector<Refinement> wanted;
    for (const auto &r : history)
      if (std::any_of(tips.begin(), tips.end(),
                      [&](const geometry::Point &tip) { return geometry::norm(r.at - tip) <= settings.refinement_trail; }))
        wanted.push_back(r);
    // The mesh is refined refinement by refinement: while no earlier refinement has left the
    // trail, the current mesh is the start of the wanted one.
    const auto same   = [](const Refinement &a, const Refinement &b) {
      return a.at.x == b.at.x && a.at.y == b.at.y && a.levels == b.levels;
    };
    const bool extends = applied.size() <= wanted.size() &&
                         std::equal(applied.begin(), applied.end(), wanted.begin(), same);
    problem.reset();
    if (!extends)
      {
        tria->clear();
        tria->copy_triangulation(*scene.mesh);
        applied.clear();
      }
    for (std::size_t k = applied.size(); k < wanted.size(); ++k)
      refine(wanted[k]);
    applied = std::move(wanted);
    make_problem();
  }

  void GlobalProblem::refine(const Refinement &r)
  {
    const dealii::Point<2> at(r.at.x, r.at.y);
    for (unsigned int l = 0; l < r.levels; ++l)
      {
        bool flagged = false;
        for (const auto &cell : tria->active_cell_iterators())
          if (cell->level() < int(r.levels) &&
              cell->center().distance(at) < settings.refinement_radius + 0.5 * cell->diameter())
            {
              cell->set_refine_flag();
              flagged = true;
            }
        if (!flagged)
          return;
        tria->execute_coarsening_and_refinement();
      }
  }

  std::vector<TipState> GlobalProblem::solve(const global::Crack &crack)
  {
    return solve(std::vector<global::Crack>{crack});
  }

  std::vector<TipState> GlobalProblem::solve(const std::vector<global::Crack> &cracks)
  {
    std::vector<geometry::Point> tips;
    std::vector<global::Tip>     frames;
    for (const auto &crack : cracks)
      for (const auto &t : crack.tips())
        {
          history.push_back({t.position, settings.refinement_levels});
          tips.push_back(t.position);
          frames.push_back(t);
        }
    mesh_for(tips);
    problem->set_cracks(cracks);
    solve_current();

    std::vector<TipState> states;
    const auto            sifs = problem->stress_intensity_factors();
    for (std::size_t t = 0; t < sifs.size(); ++t)
      {
        TipState s;
        s.position  = frames[t].position;
        s.direction = frames[t].direction;
        s.k1        = sifs[t].k1 / lambda;
        s.k2        = sifs[t].k2 / lambda;
        s.k_terms   = sifs[t].k_terms / lambda;
        const double g = (sifs[t].k1 * sifs[t].k1 + sifs[t].k2 * sifs[t].k2) / scene.material.effective_modulus();
        const bool grows = at_rest(s).empty();
        s.critical_load_factor = grows ? lambda * std::sqrt(scene.material.fracture_energy / g)
                                       : std::numeric_limits<double>::infinity();
        const bool finite = std::isfinite(s.k1) && std::isfinite(s.k2) && !std::isnan(s.critical_load_factor) &&
                            (!grows || s.critical_load_factor > 0.);
        if (!finite && cracked_solve_done)
          throw std::runtime_error("the global solve gave K_I = " + to_text(s.k1) + ", K_II = " + to_text(s.k2) +
                                   " Pa m^1/2 at the tip " + to_text(s.position) +
                                   " after earlier solves gave finite ones: the crack's geometry there degenerates");
        if (!finite)
          throw InvalidParameter("Boundary conditions", "the scene's loads",
                                 "give K_I = " + to_text(s.k1) + ", K_II = " + to_text(s.k2) + " Pa m^1/2 and lambda_c = " +
                                   to_text(s.critical_load_factor) + " at the tip " + to_text(s.position) +
                                   ": not representable in double precision; keep the loads, Young's modulus, "
                                   "Fracture energy and Global / Reference load factor near their physical sizes "
                                   "(SI units)");
        states.push_back(s);
      }
    cracked_solve_done = true;
    return states;
  }

  void GlobalProblem::solve_uncracked()
  {
    mesh_for({});
    problem->set_crack(std::nullopt);
    solve_current();
  }

  void GlobalProblem::solve_current()
  {
    problem->setup();
    problem->assemble();
    global::SolverSettings solver;
    if (settings.linear_solver == "cg-amg")
      solver.type = global::SolverSettings::Type::cg_amg;
    problem->solve(solver);
    lambda = settings.reference_load_factor;
  }

  std::vector<geometry::Point> GlobalProblem::displacement_per_unit_load(const std::vector<geometry::Point> &points)
  {
    problem->prepare_point_evaluation(points);
    auto u = problem->evaluate_points();
    for (auto &x : u)
      x = {x.x / lambda, x.y / lambda};
    return u;
  }

  double GlobalProblem::hoop_direction(const TipState &tip, double r)
  {
    const double pi = std::acos(-1.), step = 0.02 * r, faces = 5. * pi / 180.;
    const auto  &m  = scene.material;
    // Lame's constants of the plane problem: plane stress takes lambda* = 2 lambda mu / (lambda + 2 mu).
    const double mu     = m.youngs_modulus / (2. * (1. + m.poisson_ratio));
    const double lambda_3d = m.youngs_modulus * m.poisson_ratio / ((1. + m.poisson_ratio) * (1. - 2. * m.poisson_ratio));
    const double lame   = m.plane_strain ? lambda_3d : 2. * lambda_3d * mu / (lambda_3d + 2. * mu);
    const geometry::Point d = tip.direction, n{-d.y, d.x};
    std::vector<double>          angles;
    std::vector<geometry::Point> points;
    for (double theta = -pi + faces; theta < pi - faces; theta += 0.002)
      {
        angles.push_back(theta);
        const geometry::Point x = tip.position + r * (std::cos(theta) * d + std::sin(theta) * n);
        for (const geometry::Point e : {geometry::Point{step, 0.}, geometry::Point{-step, 0.},
                                        geometry::Point{0., step}, geometry::Point{0., -step}})
          points.push_back(x + e);
      }
    const auto u    = displacement_per_unit_load(points);
    double     best = -std::numeric_limits<double>::infinity(), at = 0.;
    for (std::size_t k = 0; k < angles.size(); ++k)
      {
        const double ux_x = (u[4 * k].x - u[4 * k + 1].x) / (2. * step), uy_x = (u[4 * k].y - u[4 * k + 1].y) / (2. * step);
        const double ux_y = (u[4 * k + 2].x - u[4 * k + 3].x) / (2. * step),
                     uy_y = (u[4 * k + 2].y - u[4 * k + 3].y) / (2. * step);
        const double sxx = lame * (ux_x + uy_y) + 2. * mu * ux_x, syy = lame * (ux_x + uy_y) + 2. * mu * uy_y;
        const double sxy = mu * (ux_y + uy_x);
        const double phi = angles[k] + std::atan2(d.y, d.x), c = std::cos(phi), s = std::sin(phi);
        const double hoop = sxx * s * s + syy * c * c - 2. * sxy * s * c;
        if (hoop > best)
          best = hoop, at = angles[k];
      }
    return at;
  }

  void GlobalProblem::scale_to(double new_lambda)
  {
    problem->scale_solution(new_lambda / lambda);
    lambda = new_lambda;
  }

  std::pair<double, double> GlobalProblem::report() const
  {
    const auto  &r    = scene.report;
    const auto   pick = [](geometry::Point v, int c) { return c == 0 ? v.x : v.y; };
    double       load = lambda, displacement = 0.;
    if (!r.load_is_lambda)
      {
        geometry::Point f;
        if (r.load_place.kind == conditions::Place::Kind::boundary)
          f = problem->reaction(r.load_place.id);
        else
          for (const auto &x : r.load_place.points)
            f = f + problem->reaction_at(x);
        load = r.load_sign * pick(f, r.load_component);
      }
    if (r.work_conjugate)
      displacement = lambda != 0. ? 2. * problem->strain_energy() / lambda : 0.;
    else
      {
        const geometry::Point u = r.displacement_place.kind == conditions::Place::Kind::boundary
                                    ? problem->mean_displacement(r.displacement_place.id)
                                    : problem->displacement(r.displacement_place.points.front());
        displacement = r.displacement_sign * pick(u, r.displacement_component);
      }
    return {load, displacement};
  }

  unsigned int GlobalProblem::n_dofs() const { return problem->n_dofs(); }
  unsigned int GlobalProblem::n_enriched_dofs() const { return problem->n_enriched_dofs(); }
  void         GlobalProblem::write_vtu(const std::string &file) const { problem->write_vtu(file); }

  std::string at_rest(const TipState &tip)
  {
    constexpr double resolved = 1e-2; // of k_terms, and of |K_II| for K_I: see the declaration
    if (!(std::hypot(tip.k1, tip.k2) > resolved * tip.k_terms))
      return "has no driving force (|K| = " + to_text(std::hypot(tip.k1, tip.k2), 3) +
             " Pa m^1/2 per unit load factor, within the interaction integral's noise: under 1 % of its terms, " +
             to_text(tip.k_terms, 3) + ")";
    if (tip.k1 < -resolved * std::abs(tip.k2))
      return "is closed (K_I < 0)";
    return "";
  }

  double kink_angle(double k1, double k2)
  {
    const double s = k1 + std::sqrt(k1 * k1 + 8. * k2 * k2);
    if (k2 == 0. || s == 0.)
      return 0.;
    return -2. * std::atan(2. * k2 / s);
  }
} // namespace pumpd::coupling
