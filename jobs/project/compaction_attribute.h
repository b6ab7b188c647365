// The `compaction` attribute of a project's <conversion> element (docs/file-formats.md): how the
// converter makes the product C = F·B compact — "refit" (the default), "knot-removal" or "none".
#pragma once

#include <string>

#include "designers/convert/polar_conversion.h"
#include "jobs/project/xml_reader.h"

namespace polarform {

// The attribute read from `r` (absent: refit); a value outside the three is the reader's error.
Compaction read_compaction(const XmlElementReader& r);

// The attribute's value for `c` (Compaction::between_breakpoints, which no project names, writes
// as "knot-removal").
std::string compaction_name(Compaction c);

}  // namespace polarform
