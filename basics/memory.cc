#include "memory.h"

#include <fstream>
#include <string>

#include <unistd.h>

namespace pumpd
{
  double available_memory()
  {
    std::ifstream in("/proc/meminfo");
    std::string   key, unit;
    double        kb = 0.;
    while (in >> key >> kb >> unit)
      if (key == "MemAvailable:")
        return 1024. * kb;
    return double(sysconf(_SC_AVPHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
  }
} // namespace pumpd
