#include "nucleation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "boundary_transfer.h"
#include "box_policy.h"
#include "csv.h"
#include "error.h"
#include "exchange.h"
#include "path_metrics.h"
#include "vtu_output.h"

namespace pumpd::coupling
{
  using geometry::Point;

  namespace
  {
    /// The no-fail band along the boundary layer [horizons] (header comment, 2).
    const double layer_clearance = 2.;

    /// The point of a boundary piece nearest p.
    Point nearest_on(const geometry::Piece &piece, Point p)
    {
      if (piece.arc && piece.spans(p) && geometry::norm(p - piece.centre) > 0.)
        return piece.centre + (piece.radius / geometry::norm(p - piece.centre)) * (p - piece.centre);
      if (piece.arc)
        return geometry::norm(p - piece.a) < geometry::norm(p - piece.b) ? piece.a : piece.b;
      return geometry::nearest_on_segment(p, piece.a, piece.b);
    }

    /// The largest bond stretch over its critical stretch, Z, of a state and the node it is at.
    std::pair<double, Point> largest_stretch_ratio(const local::PdModel &model, const local::State &s)
    {
      const auto  z    = model.stretch_ratio(s);
      std::size_t best = model.nodes().front();
      for (std::size_t i : model.nodes())
        if (z[i] > z[best])
          best = i;
      return {z[best], model.lattice().position(best)};
    }

    /// No-fail zones along the box's boundary layer: per box side with layer nodes of its own
    /// (within a horizon of it and of no other side), the bounding box of the layer nodes within a
    /// horizon of it (they are prescribed already), its bonds and those within `margin` linear.
    std::vector<local::PrescribedRegion> layer_no_fail_zones(const local::PdModel &probe, double horizon,
                                                             double margin)
    {
      const auto &box  = probe.region().box;
      const auto  near = [&](Point p) {
        const double distance[4] = {p.x - box.x_min, box.x_max - p.x, p.y - box.y_min, box.y_max - p.y};
        std::array<bool, 4> sides{};
        for (int side = 0; side < 4; ++side)
          sides[side] = distance[side] < horizon;
        return sides;
      };
      std::array<bool, 4> own{};
      for (std::size_t i : probe.boundary_layer())
        {
          const auto sides = near(probe.lattice().position(i));
          if (std::count(sides.begin(), sides.end(), true) == 1)
            own[std::find(sides.begin(), sides.end(), true) - sides.begin()] = true;
        }
      std::vector<local::PrescribedRegion> zones;
      for (int side = 0; side < 4; ++side)
        {
          if (!own[side])
            continue;
          std::optional<geometry::Box> strip;
          for (std::size_t i : probe.boundary_layer())
            if (const Point p = probe.lattice().position(i); near(p)[side])
              strip = strip ? geometry::Box{std::min(strip->x_min, p.x), std::min(strip->y_min, p.y),
                                            std::max(strip->x_max, p.x), std::max(strip->y_max, p.y)}
                            : geometry::Box{p.x, p.y, p.x, p.y};
          zones.push_back(local::PrescribedRegion::box("Boundary layer", *strip, true, true));
          zones.back().elastic_margin = margin;
        }
      return zones;
    }

    /// Whether `box` holds no point of the outline or a hole's rim (its circumscribed circle holds
    /// none): its layer meets no free surface (header comment, 3).
    bool in_the_open(const geometry::Body &body, const geometry::Box &box)
    {
      const Point centre{0.5 * (box.x_min + box.x_max), 0.5 * (box.y_min + box.y_max)};
      return body.clearance(centre) > 0.5 * std::hypot(box.x_max - box.x_min, box.y_max - box.y_min);
    }

    /// The tips a nucleation box's ridge is traced from (header comment, 4): the material node
    /// next to the mouth, along t; or the two ends of the interior flaw, along t and -t.
    std::vector<TipState> nucleation_tips(const local::PdModel &model, const std::optional<Point> &mouth,
                                          const geometry::Polyline &flaw, Point t, double lambda_i)
    {
      const auto tip = [&](Point at, Point direction) {
        TipState s;
        s.position             = at;
        s.direction            = direction;
        s.critical_load_factor = lambda_i;
        return s;
      };
      if (mouth)
        return {tip(model.lattice().position(model.nearest_node(*mouth + 0.5 * model.lattice().spacing() * t)), t)};
      return {tip(flaw.back(), t), tip(flaw.front(), -1. * t)};
    }

    /// The side of a nucleation box (header comment, 3): room for the longest crack between the
    /// mouth (or the centre) and the no-fail band of every layer.
    double box_side(const GlobalLocalSettings &settings)
    {
      return std::max(settings.cycle.box.size,
                      2. * ((1. + layer_clearance) * settings.pd.horizon + settings.cycle.exchange.max_advance));
    }

    std::string site_name(std::size_t number)
    {
      return number == 1 ? "the first initiation site" : "initiation site " + std::to_string(number);
    }

    /// The PD state file of the site `number`: nucleation_pd.vtu for the first, then _2, _3, ...
    std::string pd_file(const Scene &scene, std::size_t number)
    {
      return scene.output_directory + "/nucleation_pd" + (number == 1 ? "" : "_" + std::to_string(number)) + ".vtu";
    }

    /// nucleation.csv: the vertices of every initial crack, with the load that formed it.
    void write_cracks(const Scene &scene, const std::vector<NucleatedCrack> &cracks,
                      const std::vector<std::size_t> &numbers)
    {
      if (scene.output_directory.empty())
        return;
      std::filesystem::create_directories(scene.output_directory);
      CsvFile csv(scene.output_directory + "/nucleation.csv", "crack,site,vertex,x_m,y_m,lambda,lambda_over_lambda_i,onset_lambda");
      for (std::size_t c = 0; c < cracks.size(); ++c)
        for (std::size_t k = 0; k < cracks[c].path.size(); ++k)
          csv.row(c + 1, numbers[c], k, cracks[c].path[k].x, cracks[c].path[k].y, cracks[c].load_factor,
                  cracks[c].load_factor / cracks[c].site.load_factor, cracks[c].onset_load_factor);
    }
  } // namespace

  Point nearest_boundary_point(const geometry::Body &body, Point p)
  {
    Point      best;
    double     best_distance = std::numeric_limits<double>::infinity();
    const auto visit         = [&](const geometry::Loop &loop) {
      for (const auto &piece : loop.pieces)
        if (const Point q = nearest_on(piece, p); geometry::norm(q - p) < best_distance)
          {
            best          = q;
            best_distance = geometry::norm(q - p);
          }
    };
    visit(body.outline());
    for (const auto &hole : body.holes())
      visit(hole);
    return best;
  }

  std::optional<Point> nucleation_mouth(const geometry::Body &body, Point site, double horizon)
  {
    if (body.clearance(site) > horizon)
      return std::nullopt;
    return nearest_boundary_point(body, site);
  }

  Point opening_direction(const geometry::Body &body, Point mouth, Point sigma1, double horizon)
  {
    const Point t{-sigma1.y, sigma1.x};
    const auto  depth = [&](Point e) {
      const Point x = mouth + horizon * e;
      return body.contains(x) ? body.clearance(x) : -1.;
    };
    return depth(t) >= depth(-1. * t) ? t : -1. * t;
  }

  NucleatedCrack nucleate(const Scene &scene, GlobalProblem &global, const GlobalLocalSettings &settings,
                          const InitiationSettings &initiation, const InitiationSite &site, std::size_t number,
                          std::ostream &out)
  {
    const auto &pd    = settings.pd;
    const auto  mouth = nucleation_mouth(scene.body, site.position, pd.horizon);
    const Point t = mouth ? opening_direction(scene.body, *mouth, site.direction, pd.horizon)
                          : Point{-site.direction.y, site.direction.x};
    const Point centre = mouth ? *mouth : site.position;
    const double h     = pd.spacing();

    BoxSettings box = settings.cycle.box;
    box.horizon     = pd.horizon;
    box.spacing     = h;
    box.behind      = 0.5;
    box.size        = box_side(settings);
    box.max_size    = std::max(box.max_size, box.size);
    BoxPolicy boxes(scene.body, box);

    NucleatedCrack crack;
    crack.site = site;
    crack.box  = boxes.place(centre, t);
    const geometry::Polyline flaw = mouth ? geometry::Polyline{*mouth, *mouth + h * t}
                                          : geometry::Polyline{centre - 0.5 * h * t, centre + 0.5 * h * t};
    const local::Region    region{scene.body, crack.box, {flaw}};
    const auto             material = pd.material(scene.material);
    const double           band     = in_the_open(scene.body, crack.box) ? 0. : layer_clearance * pd.horizon;
    const local::PdModel   probe(material, pd.horizon, pd.horizon_over_spacing, region);
    auto                   prescribed = layer_no_fail_zones(probe, pd.horizon, band);
    for (auto &place : held_places(scene.conditions, probe))
      prescribed.push_back(std::move(place));
    const local::PdModel model(material, pd.horizon, pd.horizon_over_spacing, region, prescribed);
    const BoundaryTransfer transfer(global, model);
    crack.pd_nodes = model.nodes().size();

    ExchangeSettings exchange     = settings.cycle.exchange;
    exchange.first_load_factor    = initiation.first_load_factor;
    exchange.start_below_accepted = false;
    ExchangeController controller(exchange);
    const auto tips = nucleation_tips(model, mouth, flaw, t, site.load_factor);
    // Each tip of an interior crack gets half of the Maximum crack length (less the flaw).
    const double allowed =
      std::min(exchange.max_advance, mouth ? settings.growth.length_limit() : 0.5 * (settings.growth.length_limit() - h));
    // An increment arrives where its far end comes within a horizon of the outline or a hole (an
    // edge crack's once it is a horizon from its mouth).
    const auto arrives = [&](const geometry::Polyline &path) {
      const bool left_mouth = !mouth || geometry::norm(path.back() - *mouth) > pd.horizon;
      return left_mouth && scene.body.clearance(path.back()) < pd.horizon;
    };

    out << "nucleation at site " << number << " " << geometry::to_text(site.position) << ": "
        << (mouth ? "mouth " + geometry::to_text(*mouth) : std::string("interior, two tips from it"))
        << ", the crack along "
        << geometry::to_text(t, 4) << " (perpendicular to sigma_1); PD box [" << crack.box.x_min << ", "
        << crack.box.x_max << "] x [" << crack.box.y_min << ", " << crack.box.y_max << "], delta " << pd.horizon
        << " m, " << crack.pd_nodes << " PD nodes; states from " << exchange.first_load_factor
        << " lambda_i, lambda_i = " << site.load_factor << std::endl;
    const auto outcome = run_exchange(model, transfer, controller, tips, std::vector<double>(tips.size(), allowed), {},
                                      arrives, pd, out, "lambda_i");
    crack.states     = outcome.states;
    crack.iterations = outcome.iterations;
    if (!scene.output_directory.empty())
      {
        std::filesystem::create_directories(scene.output_directory);
        local::write_vtu(pd_file(scene, number), model, outcome.state);
      }
    if (!outcome.branching.empty())
      {
        crack.refusal = InvalidParameter("Initial cracks", "none",
                                         "the damage that formed at " + site_name(number) + " " +
                                           geometry::to_text(site.position) + " branches, refused: " + outcome.branching);
        return crack;
      }
    if (outcome.decision == ExchangeController::Decision::too_small)
      {
        const auto [z, at] = largest_stretch_ratio(model, outcome.state);
        crack.refusal      = InvalidParameter(
          "Maximum load factor", pumpd::to_text(exchange.max_load_factor),
          "no crack formed at " + site_name(number) + " " + geometry::to_text(site.position) +
            " up to this many times lambda_i = " + pumpd::to_text(site.load_factor, 4) +
            ": the elastic sigma_1 / sigma_s there reached " + pumpd::to_text(outcome.load_factor, 4) +
            ", the largest bond stretch over its critical one " + pumpd::to_text(z, 4) + " at " +
            geometry::to_text(at, 4) + " (the scene does not break)");
        return crack;
      }
    crack.load_factor       = outcome.load_factor * site.load_factor;
    crack.onset_load_factor = outcome.onset_load_factor * site.load_factor;
    if (mouth)
      {
        auto path  = outcome.increments.front().path;
        path[0]    = *mouth;
        crack.path = truncate(path, allowed);
      }
    else
      {
        const auto ahead = truncate(outcome.increments[0].path, allowed);
        const auto back  = truncate(outcome.increments[1].path, allowed);
        crack.path.assign(back.rbegin(), back.rend());
        crack.path.insert(crack.path.end(), ahead.begin(), ahead.end());
      }
    out << "nucleation at site " << number << ": a crack of " << geometry::length(crack.path) << " m formed at lambda = "
        << crack.load_factor << " (" << outcome.load_factor << " lambda_i; its growth set in at "
        << outcome.onset_load_factor << " lambda_i): " << geometry::to_text(crack.path) << std::endl;
    return crack;
  }

  std::vector<std::size_t> distinct_sites(const std::vector<InitiationSite> &sites, double same_site)
  {
    std::vector<std::size_t> distinct;
    for (std::size_t k = 0; k < sites.size(); ++k)
      if (std::none_of(distinct.begin(), distinct.end(), [&](std::size_t j) {
            return geometry::norm(sites[j].position - sites[k].position) < same_site;
          }))
        distinct.push_back(k);
    return distinct;
  }

  GlobalLocalResult run_global_local_from_initiation(const Scene &scene, const GlobalLocalSettings &settings,
                                                     const InitiationSettings &initiation, std::ostream &out)
  {
    const auto found = find_initiation(scene, settings.global, settings.pd, initiation);
    report_initiation(found, scene, out);
    GlobalProblem global(scene, settings.global);
    global.solve_uncracked();

    const auto                  checked = distinct_sites(found.sites, 0.5 * box_side(settings));
    std::vector<SiteOutcome>    outcomes(found.sites.size());
    std::vector<NucleatedCrack> formed;
    std::vector<std::size_t>    formed_at; // the site of each formed crack
    std::optional<InvalidParameter> first_refusal;
    for (std::size_t k : checked)
      {
        outcomes[k].checked = true;
        auto crack          = nucleate(scene, global, settings, initiation, found.sites[k], k + 1, out);
        if (crack.refusal)
          {
            out << "nucleation at site " << k + 1 << ": no crack: " << crack.refusal->what() << "\n";
            if (!first_refusal)
              first_refusal = crack.refusal;
            continue;
          }
        outcomes[k].formed      = true;
        outcomes[k].load_factor = crack.load_factor;
        formed.push_back(std::move(crack));
        formed_at.push_back(k);
      }
    if (formed.empty())
      {
        write_initiation_sites(found, scene, outcomes);
        throw *first_refusal;
      }

    // The initial cracks: those formed within one load increment of the lowest (header comment, 5).
    const auto lowest = std::min_element(formed.begin(), formed.end(), [](const auto &a, const auto &b) {
      return a.load_factor < b.load_factor;
    });
    const double until = lowest->load_factor + settings.cycle.exchange.load_increment * lowest->site.load_factor;
    std::vector<NucleatedCrack> initial;
    std::vector<std::size_t>    numbers;
    for (std::size_t c = 0; c < formed.size(); ++c)
      if (formed[c].load_factor <= until * (1. + 1e-9))
        {
          initial.push_back(formed[c]);
          numbers.push_back(formed_at[c] + 1);
          outcomes[formed_at[c]].crack = initial.size();
        }
    for (std::size_t k = 0; k < found.sites.size(); ++k)
      {
        out << "nucleation: site " << k + 1 << " " << geometry::to_text(found.sites[k].position) << ": ";
        if (!outcomes[k].checked)
          {
            const auto same = std::min_element(checked.begin(), checked.end(), [&](std::size_t a, std::size_t b) {
              return geometry::norm(found.sites[a].position - found.sites[k].position) <
                     geometry::norm(found.sites[b].position - found.sites[k].position);
            });
            out << "the same site as site " << *same + 1 << " (within half a box side)\n";
          }
        else if (!outcomes[k].formed)
          out << "checked, no crack\n";
        else
          out << "a crack at lambda = " << outcomes[k].load_factor
              << (outcomes[k].crack ? ": initial crack " + std::to_string(outcomes[k].crack)
                                    : std::string(": later than one load increment above the lowest, ") +
                                        pumpd::to_text(lowest->load_factor) + ", not grown")
              << "\n";
      }
    write_initiation_sites(found, scene, outcomes);
    write_cracks(scene, initial, numbers);

    Scene cracked = scene;
    cracked.cracks.clear();
    for (const auto &c : initial)
      cracked.cracks.push_back(c.path);
    // A nucleated crack runs along the direction its own PD damage took: its first growth goes on
    // from it and is no kink from a crack the scene gave (resolution.h).
    GlobalLocalSettings growth                = settings;
    growth.cycle.resolution.kink_tolerance = 0.;
    return run_global_local(cracked, growth, out);
  }
} // namespace pumpd::coupling
