// One measured figure per line, `pumpd-metric <name> <value>`, for scripts to collect.
#pragma once

#include <iostream>
#include <string>

namespace pumpd::test
{
  inline void metric(const std::string &name, double value)
  {
    std::cout << "pumpd-metric " << name << " " << value << std::endl;
  }
} // namespace pumpd::test
