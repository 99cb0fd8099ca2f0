#include "exchange.h"

#include <algorithm>
#include <chrono>
#include <cmath>
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

    /// The box's PD states at given load factors: the boundary layer and the held places at
    /// lambda lambda_c, the state relaxed, its tips' increments read off the damage.
    class BoxStates
    {
    public:
      BoxStates(const local::PdModel &model, const BoundaryTransfer &transfer, const std::vector<TipState> &tips,
                const std::vector<std::vector<geometry::Polyline>> &faces, const PeridynamicsSettings &pd)
        : model(model)
        , transfer(transfer)
        , tips(tips)
        , layer(model)
        , relax(model, pd.tolerance, pd.max_iterations)
        , lambda_c(tips.front().critical_load_factor)
        , extraction(tips.size())
      {
        for (std::size_t k = 0; k < tips.size(); ++k)
          {
            extraction[k].threshold = pd.crack_damage;
            extraction[k].horizon   = pd.horizon;
            if (!faces.empty())
              extraction[k].faces = faces[k];
          }
      }

      /// The undamaged box at lambda (the crack's bonds broken), before its relaxation.
      local::State start(double lambda) const
      {
        local::State s = model.initial_state();
        transfer.start(lambda * lambda_c, s);
        return s;
      }

      /// Relaxes s, predicted from the equilibrium `before` at lambda_s, at lambda.
      local::RelaxationResult relaxed(const std::optional<Equilibrium> &before, double lambda_s, double lambda,
                                      local::State &s, ExchangeOutcome &r)
      {
        const auto t = Clock::now();
        predict(model, before, lambda_s, lambda, s);
        transfer.apply(lambda * lambda_c, layer);
        layer.apply(s, 1.);
        transfer.hold(lambda * lambda_c, s);
        const auto result = relax.solve(s);
        local::check_finite(model, s);
        r.iterations += result.iterations;
        r.unrelaxed += result.converged ? 0 : 1;
        r.node_steps += double(result.iterations) * double(model.nodes().size());
        r.seconds_pd += seconds_since(t);
        return result;
      }

      /// Per tip, its increment in s (throws CrackBranching).
      std::vector<CrackIncrement> increments(const local::State &s, ExchangeOutcome &r) const
      {
        const auto                  t      = Clock::now();
        const DamageField           damage = damage_field(model, s);
        std::vector<CrackIncrement> result;
        for (std::size_t k = 0; k < tips.size(); ++k)
          result.push_back(extract_crack(damage, tips[k].position, tips[k].direction, extraction[k]));
        r.seconds_extraction += seconds_since(t);
        return result;
      }

    private:
      const local::PdModel            &model;
      const BoundaryTransfer          &transfer;
      const std::vector<TipState>     &tips;
      local::BoundaryLayer             layer;
      const local::DynamicRelaxation   relax;
      const double                     lambda_c;
      std::vector<ExtractionSettings>  extraction;
    };

    bool any_grew(const std::vector<CrackIncrement> &increments)
    {
      return std::any_of(increments.begin(), increments.end(), [](const auto &i) { return i.path.size() > 1; });
    }

    /// The onset of growth (exchange.h): the bracket (quiet, grows_at] of the ladder refined by
    /// bisection from the quiet equilibrium; without a quiet state of the ladder, states of the
    /// undamaged box one load increment apart below its first one find it.
    double growth_onset(BoxStates &box, std::optional<Equilibrium> quiet, double grows_at, double load_increment,
                        double resolution, ExchangeOutcome &r, std::ostream &out, const std::string &unit)
    {
      const auto probe = [&](local::State &s, const std::optional<Equilibrium> &from, double lambda) {
        const auto relaxed = box.relaxed(std::nullopt, from ? from->lambda : lambda, lambda, s, r);
        ++r.onset_states;
        bool grew = true;
        try
          {
            grew = any_grew(box.increments(s, r));
          }
        catch (const CrackBranching &)
          {
          }
        out << "    PD at " << std::setprecision(4) << lambda << " " << unit << ": " << relaxed.iterations
            << " DR iterations -> " << (grew ? "grows: the onset lies at or below" : "no growth: the onset lies above")
            << "\n"
            << std::setprecision(6);
        return grew;
      };
      for (double lambda = grows_at - load_increment; !quiet && lambda >= 0.05 - 1e-12; lambda -= load_increment)
        {
          local::State s = box.start(lambda);
          if (probe(s, std::nullopt, lambda))
            grows_at = lambda;
          else
            quiet = Equilibrium{std::move(s), lambda};
        }
      while (quiet && grows_at - quiet->lambda > resolution * (1. + 1e-9))
        {
          const double lambda = 0.5 * (quiet->lambda + grows_at);
          local::State s      = quiet->state;
          if (probe(s, quiet, lambda))
            grows_at = lambda;
          else
            quiet = Equilibrium{std::move(s), lambda};
        }
      return grows_at;
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
    BoxStates box(model, transfer, tips, faces, pd);

    ExchangeOutcome r;
    local::State   &s      = r.state;
    double          lambda = controller.start();
    s                      = box.start(lambda);
    local::State               saved        = s; // the state a repeat starts from
    double                     saved_lambda = lambda, state_lambda = lambda;
    std::optional<Equilibrium> before; // the equilibrium before `saved`
    std::optional<Equilibrium> quiet;  // the last equilibrium before the crack first grew
    double grows_at = std::numeric_limits<double>::quiet_NaN(); // the first load factor it grew at
    for (;;)
      {
        const auto relaxed = box.relaxed(before, state_lambda, lambda, s, r);
        state_lambda       = lambda;
        ++r.states;
        try
          {
            r.increments = box.increments(s, r);
          }
        catch (const CrackBranching &e)
          {
            r.branching = e.what();
            r.increments.clear();
            break;
          }
        r.reaches.clear();
        if (std::isnan(grows_at) && any_grew(r.increments))
          {
            grows_at = lambda;
            if (r.states > 1) // the state before it, relaxed without growth
              quiet = Equilibrium{saved, saved_lambda};
          }
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
    if (r.branching.empty() && !std::isnan(grows_at))
      r.onset_load_factor = growth_onset(box, std::move(quiet), grows_at, controller.settings().load_increment,
                                         controller.settings().onset_resolution, r, out, unit);
    return r;
  }
} // namespace pumpd::coupling
