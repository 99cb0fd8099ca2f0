#include "hash.h"

#include <cstring>
#include <iomanip>
#include <sstream>

namespace pumpd
{
  std::uint64_t fnv1a(const std::string &bytes, std::uint64_t h)
  {
    const std::uint64_t prime = 1099511628211ull;
    std::size_t         i     = 0;
    for (; i + 8 <= bytes.size(); i += 8)
      {
        std::uint64_t word;
        std::memcpy(&word, bytes.data() + i, 8);
        h = (h ^ word) * prime;
      }
    for (; i < bytes.size(); ++i)
      h = (h ^ static_cast<unsigned char>(bytes[i])) * prime;
    return h;
  }

  std::string hex(std::uint64_t h)
  {
    std::ostringstream s;
    s << std::hex << std::setw(16) << std::setfill('0') << h;
    return s.str();
  }
} // namespace pumpd
