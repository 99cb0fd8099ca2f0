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
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error))
      return std::nullopt;
    std::ifstream in(file, std::ios::binary | std::ios::ate);
    if (!in)
      return std::nullopt;
    const auto size = in.tellg();
    if (size < 0)
      return std::nullopt;
    std::string bytes(std::size_t(size), '\0');
    in.seekg(0);
    in.read(bytes.data(), std::streamsize(bytes.size()));
    if (!in)
      return std::nullopt;
    return bytes;
  }

  std::string special_file_kind(const std::string &path)
  {
    namespace fs = std::filesystem;
    std::error_code error;
    switch (fs::status(path, error).type())
      {
        case fs::file_type::directory:
          return "a directory";
        case fs::file_type::fifo:
          return "a FIFO";
        case fs::file_type::character:
          return "a character device";
        case fs::file_type::block:
          return "a block device";
        case fs::file_type::socket:
          return "a socket";
        default:
          return "";
      }
  }
} // namespace pumpd
