#include "src/fit/parallel.h"

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

namespace polarform {

int worker_count(int requested, std::size_t n, std::size_t min_chunk) {
  const std::size_t useful = std::max<std::size_t>(1, n / std::max<std::size_t>(1, min_chunk));
  return static_cast<int>(std::clamp<std::size_t>(useful, 1, static_cast<std::size_t>(std::max(1, requested))));
}

void parallel_chunks(std::size_t n, int chunks,
                     const std::function<void(std::size_t, std::size_t, int)>& body) {
  chunks = std::max(1, chunks);
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(chunks));
  auto run = [&](int c) {
    const std::size_t begin = n * static_cast<std::size_t>(c) / static_cast<std::size_t>(chunks);
    const std::size_t end = n * static_cast<std::size_t>(c + 1) / static_cast<std::size_t>(chunks);
    try {
      body(begin, end, c);
    } catch (...) {
      errors[static_cast<std::size_t>(c)] = std::current_exception();
    }
  };
  std::vector<std::thread> workers;
  for (int c = 1; c < chunks; ++c) workers.emplace_back(run, c);
  run(0);
  for (auto& w : workers) w.join();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
}

void ProgressRange::operator()(double fraction) {
  if (!sink_) return;
  const double x = from_ + (to_ - from_) * std::clamp(fraction, 0.0, 1.0);
  if (x < *last_) return;
  *last_ = x;
  sink_(x);
}

ProgressRange ProgressRange::sub(double a, double b) const {
  ProgressRange r = *this;
  r.from_ = from_ + (to_ - from_) * a;
  r.to_ = from_ + (to_ - from_) * b;
  return r;
}

}  // namespace polarform
