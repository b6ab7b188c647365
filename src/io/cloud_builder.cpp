#include "src/io/cloud_builder.h"

#include <algorithm>
#include <limits>

#include "src/error.h"

namespace polarform::io_detail {

namespace {

// The smallest record of any supported format: "0 0 0\n" in text, 12 bytes in binary.
constexpr std::size_t kMinBytesPerPoint = 6;

}  // namespace

CloudBuilder::CloudBuilder(std::string_view name, std::size_t total_bytes,
                           const ReadOptions& options)
    : name_(name),
      total_bytes_(total_bytes),
      options_(options),
      next_report_(options.progress && total_bytes > 0 ? (total_bytes + 99) / 100
                                                       : std::numeric_limits<std::size_t>::max()) {}

void CloudBuilder::reserve(std::size_t points) {
  const std::size_t capacity = std::min(points, total_bytes_ / kMinBytesPerPoint + 1);
  if (capacity <= capacity_) return;
  points_.conservativeResize(3, static_cast<Eigen::Index>(capacity));
  capacity_ = capacity;
}

void CloudBuilder::grow() { reserve(std::max<std::size_t>(1024, 2 * capacity_)); }

void CloudBuilder::reject(std::string_view where, std::string_view what) {
  if (!options_.skip_bad) fail(where, what);
  ++dropped_;
}

void CloudBuilder::fail(std::string_view where, std::string_view what) const {
  std::string message = name_;
  if (!where.empty()) message.append(": ").append(where);
  message.append(": ").append(what);
  throw InputError(message);
}

void CloudBuilder::report(std::size_t offset) {
  const std::size_t percent = offset >= total_bytes_ ? 100 : offset * 100 / total_bytes_;
  if (percent > reported_percent_) {
    reported_percent_ = percent;
    options_.progress(
        std::min(1.0, static_cast<double>(offset) / static_cast<double>(total_bytes_)));
  }
  next_report_ = percent >= 100 ? std::numeric_limits<std::size_t>::max()
                                : ((percent + 1) * total_bytes_ + 99) / 100;
}

PointCloud CloudBuilder::finish() {
  if (options_.progress && reported_percent_ < 100) {
    reported_percent_ = 100;
    options_.progress(1.0);
  }
  if (count_ < 3) {
    std::string what = "needs at least 3 points, found " + std::to_string(count_);
    if (dropped_ > 0) what += " (" + std::to_string(dropped_) + " bad records dropped)";
    fail("", what);
  }
  points_.conservativeResize(3, static_cast<Eigen::Index>(count_));
  capacity_ = count_;
  return PointCloud{std::move(points_), dropped_};
}

}  // namespace polarform::io_detail
