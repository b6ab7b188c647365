// Collects the points of one file straight into the result matrix (the only full copy), applies
// the rules every reader shares -- finite coordinates, bad records dropped or fatal, at least 3
// points -- and reports progress at most 100 times. Error messages read "name: where: what".
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>

#include "src/io/point_cloud.h"

namespace polarform::io_detail {

class CloudBuilder {
 public:
  CloudBuilder(std::string_view name, std::size_t total_bytes, const ReadOptions& options);

  // Allocates room for `points` (a hint, capped by what total_bytes can hold); the matrix still
  // grows if more points arrive.
  void reserve(std::size_t points);

  // Adds the point; a NaN or infinite coordinate makes it a bad record (see reject), located by
  // where() -- a callable returning e.g. "line 12" -- which is only called on that path.
  template <class Where>
  void add(double x, double y, double z, Where&& where) {
    if (std::isfinite(x) && std::isfinite(y) && std::isfinite(z)) {
      if (count_ == capacity_) grow();
      double* p = points_.data() + 3 * count_++;
      p[0] = x;
      p[1] = y;
      p[2] = z;
      return;
    }
    const char axis = !std::isfinite(x) ? 'x' : !std::isfinite(y) ? 'y' : 'z';
    reject(where(), std::string(1, axis) + " is NaN or infinite: expected a finite coordinate");
  }

  // A bad record: dropped and counted with skip_bad, otherwise an InputError.
  void reject(std::string_view where, std::string_view what);

  // A structural error that skip_bad does not excuse.
  [[noreturn]] void fail(std::string_view where, std::string_view what) const;

  // Reports progress if `offset` (bytes consumed) has passed the next whole percent.
  void progress(std::size_t offset) {
    if (offset >= next_report_) report(offset);
  }

  // The cloud, shrunk to size. Throws InputError for fewer than 3 points.
  PointCloud finish();

  std::string_view name() const { return name_; }

 private:
  void grow();
  void report(std::size_t offset);

  std::string name_;
  std::size_t total_bytes_;
  const ReadOptions& options_;
  Eigen::Matrix3Xd points_;
  std::size_t count_ = 0;
  std::size_t capacity_ = 0;
  std::size_t dropped_ = 0;
  std::size_t reported_percent_ = 0;
  std::size_t next_report_;
};

}  // namespace polarform::io_detail
