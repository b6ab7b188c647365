#include "jobs/report/exchange_headers.h"

#include "polarform_version.h"

namespace polarform {

ExchangeHeaders exchange_headers(const std::string& what) {
  ExchangeHeaders h;
  h.iges.description = "polarform " + std::string(POLARFORM_VERSION) + " " + what;
  h.step.description = h.iges.description;
  return h;
}

}  // namespace polarform
