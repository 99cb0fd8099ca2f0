#include "full_pd.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <memory>
#include <ostream>
#include <sstream>

#include "beam_scene.h"
#include "boundary_layer.h"
#include "crack_extraction.h"
#include "error.h"
#include "integrators.h"
#include "model.h"
#include "path_metrics.h"
#include "vtu_output.h"

namespace pumpd::coupling
{
  using geometry::Point;
  using Clock = std::chrono::steady_clock;

  namespace
  {
    double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

    std::string text(double v)
    {
      std::ostringstream s;
      s << v;
      return s.str();
    }

    void validate(const FullPdParameters &p)
    {
      const auto &o = p.outline;
      if (!(o.width() > 0. && o.height() > 0.) || !std::isfinite(o.width()) || !std::isfinite(o.height()))
        throw InvalidParameter("Beam outline", to_text(Point{o.x_min, o.y_min}) + "; " + to_text(Point{o.x_max, o.y_max}),
                               "needs a lower-left and an upper-right corner with positive width and height");
      const double tol = 1e-9 * std::max(o.width(), o.height());
      for (const auto &c : p.holes)
        if (!(c.radius > 0.) || !o.contains(geometry::Box{c.centre.x - c.radius, c.centre.y - c.radius, c.centre.x + c.radius,
                                                  c.centre.y + c.radius},
                                              tol))
          throw InvalidParameter("Holes", to_text(c.centre) + " r " + text(c.radius),
                                 "each hole needs a radius > 0 and must lie inside the beam outline");
      if (p.initial_crack.size() < 2)
        throw InvalidParameter("Initial crack", to_text(p.initial_crack), "needs at least 2 points");
      for (const auto &x : p.initial_crack)
        if (!o.contains(x, tol))
          throw InvalidParameter("Initial crack", to_text(p.initial_crack), "must lie inside the beam outline");
      for (const auto &[name, x] : {std::pair<const char *, Point>{"Pin support", p.pin},
                                    {"Roller support", p.roller},
                                    {"Load point", p.load_point}})
        if (!o.contains(x, tol))
          throw InvalidParameter(name, to_text(x), "must lie on or inside the beam outline");
      if (!(p.support_radius >= 0.) || !(p.support_radius <= 0.5 * std::min(o.width(), o.height())))
        throw InvalidParameter("Support radius", text(p.support_radius),
                               "must be in [0, half the beam's smaller side] m (0: one horizon)");
      if (!(p.no_fail_radius == 0. || (p.no_fail_radius >= p.support_radius && p.no_fail_radius <= 0.5 * std::min(o.width(), o.height()))))
        throw InvalidParameter("No-fail radius", text(p.no_fail_radius),
                               "must be 0 (none) or in [Support radius, half the beam's smaller side] m");
      require_positive("Horizon", p.horizon);
      if (p.horizon_ratio < 2)
        throw InvalidParameter("Horizon over spacing", std::to_string(p.horizon_ratio),
                               "must be an integer >= 2: the horizon spans at least two PD spacings");
      require_range("Crack damage threshold", p.crack_damage, 0.05, 0.95, "must be in [0.05, 0.95]");
      require_range("Onset stretch ratio", p.onset_stretch_ratio, 1e-3, 1., "must be in [0.001, 1]");
      require_range("Minimum increment", p.min_increment, 1e-6, 1., "must be in [1e-6, 1]: a fraction of the displacement");
      require_range("Maximum increment", p.max_increment, p.min_increment, 1.,
                    "must be in [Minimum increment, 1]");
      require_range("First increment", p.first_increment, p.min_increment, p.max_increment,
                    "must be in [Minimum increment, Maximum increment]");
      if (!(p.target_advance >= 0.) || !std::isfinite(p.target_advance))
        throw InvalidParameter("Target advance", text(p.target_advance), "must be >= 0 m (0: one horizon)");
      if (!(p.max_advance >= 0.) || !std::isfinite(p.max_advance))
        throw InvalidParameter("Maximum advance", text(p.max_advance), "must be >= 0 m (0: four horizons)");
      const double target = p.target_advance > 0. ? p.target_advance : p.horizon;
      if (p.max_advance > 0. && p.max_advance < target)
        throw InvalidParameter("Maximum advance", text(p.max_advance),
                               "must be 0 or at least the target advance (" + text(target) + " m)");
      require_positive("Maximum displacement", p.max_displacement);
      if (p.max_steps < 1)
        throw InvalidParameter("Maximum steps", "0", "must be >= 1");
      if (p.stall_steps < 1)
        throw InvalidParameter("Stall steps", "0", "must be >= 1");
      if (!(p.hole_margin >= 0.) || !(p.hole_margin <= 0.1))
        throw InvalidParameter("Hole margin", text(p.hole_margin), "must be in [0, 0.1] m");
      if (p.output_interval < 1)
        throw InvalidParameter("Output interval", "0", "must be >= 1");
      require_range("Servo gain", p.servo_gain, 1e-6, 1., "must be in [1e-6, 1]");
      if (!(p.gauge_distance >= 0.) || !(p.gauge_distance <= 0.25 * o.width()))
        throw InvalidParameter("Gauge distance", text(p.gauge_distance),
                               "must be in [0, a quarter of the beam's width] m (0: one horizon)");
    }

    /// The material node nearest x.
    std::size_t nearest_node(const local::PdModel &model, Point x)
    {
      std::size_t best = model.nodes().front();
      for (std::size_t i : model.nodes())
        if (geometry::norm(model.lattice().position(i) - x) < geometry::norm(model.lattice().position(best) - x))
          best = i;
      return best;
    }

    double peak_rss_mb()
    {
      rusage usage{};
      getrusage(RUSAGE_SELF, &usage);
      return double(usage.ru_maxrss) / 1024.; // kB on Linux
    }
  } // namespace

  FullPdResult run_full_pd(const FullPdParameters &parameters, std::ostream &out)
  {
    const FullPdParameters &p = parameters;
    validate(p);
    const auto   t0     = Clock::now();
    const double h      = p.horizon / p.horizon_ratio;
    const double radius = p.support_radius > 0. ? p.support_radius : p.horizon;
    const double a_t    = p.target_advance > 0. ? p.target_advance : p.horizon;
    const double a_max  = p.max_advance > 0. ? p.max_advance : 4. * p.horizon;
    const geometry::Polyline reference = p.published_path.empty() ? geometry::Polyline{} : read_path(p.published_path);

    geometry::Body body{p.outline, p.holes};
    local::Region  region{body, p.outline, {p.initial_crack}};
    std::vector<local::PrescribedRegion> supports = {
      local::PrescribedRegion::disk("Pin support", p.pin, radius, true, true),
      local::PrescribedRegion::disk("Roller support", p.roller, radius, false, true),
      local::PrescribedRegion::disk("Load point", p.load_point, radius, false, true)};
    if (p.no_fail_radius > 0.)
      for (auto &r : supports)
        r.elastic_margin = std::max(0., p.no_fail_radius - radius);
    const local::PdModel model(p.material, p.horizon, p.horizon_ratio, region, supports);
    local::RegionDisplacement pin(model, 0), roller(model, 1), load(model, 2);
    pin.set_target(Point{0., 0.});
    roller.set_target(Point{0., 0.});
    const local::DynamicRelaxation relax(model, p.tolerance, p.max_iterations);
    const double                   n_nodes = double(model.nodes().size());

    const Point tip0 = p.initial_crack.back();
    Point       dir0 = tip0 - p.initial_crack[p.initial_crack.size() - 2];
    dir0             = (1. / geometry::norm(dir0)) * dir0;
    ExtractionSettings extraction;
    extraction.threshold = p.crack_damage;
    extraction.horizon   = p.horizon;
    const double length0 = geometry::length(p.initial_crack);

    // Crack-mouth opening w: the relative displacement of two gauge nodes either side of the
    // mouth, along the normal to the initial crack.
    const Point mouth_dir = (1. / geometry::norm(p.initial_crack[1] - p.initial_crack[0])) *
                            (p.initial_crack[1] - p.initial_crack[0]);
    const Point       normal{mouth_dir.y, -mouth_dir.x};
    const double      gauge = p.gauge_distance > 0. ? p.gauge_distance : p.horizon;
    const std::size_t gauge_minus = nearest_node(model, p.initial_crack[0] - gauge * normal);
    const std::size_t gauge_plus  = nearest_node(model, p.initial_crack[0] + gauge * normal);
    const auto mouth_opening = [&](const local::State &st) {
      return (st.ux[gauge_plus] - st.ux[gauge_minus]) * normal.x +
             (st.uy[gauge_plus] - st.uy[gauge_minus]) * normal.y;
    };
    const bool by_mouth = p.control == FullPdParameters::Control::crack_mouth_opening;

    // Nodes near the initial tip: their stretch ratio decides the elastic jump (the pads' own
    // stress concentrations do not).
    std::vector<std::size_t> near_tip;
    for (std::size_t i : model.nodes())
      if (geometry::norm(model.lattice().position(i) - tip0) < 2. * p.horizon)
        near_tip.push_back(i);

    std::unique_ptr<local::PvdSeries> series;
    std::ofstream                     table;
    if (!p.output_directory.empty())
      {
        std::filesystem::create_directories(p.output_directory);
        series = std::make_unique<local::PvdSeries>(p.output_directory, "pd");
        write_body(p.output_directory + "/body.csv", body, {{"pin", p.pin}, {"roller", p.roller}, {"load", p.load_point}});
        if (!reference.empty())
          write_path(p.output_directory + "/reference_path.csv", reference);
        write_path(p.output_directory + "/crack_path.csv", p.initial_crack);
        table.open(p.output_directory + "/load_steps.csv");
        table << "step,load_point_displacement_m,crack_mouth_opening_m,load_N_per_m,crack_length_m,tip_x_m,tip_y_m,"
                 "dr_iterations,dr_converged,repeats,seconds\n";
      }
    out << "full PD: beam " << p.outline.width() << " x " << p.outline.height() << " m, " << p.holes.size()
        << " holes, initial crack " << length0 << " m; delta " << p.horizon << " m, m = " << p.horizon_ratio
        << ", h = " << h << " m: " << model.nodes().size() << " nodes; supports and load pad of radius " << radius
        << " m (" << model.prescribed_nodes(0).size() << ", " << model.prescribed_nodes(1).size() << ", "
        << model.prescribed_nodes(2).size() << " nodes), no-fail radius " << p.no_fail_radius << " m ("
        << model.linear_bond_count() << " linear bonds); K_c = " << model.material().critical_sif() << " Pa m^1/2\n";

    FullPdResult result;
    result.nodes = model.nodes().size();
    result.path  = p.initial_crack;
    local::State s = model.initial_state();
    // The damage the crack is traced through: per node the largest of the accepted states. Softened
    // bonds behind the tip relax again when the load falls after the peak (the softening is
    // elastic up to the break stretch), but the crack they marked stays.
    DamageField traced;
    std::vector<double> ux_prev(s.ux.size(), 0.), uy_prev(s.uy.size(), 0.); // last accepted state
    // d: the controlled displacement (load point, or crack-mouth opening once the servo is on);
    // pad: the load point's displacement.
    double      d = 0., dd_prev = 0., pad = 0., pad_prev = 0.;
    bool        servo_on   = false;
    double      pad_over_w = 0.; // (d/w)_0 of the servo
    double      dd         = 0.01 * p.max_displacement; // reference state of the elastic phase
    bool        elastic    = true;
    bool        grown      = false;
    std::size_t stalled    = 0;
    double      length     = length0;
    double      growth_t0  = 0.;

    for (std::size_t n = 1;; ++n)
      {
        if (n > p.max_steps)
          {
            result.stop_reason = "maximum steps";
            break;
          }
        if (pad >= p.max_displacement * (1. - 1e-12))
          {
            result.stop_reason = "maximum displacement";
            break;
          }
        if (!servo_on)
          dd = std::min(dd, p.max_displacement - d);
        const auto   t_step = Clock::now();
        FullPdStep   step;
        step.step = n;
        const local::State saved = s;
        CrackIncrement     increment;
        DamageField        field;
        std::string        branching;
        double             d_new = d + dd, pad_new = pad, growth = 0., last_growth = 0.;
        for (;;)
          {
            d_new = d + dd;
            // Predictor: elastic, the state scaled to the new displacement; later the last
            // increment extrapolated.
            pad_new = d_new;
            if (elastic && d > 0.)
              for (std::size_t i : model.nodes())
                {
                  s.ux[i] *= d_new / d;
                  s.uy[i] *= d_new / d;
                }
            else if (dd_prev > 0.)
              {
                const double r = dd / dd_prev;
                for (std::size_t i : model.nodes())
                  {
                    const double ux = s.ux[i], uy = s.uy[i];
                    s.ux[i] += r * (ux - ux_prev[i]);
                    s.uy[i] += r * (uy - uy_prev[i]);
                  }
                if (servo_on)
                  pad_new = pad + r * (pad - pad_prev);
              }
            else if (servo_on)
              pad_new = pad + pad_over_w * dd;
            load.set_target(Point{0., -pad_new});
            pin.apply(s, 1.);
            roller.apply(s, 1.);
            load.apply(s, 1.);
            local::Servo servo;
            if (servo_on)
              {
                // The opening misses its target by e: move the pad by (d/w) e and, with it, the
                // whole body along the secant mode saved / pad (the last accepted state per unit
                // pad displacement), so that the beam's bending follows the pad at once instead of
                // over the relaxation's slowest period; the relaxation then settles the rest.
                servo.tolerance = 0.1 * dd / d_new;
                servo.correct   = [&](local::State &st) {
                  const double error = d_new - mouth_opening(st);
                  if (std::abs(error) < servo.tolerance * d_new)
                    return std::abs(error) / d_new;
                  const double move  = p.servo_gain * pad_over_w * error;
                  const double share = move / pad; // of the secant mode saved / pad
                  for (std::size_t i : model.nodes())
                    {
                      st.ux[i] += share * saved.ux[i];
                      st.uy[i] += share * saved.uy[i];
                    }
                  pad_new += move;
                  load.set_target(Point{0., -pad_new});
                  load.apply(st, 1.);
                  return std::abs(d_new - mouth_opening(st)) / d_new;
                };
              }
            const auto relaxed = relax.solve(s, servo);
            step.iterations += relaxed.iterations;
            step.converged = relaxed.converged;
            result.node_steps += n_nodes * double(relaxed.iterations);
            if (!relaxed.converged)
              out << "  warning: dynamic relaxation stopped at residual " << relaxed.residual << " after "
                  << relaxed.iterations << " iterations\n";
            try
              {
                field = damage_field(model, s);
                if (!traced.values.empty())
                  for (std::size_t k = 0; k < field.values.size(); ++k)
                    field.values[k] = std::max(field.values[k], traced.values[k]);
                increment = extract_crack(field, tip0, dir0, extraction);
              }
            catch (const CrackBranching &e)
              {
                branching = e.what();
                break;
              }
            growth = std::max(0., length0 + increment.length() - length);
            // Repeat a too-long advance with half the increment, unless halving did not shorten it
            // (unstable growth, a snap-back: the crack runs at any increment; accepted as it is).
            const bool shorter = step.repeats == 0 || growth < 0.75 * last_growth;
            last_growth        = growth;
            if (growth > a_max && shorter && dd > p.min_increment * d * (1. + 1e-9) && !elastic)
              {
                out << "  step " << n << ": d " << d_new << " m grew the crack by " << 1e3 * growth
                    << " mm (> maximum advance): repeated with half the increment\n";
                s  = saved;
                dd = std::max(0.5 * dd, p.min_increment * d);
                ++step.repeats;
                continue;
              }
            break;
          }
        result.seconds_relaxation += seconds_since(t_step);

        // Accept the state.
        for (std::size_t i : model.nodes())
          {
            ux_prev[i] = saved.ux[i];
            uy_prev[i] = saved.uy[i];
          }
        traced   = field;
        dd_prev  = dd;
        d        = d_new;
        pad_prev = pad;
        pad      = pad_new;
        if (servo_on)
          pad_over_w = pad / mouth_opening(s);
        std::string stop;
        if (!branching.empty())
          stop = "crack branching, refused: " + branching;
        else
          {
            geometry::Polyline path = p.initial_crack;
            for (std::size_t k = 1; k < increment.path.size(); ++k)
              path.push_back(increment.path[k]);
            auto arrival = arrive(path, body, p.hole_margin, p.horizon, p.initial_crack.size());
            result.path  = arrival.path;
            stop         = arrival.reason;
          }
        const double new_length = geometry::length(result.path);
        growth                  = std::max(0., new_length - length);
        length                  = new_length;

        // Next increment (the rule in full_pd.h).
        double z_tip = 0.;
        if (elastic)
          {
            const auto z = model.stretch_ratio(s);
            for (std::size_t i : near_tip)
              z_tip = std::max(z_tip, z[i]);
            if (z_tip >= p.onset_stretch_ratio * (1. - 1e-3) || growth > 0.)
              {
                elastic = false;
                if (by_mouth)
                  {
                    // From here on d is the crack-mouth opening (w = d / (d/w)_0 in the elastic phase).
                    servo_on   = true;
                    pad_over_w = pad / mouth_opening(s);
                    d          = mouth_opening(s);
                    dd_prev /= pad_over_w;
                  }
                dd = p.first_increment * d;
              }
            else
              dd = std::max(d * (p.onset_stretch_ratio / std::max(z_tip, 1e-12) - 1.), p.first_increment * d);
          }
        else if (growth > 0.)
          dd *= std::clamp(a_t / growth, 0.5, 2.);
        else
          dd *= 2.;
        if (!elastic)
          dd = std::clamp(dd, p.min_increment * d, p.max_increment * d);
        if (growth > 0. && !grown)
          {
            grown      = true;
            growth_t0  = seconds_since(t0);
          }
        stalled = grown && growth == 0. ? stalled + 1 : 0;
        if (stop.empty() && stalled >= p.stall_steps)
          stop = "the crack stopped growing (" + std::to_string(stalled) + " steps without growth)";

        step.displacement  = pad;
        step.mouth_opening = mouth_opening(s);
        step.load          = -load.reaction(s).y;
        step.crack_length  = length;
        step.tip           = result.path.back();
        step.seconds       = seconds_since(t_step);
        result.steps.push_back(step);
        if (table)
          {
            table << std::setprecision(10) << n << "," << pad << "," << step.mouth_opening << "," << step.load << ","
                  << length << "," << step.tip.x << "," << step.tip.y << "," << step.iterations << ","
                  << step.converged << "," << step.repeats << "," << step.seconds << "\n";
            table.flush();
            write_path(p.output_directory + "/crack_path.csv", result.path);
          }
        const bool last = !stop.empty() || n >= p.max_steps || pad >= p.max_displacement * (1. - 1e-12);
        if (series && (n % p.output_interval == 0 || last))
          series->add(model, s);

        // ETA: growth rate against the tip's clearance once the crack grows, else the
        // displacement still to go.
        const double elapsed = seconds_since(t0);
        double       eta     = pad > 0. ? elapsed / pad * (p.max_displacement - pad) : 0.;
        if (grown && length > length0)
          eta = std::min(eta, (elapsed - growth_t0 + 1e-9) / (length - length0) *
                                std::max(0., clearance(result.path.back(), body) - p.hole_margin));
        out << "step " << std::setw(3) << n << "  d " << std::setprecision(4) << std::setw(9) << 1e3 * pad << " mm  w "
            << std::setw(9) << 1e3 * step.mouth_opening << " mm  load "
            << std::setw(9) << step.load << " N/m  crack " << std::setw(7) << 1e3 * length << " mm (+"
            << 1e3 * growth << ")  tip " << to_text(step.tip) << "  DR " << step.iterations
            << (step.converged ? "" : " (not converged)") << (step.repeats ? "  repeats " + std::to_string(step.repeats) : "")
            << (elastic ? "  elastic, Z_tip " + text(z_tip) : "") << "  " << std::fixed << std::setprecision(1)
            << step.seconds << " s  ETA ~" << std::setprecision(0) << eta << " s" << std::defaultfloat
            << std::setprecision(6) << (growth > 0. ? "  (tracing: " + increment.stop_reason + ")" : "") << std::endl;
        if (!stop.empty())
          {
            result.stop_reason = stop;
            break;
          }
      }

    result.seconds     = seconds_since(t0);
    result.peak_rss_mb = peak_rss_mb();
    std::size_t iterations = 0;
    for (const auto &st : result.steps)
      iterations += st.iterations;
    out << "end: " << result.stop_reason << "; crack " << geometry::length(result.path) << " m, tip at "
        << to_text(result.path.back()) << ", load-point displacement " << pad << " m, " << result.steps.size()
        << " steps, " << result.seconds << " s\n";
    out << "pumpd-metric fullpd.nodes " << model.nodes().size() << "\n"
        << "pumpd-metric fullpd.node_steps " << result.node_steps << "\n"
        << "pumpd-metric fullpd.dr_iterations " << iterations << "\n"
        << "pumpd-metric fullpd.ns_per_node_iteration "
        << (result.node_steps > 0. ? 1e9 * result.seconds_relaxation / result.node_steps : 0.) << "\n"
        << "pumpd-metric fullpd.seconds_total " << result.seconds << "\n"
        << "pumpd-metric fullpd.peak_rss_mb " << result.peak_rss_mb << "\n"
        << "pumpd-metric fullpd.crack_length_m " << geometry::length(result.path) << "\n";
    if (!reference.empty())
      {
        const auto dist            = published_distance(result.path, reference, 0.1 * h);
        result.published_mean      = dist.mean;
        result.published_hausdorff = dist.hausdorff;
        out << "pumpd-metric fullpd.mean_dev_mm " << 1e3 * dist.mean << "\n"
            << "pumpd-metric fullpd.hausdorff_mm " << 1e3 * dist.hausdorff << "\n";
      }
    return result;
  }
} // namespace pumpd::coupling
