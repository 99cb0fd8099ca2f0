// The ladder of a study (study_settings.h): named settings of a scene, each a list of overrides of
// its entries, and the scene file each of them makes.
//   ladder   = rung ; rung ; ...
//   rung     = <name>: override, override, ...       (no override: the scene as it is)
//   override = <entry> = <value> | <entry> x <factor> | <entry> + <n> | <entry> - <n>
// <entry> is an entry's name, looked up in the sections the rung's method reads (its Type, given
// in the rung or the study's), or "<section>/<entry>" (nested sections as "A/B/<entry>").
#pragma once

#include <string>
#include <vector>

#include "parameter_table.h"

namespace pumpd::coupling
{
  struct Override
  {
    std::string entry;
    char        operation = '='; ///< '=', 'x', '+' or '-'
    std::string value;
  };

  struct Rung
  {
    std::string           name;
    std::string           setting; ///< the overrides as written
    std::vector<Override> overrides;
  };

  /// The rungs of `ladder`, the study entry `entry` (for messages). Throws InvalidParameter
  /// naming `entry` and the rung for a rung without a name, a name that is not a plain file name
  /// ([A-Za-z0-9._+-]), or an override of none of the forms above.
  std::vector<Rung> parse_ladder(const std::string &ladder, const std::string &entry);
  /// The overrides of one rung "<override>, <override>, ...".
  std::vector<Override> parse_overrides(const std::string &overrides, const std::string &entry,
                                        const std::string &rung);

  /// The sections a method reads, Method included.
  std::vector<std::string> sections_read_by(const std::string &method);

  /// The scene's parameters with the rung's overrides, its method `method` unless the rung sets
  /// Type. Throws InvalidParameter naming `entry` and the rung for an entry that the method's
  /// sections do not have or have several of, a factor or increment of an entry that is not a
  /// number.
  ParameterTable apply(const ParameterTable &scene, const Rung &rung, const std::string &method,
                       const std::string &entry);
} // namespace pumpd::coupling
