#include "parameter_file.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "error.h"
#include "text.h"

namespace pumpd::coupling
{
  namespace
  {
    /// The lines of a scene file as deal.II 9.4 reads them: each line trimmed, one that ends in a
    /// backslash joined to the next (the backslash dropped), then the comment from '#' cut and
    /// tabs made spaces; each with the number of its first line.
    std::vector<std::pair<std::string, int>> logical_lines(const std::string &text)
    {
      std::vector<std::pair<std::string, int>> lines;
      std::istringstream                       in(text);
      std::string                              line, joined;
      int                                      number = 0, first = 0;
      bool                                     continued = false;
      while (std::getline(in, line))
        {
          ++number;
          if (!continued)
            first = number;
          line = trim(line);
          continued = !line.empty() && line.back() == '\\';
          joined += continued ? line.substr(0, line.size() - 1) : line;
          if (continued)
            continue;
          joined = joined.substr(0, joined.find('#'));
          std::replace(joined.begin(), joined.end(), '\t', ' ');
          lines.emplace_back(trim(joined), first);
          joined.clear();
        }
      return lines;
    }

    /// What follows `keyword` (deal.II takes it in lower or upper case) at the start of a line.
    std::string starting(const std::string &line, const std::string &keyword)
    {
      std::string upper = keyword;
      for (auto &c : upper)
        c = char(std::toupper(c));
      for (const auto &k : {keyword, upper})
        if (line.rfind(k + " ", 0) == 0)
          return trim(line.substr(k.size() + 1));
      return {};
    }

    const std::string byte_order_mark = "\xEF\xBB\xBF";

    /// The text of a scene file without the byte order mark it may start with.
    std::string without_byte_order_mark(const std::string &text)
    {
      return text.rfind(byte_order_mark, 0) == 0 ? text.substr(byte_order_mark.size()) : text;
    }

    void check(const std::string &file, std::vector<std::string> &stack, std::set<std::string> &set);

    /// The entries the lines of `text` (of `file`) set, and those of the files it includes, into
    /// `set`; each entry once per file.
    void walk(const std::string &text, const std::string &file, std::vector<std::string> &stack,
              std::set<std::string> &set)
    {
      std::vector<std::string>   section;
      std::map<std::string, int> set_at; // "Section/Sub/entry" -> its line
      for (const auto &[line, number] : logical_lines(text))
        {
          if (const auto name = starting(line, "subsection"); !name.empty())
            section.push_back(name);
          else if ((line == "end" || line == "END") && !section.empty())
            section.pop_back();
          else if (const auto included = starting(line, "include"); !included.empty())
            check(included, stack, set);
          else if (const auto entry = starting(line, "set"); !entry.empty())
            {
              std::string path;
              for (const auto &s : section)
                path += s + "/";
              path += trim(entry.substr(0, entry.find('=')));
              const auto [at, fresh] = set_at.emplace(path, number);
              if (!fresh)
                throw InvalidParameter(path, "set twice in " + file,
                                       "lines " + std::to_string(at->second) + " and " + std::to_string(number) +
                                         ": each entry once per file (a file may set again an entry of a file it "
                                         "includes)");
              set.insert(path);
            }
        }
    }

    void check(const std::string &file, std::vector<std::string> &stack, std::set<std::string> &set)
    {
      const std::string name = stack.empty() ? "scene file" : "include";
      const std::string what = " (the path of a .prm file, relative to the working directory)";
      if (const auto kind = special_file_kind(file); !kind.empty())
        throw InvalidParameter(name, file, "is " + kind + ", not a regular file" + what);
      auto text = file_contents(file);
      if (!text)
        throw InvalidParameter(name, file, "not found, or not a readable regular file" + what);
      // deal.II reads an included file itself, and would take the mark for part of its first line.
      if (!stack.empty() && text->rfind(byte_order_mark, 0) == 0)
        throw InvalidParameter(name, file,
                               "starts with a UTF-8 byte order mark (the bytes EF BB BF), which deal.II cannot read "
                               "in an included file: save it as UTF-8 without a byte order mark");
      text = without_byte_order_mark(*text);
      const auto canonical = std::filesystem::weakly_canonical(file).string();
      for (const auto &open : stack)
        if (open == canonical)
          throw InvalidParameter("include", file,
                                 "includes itself, directly or through the files it includes: a file may include "
                                 "others, but not one that includes it");
      stack.push_back(canonical);
      walk(*text, file, stack, set);
      stack.pop_back();
    }
  } // namespace

  std::set<std::string> check_parameter_file(const std::string &file)
  {
    std::vector<std::string> stack;
    std::set<std::string>    set;
    check(file, stack, set);
    return set;
  }

  std::set<std::string> entries_set_in(const std::string &text)
  {
    std::vector<std::string> stack;
    std::set<std::string>    set;
    walk(without_byte_order_mark(text), "the scene text", stack, set);
    return set;
  }

  std::set<std::string> parse_parameter_file(dealii::ParameterHandler &prm, const std::string &file)
  {
    auto set = check_parameter_file(file);
    const std::string text = file_contents(file).value_or("");
    if (text.rfind(byte_order_mark, 0) == 0)
      {
        std::istringstream in(without_byte_order_mark(text));
        prm.parse_input(in, file);
      }
    else
      prm.parse_input(file);
    return set;
  }
} // namespace pumpd::coupling
