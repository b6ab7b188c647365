#include "jobs/project/compaction_attribute.h"

namespace polarform {

Compaction read_compaction(const XmlElementReader& r) {
  const std::string name = r.choice("compaction", {"refit", "knot-removal", "none"}, "refit");
  return name == "none"           ? Compaction::none
         : name == "knot-removal" ? Compaction::full
                                  : Compaction::refit;
}

std::string compaction_name(Compaction c) {
  switch (c) {
    case Compaction::none:
      return "none";
    case Compaction::refit:
      return "refit";
    case Compaction::between_breakpoints:
    case Compaction::full:
      return "knot-removal";
  }
  return "refit";
}

}  // namespace polarform
