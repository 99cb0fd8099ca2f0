// The entries of a scene file with their values, every section's entry included (its default where
// the file does not set it): what a study changes to make the scene file of each of its runs.
// Paths name nested sections as in the file: "Global-local/Resolution/Rule". The table knows which
// entries the file sets: the length defaults a scene derives (scene_lengths.h) stay derived where
// it does not.
#pragma once

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace pumpd::coupling
{
  class ParameterTable
  {
  public:
    /// The parameters of a scene file after reading it (deal.II's exceptions for a malformed file,
    /// an unknown entry or a value outside its pattern, as read_parameters).
    static ParameterTable of_file(const std::string &file);
    /// The parameters `prm` holds (Parameters::add_parameters declared them) after reading a file.
    /// `set`: the entries the file set (parse_parameter_file).
    static ParameterTable of_handler(const dealii::ParameterHandler &prm, std::set<std::string> set = {});

    /// The value of the entry at `path` (std::out_of_range if there is none).
    const std::string &get(const std::string &path) const;
    /// Sets the entry, as a scene file does.
    void               set(const std::string &path, const std::string &value);
    /// True if the file set the entry, or set() did.
    bool               is_set(const std::string &path) const { return set_entries.count(path) > 0; }
    /// The paths whose last part is `name` and whose first is one of `sections`.
    std::vector<std::string> find(const std::string &name, const std::vector<std::string> &sections) const;
    bool                     has(const std::string &path) const;
    /// Every entry: path and value.
    const std::vector<std::pair<std::string, std::string>> &all() const { return entries; }

    /// A scene file setting every entry but those of the section `omitted` and the length defaults
    /// the scene derives that were not set.
    std::string text(const std::string &omitted) const;
    /// The entries of the section `name` only, in the same form.
    std::string section(const std::string &name) const;

  private:
    /// The entries whose path starts with `prefix` (all: "") but those starting with `omitted`.
    std::string emit(const std::string &prefix, const std::string &omitted) const;

    std::vector<std::pair<std::string, std::string>> entries; ///< path, value, in the order deal.II prints them
    std::set<std::string>                            set_entries; ///< the paths set
  };
} // namespace pumpd::coupling
