#include "exchange.h"

#include <chrono>
#include <iomanip>
#include <limits>
#include <optional>
#include <ostream>

#include "error.h"
#include "integrators.h"

namespace pumpd::coupling
{
  using Clock = std::chrono::steady_clock;

  namespace
  {
    double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
  } // namespace

  const char *to_text(ExchangeController::Decision d)
  {
    switch (d)
      {
        case ExchangeController::Decision::raise:
          return "raise";
        case ExchangeController::Decision::repeat:
          return "repeat";
        case ExchangeController::Decision::accept:
          return "accept";
        case ExchangeController::Decision::truncate:
          return "truncate";
        case ExchangeController::Decision::too_small:
          return "too-small";
      }
    return "";
  }

  DamageField damage_field(const local::PdModel &model, const local::State &s)
  {
    const auto &lattice = model.lattice();
    const auto  damage  = model.damage(s);
    DamageField field;
    field.origin  = lattice.position(lattice.index(0, 0));
    field.spacing = lattice.spacing();
    field.nx      = lattice.nx();
    field.ny      = lattice.ny();
    field.values.assign(field.nx * field.ny, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i : model.nodes())
      field.values[lattice.row(i) * field.nx + lattice.column(i)] = damage[i];
    return field;
  }

  namespace
  {
    /// A relaxed PD state and its load factor.
    struct Equilibrium
    {
      local::State state;
      double       lambda = 0.;
    };

    /// The start of the PD state at `lambda` from the equilibrium s at lambda_s: the secant through
    /// the equilibrium before it (first-order continuation in the load factor) where there is
    /// one, else s scaled (exact while the box is elastic).
    void predict(const local::PdModel &model, const std::optional<Equilibrium> &before, double lambda_s,
                 double lambda, local::State &s)
    {
      if (before && lambda_s > before->lambda)
        {
          const double r = (lambda - lambda_s) / (lambda_s - before->lambda);
          for (std::size_t i : model.nodes())
            {
              s.ux[i] += r * (s.ux[i] - before->state.ux[i]);
              s.uy[i] += r * (s.uy[i] - before->state.uy[i]);
            }
          return;
        }
      for (std::size_t i : model.nodes())
        {
          s.ux[i] *= lambda / lambda_s;
          s.uy[i] *= lambda / lambda_s;
        }
    }
  } // namespace

  ExchangeOutcome run_exchange(const local::PdModel &model, const BoundaryTransfer &transfer,
                               ExchangeController &controller, const std::vector<TipState> &tips,
                               const std::vector<double> &allowed,
                               const std::vector<std::vector<geometry::Polyline>> &faces,
                               const std::function<bool(const geometry::Polyline &)> &arrives,
                               const PeridynamicsSettings &pd, std::ostream &out, const std::string &unit,
                               double advance_scale)
  {
    // Per tip: its trace ends on the other cracks' faces.
    std::vector<ExtractionSettings> extraction(tips.size());
    for (std::size_t k = 0; k < tips.size(); ++k)
      {
        extraction[k].threshold = pd.crack_damage;
        extraction[k].horizon   = pd.horizon;
        if (!faces.empty())
          extraction[k].faces = faces[k];
      }
    local::BoundaryLayer           layer(model);
    const local::DynamicRelaxation relax(model, pd.tolerance, pd.max_iterations);
    const double                   lambda_c = tips.front().critical_load_factor;

    ExchangeOutcome r;
    local::State   &s      = r.state;
    s                      = model.initial_state();
    double          lambda = controller.start();
    transfer.start(lambda * lambda_c, s);
    local::State               saved        = s; // the state a repeat starts from
    double                     saved_lambda = lambda, state_lambda = lambda;
    std::optional<Equilibrium> before; // the equilibrium before `saved`
    for (;;)
      {
        auto t = Clock::now();
        predict(model, before, state_lambda, lambda, s);
        transfer.apply(lambda * lambda_c, layer);
        layer.apply(s, 1.);
        transfer.hold(lambda * lambda_c, s);
        const auto relaxed = relax.solve(s);
        local::check_finite(model, s);
        state_lambda = lambda;
        r.iterations += relaxed.iterations;
        ++r.states;
        r.unrelaxed += relaxed.converged ? 0 : 1;
        r.node_steps += double(relaxed.iterations) * double(model.nodes().size());
        r.seconds_pd += seconds_since(t);

        t = Clock::now();
        const DamageField damage = damage_field(model, s);
        r.increments.clear();
        r.reaches.clear();
        try
          {
            for (std::size_t k = 0; k < tips.size(); ++k)
              r.increments.push_back(extract_crack(damage, tips[k].position, tips[k].direction, extraction[k]));
          }
        catch (const CrackBranching &e)
          {
            r.branching = e.what();
          }
        r.seconds_extraction += seconds_since(t);
        if (!r.branching.empty())
          break;
        std::size_t farthest = 0;
        for (std::size_t k = 1; k < tips.size(); ++k)
          if (r.increments[k].length() / allowed[k] > r.increments[farthest].length() / allowed[farthest])
            farthest = k;
        for (const auto &increment : r.increments)
          r.reaches.push_back(increment.path.size() > 1 && (arrives(increment.path) ||
                                                            increment.stop_reason.rfind(reaches_face, 0) == 0));
        const auto &increment = r.increments[farthest];
        r.decision            = controller.judge(increment.length() / advance_scale, allowed[farthest] / advance_scale,
                                                 r.reaches[farthest]);
        out << "    PD at " << std::setprecision(4) << lambda << " " << unit << ": " << relaxed.iterations
            << " DR iterations"
            << (relaxed.converged ? "" : " (not relaxed within Relaxation max iterations: residual " +
                                           pumpd::to_text(relaxed.residual, 3) + ")")
            << ", advance " << increment.length() << " m"
            << (tips.size() > 1 ? " (tip " + std::to_string(farthest) + " of the box)" : "") << " -> "
            << to_text(r.decision) << "\n"
            << std::setprecision(6);
        if (r.decision == ExchangeController::Decision::raise)
          {
            if (r.states > 1)
              before = Equilibrium{saved, saved_lambda};
            saved        = s;
            saved_lambda = lambda;
            lambda       = controller.load_factor();
          }
        else if (r.decision == ExchangeController::Decision::repeat)
          {
            s            = saved;
            state_lambda = saved_lambda;
            lambda       = controller.load_factor();
            ++r.repeats;
          }
        else
          break;
      }
    r.load_factor = lambda;
    return r;
  }
} // namespace pumpd::coupling
