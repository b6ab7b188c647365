// The IGES and STEP headers of a job's exchange files: both describe the file as
// "polarform <version> <what>".
#pragma once

#include <string>

#include "export/iges_writer.h"
#include "export/step_writer.h"

namespace polarform {

struct ExchangeHeaders {
  IgesHeader iges;
  StepHeader step;
};

ExchangeHeaders exchange_headers(const std::string& what);

}  // namespace polarform
