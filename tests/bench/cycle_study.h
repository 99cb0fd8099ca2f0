// Helpers of the studies that run the global-local cycle on the Ingraffea scenes (study_coupling,
// study_resolution): a run with its progress forwarded line by line, the PD discretisation
// changed with the box and exchange lengths in proportion, and the distance between the grown
// parts of two paths. The studies run from the source tree (relative paths of the prm files).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <exception>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <streambuf>
#include <string>

#include "global_local.h"
#include "metric.h"
#include "parameters.h"
#include "path_metrics.h"

namespace pumpd::study
{
  using geometry::Point;
  using geometry::Polyline;

  inline const double not_a_number = std::numeric_limits<double>::quiet_NaN();

  /// Forwards everything to std::cout line by line; a line that run_global_local starts with
  /// "pumpd-metric " (no case name) is shown as "  [run] ..." instead, and kept by name.
  class RunOutput : public std::streambuf
  {
  public:
    ~RunOutput() override { flush_line(); }

    std::map<std::string, double> metrics;

  protected:
    int overflow(int c) override
    {
      if (c == traits_type::eof())
        return traits_type::not_eof(c);
      line.push_back(char(c));
      if (c == '\n')
        flush_line();
      return c;
    }
    int sync() override
    {
      flush_line();
      return 0;
    }

  private:
    void flush_line()
    {
      if (line.empty())
        return;
      const std::string tag = "pumpd-metric ";
      if (line.compare(0, tag.size(), tag) == 0)
        {
          std::istringstream words(line.substr(tag.size()));
          std::string        name;
          double             value = 0.;
          if (words >> name >> value)
            metrics[name] = value;
          line = "  [run] " + line.substr(tag.size());
        }
      std::cout << line << std::flush;
      line.clear();
    }
    std::string line;
  };

  inline void metric(const std::string &name, double value)
  {
    test::metric(name, value);
    EXPECT_TRUE(std::isfinite(value)) << name << " = " << value;
  }

  inline coupling::Parameters from_prm(const std::string &scene)
  {
    return coupling::read_parameters("prm/" + scene);
  }

  /// The PD discretisation changed to (delta, m): the lengths of the box and of the exchange
  /// controller scaled with delta / 0.004 (header comment), Minimum advance at least 2 h.
  inline coupling::Parameters with_pd(coupling::Parameters p, double delta, int m)
  {
    const double s            = delta / p.pd.horizon;
    auto        &c            = p.cycle;
    p.pd.horizon              = delta;
    p.pd.horizon_over_spacing = m;
    c.box.size *= s;
    c.box.margin *= s;
    c.box.max_size *= s;
    c.exchange.max_advance *= s;
    c.exchange.near_distance *= s;
    c.exchange.min_advance = std::max(s * c.exchange.min_advance, 2. * delta / m);
    return p;
  }

  struct CycleRun
  {
    std::string                                name;
    coupling::Parameters                       p;
    std::optional<coupling::GlobalLocalResult> r; ///< empty if the run threw
    std::map<std::string, double>              metrics; ///< its pumpd-metric lines, by name
  };

  inline Polyline initial_crack(const coupling::Parameters &p) { return coupling::build_scene(p.scene).crack(); }

  /// Runs the cycle; its output under <build>/tests/bench/<output>/<name>.
  inline CycleRun run(const std::string &output, const std::string &name, coupling::Parameters p)
  {
    p.scene.output_directory = std::string(PUMPD_BINARY_DIR) + "/" + output + "/" + name;
    std::filesystem::remove_all(p.scene.output_directory); // no stale checkpoint, no stale series
    const auto &c = p.cycle;
    std::cout << "\n=== " << name << ": delta " << p.pd.horizon << " m, m = " << p.pd.horizon_over_spacing << " (h "
              << p.pd.spacing() << " m), box " << c.box.size << " m (margin " << c.box.margin << ", max "
              << c.box.max_size << "), advance " << c.exchange.min_advance << " ... " << c.exchange.max_advance
              << " m (near " << c.exchange.near_distance << " m), max exchanges " << c.max_exchanges << ", output "
              << p.scene.output_directory << std::endl;
    CycleRun result{name, p, std::nullopt, {}};
    RunOutput    buffer;
    std::ostream progress(&buffer);
    try
      {
        result.r = coupling::run_global_local(coupling::build_scene(p.scene), p.global_local_settings(), progress);
      }
    catch (const std::exception &e)
      {
        progress.flush();
        std::cout << "=== " << name << " FAILED, exception: " << e.what() << std::endl;
        ADD_FAILURE() << name << ": " << e.what();
        return result;
      }
    progress.flush();
    result.metrics     = buffer.metrics;
    const auto  &r     = *result.r;
    const double grown = geometry::length(r.path) - geometry::length(initial_crack(p));
    std::cout << "=== " << name << ": " << r.exchanges.size() << " exchanges, crack " << geometry::length(r.path)
              << " m (grown " << grown << " m), tip (" << r.path.back().x << ", " << r.path.back().y
              << "), stop reason: " << r.stop_reason << "; " << r.seconds << " s" << std::endl;
    return result;
  }

  inline double grown(const CycleRun &run)
  {
    return run.r ? geometry::length(run.r->path) - geometry::length(initial_crack(run.p)) : not_a_number;
  }

  /// The path from its vertex nearest the initial tip on (the grown part, that vertex included).
  inline Polyline grown_part(const CycleRun &run)
  {
    const Point   tip  = initial_crack(run.p).back();
    const auto   &path = run.r->path;
    std::size_t   k    = 0;
    for (std::size_t i = 1; i < path.size(); ++i)
      if (geometry::norm(path[i] - tip) < geometry::norm(path[k] - tip))
        k = i;
    return Polyline(path.begin() + std::ptrdiff_t(k), path.end());
  }

  /// Symmetric mean distance [m] between the grown parts of two paths, the longer cut at the
  /// point nearest the shorter one's tip; NaN if either run failed.
  inline double path_change(const CycleRun &a, const CycleRun &b)
  {
    if (!a.r || !b.r)
      return not_a_number;
    Polyline pa = grown_part(a), pb = grown_part(b);
    if (geometry::length(pa) > geometry::length(pb))
      pa = coupling::up_to_nearest(pa, pb.back());
    else
      pb = coupling::up_to_nearest(pb, pa.back());
    const auto d = coupling::path_distance(pa, pb, 5e-5);
    std::cout << "  " << a.name << " vs " << b.name << ": compared over " << geometry::length(pa) << " / "
              << geometry::length(pb) << " m of grown path; mean " << 1e3 * d.mean << " mm, Hausdorff "
              << 1e3 * d.hausdorff << " mm" << std::endl;
    return d.mean;
  }

  inline void sanity(const CycleRun &run)
  {
    EXPECT_TRUE(run.r.has_value()) << run.name << " threw";
    if (run.r)
      {
        EXPECT_GT(grown(run), 0.02) << run.name << ": the crack grew only " << grown(run) << " m ("
                                    << run.r->stop_reason << ")";
      }
  }
} // namespace pumpd::study
