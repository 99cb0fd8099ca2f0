#include "text.h"

#include <fstream>
#include <sstream>

namespace pumpd
{
  std::string trim(const std::string &s)
  {
    const auto a = s.find_first_not_of(" \t\n\r"), b = s.find_last_not_of(" \t\n\r");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
  }

  std::optional<std::string> file_contents(const std::string &file)
  {
    std::ifstream in(file, std::ios::binary);
    if (!in)
      return std::nullopt;
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
} // namespace pumpd
