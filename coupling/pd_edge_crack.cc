#include "pd_edge_crack.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <ostream>

#include <deal.II/base/parameter_handler.h>

#include "boundary_layer.h"
#include "csv.h"
#include "checkpoint.h"
#include "error.h"
#include "integrators.h"
#include "lefm.h"
#include "model.h"
#include "vtu_output.h"

namespace pumpd::coupling
{
  namespace Patterns = dealii::Patterns;

  void EdgeCrackSettings::add_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Edge crack");
    prm.add_parameter("Box size", box_size, "Side of the square PD box [m], at least 4 horizons; the crack tip is at its centre.",
                      Patterns::Double(1e-300));
    prm.add_parameter("First K over K_c", k_start, "K of the first load step, as a multiple of K_c = sqrt(E' G_c).",
                      Patterns::Double(1e-6, 1000.));
    prm.add_parameter("Last K over K_c", k_end, "K of the last load step, at least the first.", Patterns::Double(1e-6, 1000.));
    prm.add_parameter("Load steps", load_steps, "Number of K levels, equally spaced.", Patterns::Integer(1, 10000));
    prm.add_parameter("Stop after growth", growth_to_stop,
                      "Stop the load steps once the crack grew this far [m]; 0 runs all steps.", Patterns::Double(0.));
    prm.add_parameter("Output interval", output_interval, "Write the PD state every n load steps.", Patterns::Integer(1));
    prm.leave_subsection();
  }

  namespace
  {
    void validate(const EdgeCrackParameters &p)
    {
      require_range("Last K over K_c", p.edge.k_end, p.edge.k_start, 1e3, "must be >= the first K over K_c");
      if (p.edge.box_size < 4. * p.pd.horizon)
        throw InvalidParameter("Box size", std::to_string(p.edge.box_size),
                               "must be at least 4 horizons (" + std::to_string(4. * p.pd.horizon) +
                                 " m): a horizon of boundary layer on each side and room for the tip");
    }
  } // namespace

  EdgeCrackResult run_edge_crack(const EdgeCrackParameters &p, std::ostream &out)
  {
    validate(p);
    const double half = 0.5 * p.edge.box_size;
    const double h    = p.pd.horizon / p.pd.horizon_over_spacing;
    local::Region region;
    region.body   = geometry::Body(geometry::Box{-4. * half, -4. * half, 4. * half, 4. * half}); // every box edge interior
    region.box    = {-half, -half, half, half};
    region.cracks = {{{-half - h, 0.}, {0., 0.}}};
    const local::PdModel model(p.material, p.pd.horizon, p.pd.horizon_over_spacing, region);

    const auto  &mat   = model.material();
    const double kc    = mat.critical_sif();
    const double kappa = lefm::kolosov(mat.poisson_ratio(), p.material.plane_strain);
    out << "PD edge crack: box " << p.edge.box_size << " m, delta " << p.pd.horizon << " m, m = " << p.pd.horizon_over_spacing
        << ", " << model.nodes().size() << " nodes (" << model.boundary_layer().size()
        << " in the boundary layer), K_c = " << kc << " Pa m^1/2\n";

    local::BoundaryLayer           layer(model);
    local::State                   s = model.initial_state();
    const local::DynamicRelaxation relax(model, p.pd.tolerance, p.pd.max_iterations);
    std::unique_ptr<PvdSeries> series;
    CsvFile                    table;
    if (!p.output_directory.empty())
      {
        series = std::make_unique<PvdSeries>(p.output_directory, "pd");
        table  = CsvFile(p.output_directory + "/load_steps.csv", "step,k_over_kc,crack_extension_m,max_damage,"
                                                                "elastic_energy_J_per_m,dissipated_J_per_m,dr_iterations,seconds");
      }

    EdgeCrackResult result;
    result.spacing  = h;
    double previous = 0.;
    const auto t0   = std::chrono::steady_clock::now();
    for (std::size_t n = 0; n < p.edge.load_steps; ++n)
      {
        const auto   t_step = std::chrono::steady_clock::now();
        const double k =
          p.edge.load_steps == 1 ? p.edge.k_end : p.edge.k_start + (p.edge.k_end - p.edge.k_start) * double(n) / double(p.edge.load_steps - 1);
        // Start from the last equilibrium scaled to the new load (exact while the box is elastic).
        for (std::size_t i : model.nodes())
          {
            s.ux[i] = previous > 0. ? s.ux[i] * k / previous : 0.;
            s.uy[i] = previous > 0. ? s.uy[i] * k / previous : 0.;
          }
        layer.set_target([&](geometry::Point x) {
          return lefm::williams_displacement(x, {0., 0.}, {1., 0.}, k * kc, 0., mat.shear_modulus(), kappa);
        });
        layer.apply(s, 1.);
        const auto relaxed = relax.solve(s);
        if (!relaxed.converged)
          out << "  warning: dynamic relaxation stopped at residual " << relaxed.residual << " after "
              << relaxed.iterations << " iterations\n";
        previous = k;

        const auto    damage = model.damage(s);
        EdgeCrackStep step;
        step.k_over_kc  = k;
        step.iterations = relaxed.iterations;
        double tip      = 0.; // the initial tip: face nodes of the pre-crack end at x = -h/2
        for (std::size_t i : model.nodes())
          {
            step.max_damage = std::max(step.max_damage, damage[i]);
            const auto x    = model.lattice().position(i);
            if (damage[i] > p.pd.crack_damage && std::abs(x.y) < 0.5 * half)
              tip = std::max(tip, x.x + 0.5 * h);
          }
        step.extension = tip;
        step.seconds   = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_step).count();
        result.steps.push_back(step);
        if (result.onset_k_over_kc == 0. && step.extension >= 2. * h)
          result.onset_k_over_kc = k;

        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const double eta     = elapsed / double(n + 1) * double(p.edge.load_steps - n - 1);
        out << "load step " << std::setw(3) << n + 1 << "/" << p.edge.load_steps << "  K/K_c " << std::setw(6) << k
            << "  DR iterations " << std::setw(6) << relaxed.iterations << "  max damage " << std::setw(8)
            << step.max_damage << "  crack growth " << std::setw(9) << step.extension << " m  ETA "
            << std::fixed << std::setprecision(0) << eta << " s" << std::defaultfloat << std::setprecision(6)
            << "\n";
        table.row(n + 1, k, step.extension, step.max_damage, model.elastic_energy(s), s.dissipated, relaxed.iterations,
                  step.seconds);
        if (series && ((n + 1) % p.edge.output_interval == 0 || n + 1 == p.edge.load_steps))
          local::write_vtu(*series, model, s);
        if (p.edge.growth_to_stop > 0. && step.extension >= p.edge.growth_to_stop)
          break;
      }
    if (!p.output_directory.empty())
      local::write_checkpoint(p.output_directory + "/checkpoint.h5", model, s,
                              {{"k_over_kc", previous}, {"load_steps_done", double(result.steps.size())}});

    const auto damage = model.damage(s);
    CsvFile    map    = p.output_directory.empty() ? CsvFile() : CsvFile(p.output_directory + "/damage.csv", "x_m,y_m,damage");
    for (std::size_t i : model.nodes())
      {
        const auto x = model.lattice().position(i);
        map.row(x.x, x.y, damage[i]);
        if (damage[i] > p.pd.crack_damage && x.x > 0.)
          {
            result.crack_nodes.push_back(x);
            result.max_offset = std::max(result.max_offset, std::abs(x.y));
          }
      }
    return result;
  }
} // namespace pumpd::coupling
