// path_change <reference.csv> <path.csv>: the symmetric mean distance [mm] between two crack paths
// (coupling/path_metrics.h, both sampled every 0.01 mm), for the regression tests.
#include <iostream>

#include "path_metrics.h"
#include "scene.h"

int main(int argc, char **argv)
{
  if (argc != 3)
    {
      std::cerr << "usage: path_change <reference.csv> <path.csv>\n";
      return 2;
    }
  try
    {
      const auto d = pumpd::coupling::path_distance(pumpd::coupling::read_path(argv[1]),
                                                    pumpd::coupling::read_path(argv[2]), 1e-5);
      std::cout << 1e3 * d.mean << "\n";
      return 0;
    }
  catch (const std::exception &e)
    {
      std::cerr << "path_change: " << e.what() << "\n";
      return 1;
    }
}
