// The memory of this machine that a new allocation may take, for the checks that refuse a
// lattice or a mesh too large for it before any long work starts.
#pragma once

namespace pumpd
{
  /// Memory this machine can give a new allocation [bytes]: MemAvailable of /proc/meminfo, else
  /// the free physical pages.
  double available_memory();
} // namespace pumpd
