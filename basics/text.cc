#include "text.h"

#include <filesystem>
#include <fstream>

namespace pumpd
{
  std::string trim(const std::string &s)
  {
    const auto a = s.find_first_not_of(" \t\n\r"), b = s.find_last_not_of(" \t\n\r");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
  }

  std::optional<std::string> file_contents(const std::string &file)
  {
    std::ifstream in(file, std::ios::binary | std::ios::ate);
    if (!in)
      return std::nullopt;
    const auto size = in.tellg();
    if (!std::filesystem::is_regular_file(file) || size < 0)
      return std::nullopt;
    std::string bytes(std::size_t(size), '\0');
    in.seekg(0);
    in.read(bytes.data(), std::streamsize(bytes.size()));
    if (!in)
      return std::nullopt;
    return bytes;
  }
} // namespace pumpd
