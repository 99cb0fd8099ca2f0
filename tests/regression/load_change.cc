// load_change <reference.csv> <run.csv>: how far the loads of a run's load_displacement.csv lie
// from the reference's, for the regression tests of the global-local cycle, whose loads are the
// onsets of growth in its PD boxes (coupling/exchange.h). Prints two relative differences: of the
// first row (the initial crack, the same on every machine but for the onset's bisection) and the
// mean over the run's rows of |P - P_ref(a)| / P_ref(a), P_ref linear in the crack length a
// between the reference's rows (rows outside the reference's crack lengths are left out: a path
// that differs in its last bits may end an exchange earlier or later).
#include <cmath>
#include <cstddef>
#include <iostream>
#include <utility>
#include <vector>

#include "csv.h"

namespace
{
  /// (crack length, load) of each row.
  std::vector<std::pair<double, double>> loads(const char *file)
  {
    std::vector<std::pair<double, double>> rows;
    for (auto &r : pumpd::read_csv_rows(file))
      rows.emplace_back(pumpd::csv_number(r["crack_length_m"]), pumpd::csv_number(r["load"]));
    return rows;
  }
} // namespace

int main(int argc, char **argv)
{
  if (argc != 3)
    {
      std::cerr << "usage: load_change <reference.csv> <run.csv>\n";
      return 2;
    }
  const auto reference = loads(argv[1]), run = loads(argv[2]);
  if (reference.empty() || run.empty())
    {
      std::cerr << "load_change: no rows in " << (reference.empty() ? argv[1] : argv[2]) << "\n";
      return 1;
    }
  const double first = std::abs(run.front().second / reference.front().second - 1.);
  double       sum   = 0.;
  std::size_t  n     = 0;
  for (const auto &[a, load] : run)
    for (std::size_t k = 1; k < reference.size(); ++k)
      if (const auto &r0 = reference[k - 1], &r1 = reference[k]; a >= r0.first && a <= r1.first && r1.first > r0.first)
        {
          const double p = r0.second + (r1.second - r0.second) * (a - r0.first) / (r1.first - r0.first);
          sum += std::abs(load / p - 1.);
          ++n;
          break;
        }
  if (n == 0)
    {
      std::cerr << "load_change: no row of " << argv[2] << " within the crack lengths of " << argv[1] << "\n";
      return 1;
    }
  std::cout << first << " " << sum / double(n) << "\n";
  return 0;
}
