// IGES 5.3 file layout: turns a list of entities (type, form, parameters, label, status) into the
// five fixed 80-column sections Start / Global / Directory Entry / Parameter Data / Terminate with
// their sequence numbers and DE <-> PD pointers (IGES 5.3 chapter 2, file structure). Knows nothing of geometry.
#pragma once

#include <string>
#include <vector>

namespace polarform {

struct IgesEntity {
  int type = 0;
  int form = 0;
  // Parameters after the entity type, already formatted (integers, reals, Hollerith strings,
  // pointers as DE sequence numbers).
  std::vector<std::string> params;
  std::string label;                // DE field 18, at most 8 characters
  std::string status = "00000000";  // DE field 9: blank, subordinate, use, hierarchy
  int name_property_de = 0;         // DE number of a 406 form 15 Name property, 0 for none
};

// DE sequence number of the entity at 0-based position `index` (two DE lines per entity).
inline int iges_de_pointer(int index) { return 2 * index + 1; }

// IGES 5.3 Hollerith string "nH...", or the empty default for empty text. Throws
// InputError naming `field` unless the text is printable ASCII.
std::string iges_string(const std::string& text, const std::string& field);

// The complete file: Start section from `start_text`, Global section from `global_params` (already
// formatted, without the two delimiter parameters, which are always "," and ";"), the entities.
std::string iges_file(const std::string& start_text, const std::vector<std::string>& global_params,
                      const std::vector<IgesEntity>& entities);

}  // namespace polarform
